// The all-quad steps part by part for petersen.distributed (all_quad.hpp: part_parity,
// split_seams, plan_part_all_quad, part_all_quads) and the added vertices' records: numpy arrays
// in and out, ids as int64 (-1 for none), the GIL released while the library works. A part's
// output faces come as a flat int64 array of corners and a uint8 array of arities (3 or 4), in
// the order the output writes them; the steps that need positions read them from the PLY at
// `path` (only the rows the corners name), as out of core does.

#include "all_quad.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "petersen/dualize/quad_quality.hpp"
#include "petersen/io/file_error.hpp"
#include "petersen/io/ply_stream.hpp"
#include "petersen/partition/all_quad.hpp"

namespace petersen::python {
namespace {

namespace py = pybind11;
using Int64Array = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;
using UInt8Array = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>;
using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;
using Ends = std::array<VertexId, 2>;

// A vertex id as the library holds it; ValueError outside [0, 2^32 - 1).
VertexId vertex_of(std::int64_t v, const char* what) {
  if (v < 0 || v >= std::int64_t{0xFFFFFFFF}) {
    throw py::value_error(std::string(what) + ": id " + std::to_string(v) + " out of range");
  }
  return static_cast<VertexId>(v);
}

// An (n, k) int64 array's rows, checked for shape (an empty array of any shape is no rows).
std::size_t row_count(const Int64Array& a, std::size_t k, const char* what) {
  if (a.size() == 0) return 0;
  if (a.ndim() != 2 || static_cast<std::size_t>(a.shape(1)) != k) {
    throw py::value_error(std::string(what) + ": an (n, " + std::to_string(k) + ") array");
  }
  return static_cast<std::size_t>(a.shape(0));
}

std::vector<Ends> ends_of(const Int64Array& a, const char* what) {
  const std::size_t n = row_count(a, 2, what);
  std::vector<Ends> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    out[i] = {vertex_of(a.data()[2 * i], what), vertex_of(a.data()[2 * i + 1], what)};
  }
  return out;
}

py::array_t<std::int64_t> ends_array(const std::vector<Ends>& ends) {
  py::array_t<std::int64_t> out({ends.size(), std::size_t{2}});
  std::int64_t* d = out.mutable_data();
  for (std::size_t i = 0; i < ends.size(); ++i) d[2 * i] = ends[i][0], d[2 * i + 1] = ends[i][1];
  return out;
}

// The faces (corners, arities) as PartFaces, checked: arities 3 or 4 adding up to the corners.
PartFaces part_faces_of(const Int64Array& corners, const UInt8Array& arity) {
  PartFaces faces;
  faces.arity.assign(arity.data(), arity.data() + arity.size());
  std::uint64_t total = 0;
  for (std::uint8_t k : faces.arity) {
    if (k != 3 && k != 4) throw py::value_error("arity: 3 or 4 per face");
    total += k;
  }
  if (total != static_cast<std::uint64_t>(corners.size())) {
    throw py::value_error("corners: the arities add up to " + std::to_string(total) +
                          " corners, not " + std::to_string(corners.size()));
  }
  faces.corners.resize(total);
  for (std::size_t c = 0; c < total; ++c)
    faces.corners[c] = vertex_of(corners.data()[c], "corners");
  return faces;
}

// The corners' positions read from the PLY at `path` (FileError for a vertex out of its range).
void read_corner_positions(const std::string& path, PartFaces& faces) {
  const PlyTriangleStream in(path);
  for (VertexId v : faces.corners) {
    if (v >= in.vertex_count()) {
      throw FileError(path, 0,
                      "vertex " + std::to_string(v) + " out of range (" +
                          std::to_string(in.vertex_count()) + " vertices)");
    }
  }
  faces.corner_positions.resize(faces.corners.size());
  in.read_positions(faces.corners, faces.corner_positions);
}

QuadOptions quad_options_of(const std::string& objective, bool keep_polygons,
                            std::uint32_t threads) {
  const std::optional<Objective> o = parse_objective(objective);
  if (!o) throw py::value_error("unknown objective '" + objective + "': quads, quality or pairs");
  QuadOptions options;
  options.objective = *o;
  options.all_quad = true;
  options.keep_polygons = keep_polygons;
  options.threads = threads;
  return options;
}

// An (n, 4) int64 array whose row i is row(items[i]).
template <class Items, class Row>
py::array_t<std::int64_t> rows_of_four(const Items& items, Row row) {
  py::array_t<std::int64_t> out({items.size(), std::size_t{4}});
  std::int64_t* at = out.mutable_data();
  for (const auto& item : items) {
    const std::array<std::int64_t, 4> r = row(item);
    at = std::copy(r.begin(), r.end(), at);
  }
  return out;
}

// Step 1: the part's open edges as (low, high, component, kept) rows, each component's parity.
py::dict part_parity_py(const Int64Array& corners, const UInt8Array& arity) {
  const PartFaces faces = part_faces_of(corners, arity);
  PartParity parity;
  {
    py::gil_scoped_release release;
    parity = part_parity(faces);
  }
  py::dict d;
  d["border"] = rows_of_four(parity.border, [](const SplitBorderEdge& e) {
    return std::array<std::int64_t, 4>{e.low, e.high, e.component, e.kept};
  });
  d["component_odd"] =
      py::array_t<std::uint8_t>(parity.component_odd.size(), parity.component_odd.data());
  d["faces"] = parity.faces;
  d["kept_faces"] = parity.kept_faces;
  return d;
}

// Step 2, from every part's (border, component_odd) in part order: the seam graph's edges as
// (low, high, a, b) rows (a, b as all_quad.hpp's SplitSeams::Edge), its nodes and counts.
py::dict split_seams_py(const std::vector<Int64Array>& borders,
                        const std::vector<UInt8Array>& component_odd) {
  if (borders.size() != component_odd.size()) {
    throw py::value_error("borders and component_odd: one of each per part");
  }
  std::vector<PartParity> parts(borders.size());
  for (std::size_t p = 0; p < parts.size(); ++p) {
    const std::size_t r = row_count(borders[p], 4, "border");
    const std::int64_t* b = borders[p].data();
    const std::size_t components = static_cast<std::size_t>(component_odd[p].size());
    parts[p].border.resize(r);
    for (std::size_t i = 0; i < r; ++i) {
      if (b[4 * i + 2] < 0 || static_cast<std::size_t>(b[4 * i + 2]) >= components) {
        throw py::value_error("border: component out of range");
      }
      parts[p].border[i] = {vertex_of(b[4 * i], "border"), vertex_of(b[4 * i + 1], "border"),
                            static_cast<std::uint32_t>(b[4 * i + 2]), b[4 * i + 3] != 0};
    }
    parts[p].component_odd.assign(component_odd[p].data(), component_odd[p].data() + components);
  }
  SplitSeams seams;
  {
    py::gil_scoped_release release;
    seams = split_seams(parts);
  }
  py::dict d;
  d["edges"] = rows_of_four(seams.edges, [](const SplitSeams::Edge& e) {
    return std::array<std::int64_t, 4>{e.low, e.high, e.a, e.b};
  });
  d["node_start"] = py::array_t<std::int64_t>(
      seams.node_start.size(),
      std::vector<std::int64_t>(seams.node_start.begin(), seams.node_start.end()).data());
  d["node_odd"] = py::array_t<std::uint8_t>(seams.node_odd.size(), seams.node_odd.data());
  d["cut_edges"] = seams.cut_edges;
  d["boundary_edges"] = seams.boundary_edges;
  d["whole_edges"] = seams.whole_edges;
  return d;
}

SplitSeams seams_of(const Int64Array& edges, const Int64Array& node_start,
                    const UInt8Array& node_odd) {
  SplitSeams seams;
  const std::size_t k = row_count(edges, 4, "seam edges");
  seams.edges.resize(k);
  const std::int64_t* e = edges.data();
  for (std::size_t i = 0; i < k; ++i) {
    seams.edges[i] = {vertex_of(e[4 * i], "seam edges"), vertex_of(e[4 * i + 1], "seam edges"),
                      static_cast<std::uint32_t>(e[4 * i + 2]),
                      static_cast<std::uint32_t>(e[4 * i + 3])};
  }
  seams.node_start.assign(node_start.data(), node_start.data() + node_start.size());
  seams.node_odd.assign(node_odd.data(), node_odd.data() + node_odd.size());
  return seams;
}

// Step 3 for part `part`: the edges it splits, those of them on cuts, its centres' corners
// ((c, 4), -1 after the last), the split pieces' worst corners, its output face count and
// whether its T-join's certificate passed.
py::dict plan_part_all_quad_py(const std::string& path, const Int64Array& corners,
                               const UInt8Array& arity, std::uint32_t part,
                               const Int64Array& seam_edges, const Int64Array& node_start,
                               const UInt8Array& node_odd, const Int64Array& earlier_cut_midpoints,
                               const std::string& objective, bool keep_polygons,
                               std::uint32_t threads) {
  PartFaces faces = part_faces_of(corners, arity);
  const SplitSeams seams = seams_of(seam_edges, node_start, node_odd);
  const std::vector<Ends> earlier = ends_of(earlier_cut_midpoints, "earlier_cut_midpoints");
  if (!std::is_sorted(earlier.begin(), earlier.end())) {
    throw py::value_error("earlier_cut_midpoints: ascending");
  }
  const QuadOptions options = quad_options_of(objective, keep_polygons, threads);
  PartSplitPlan plan;
  {
    py::gil_scoped_release release;
    read_corner_positions(path, faces);
    plan = plan_part_all_quad(faces, part, seams, earlier, options);
  }
  py::dict d;
  d["midpoints"] = ends_array(plan.midpoints);
  d["cut_midpoints"] = ends_array(plan.cut_midpoints);
  py::array_t<std::int64_t> centres({plan.centre_corners.size(), std::size_t{4}});
  std::int64_t* c = centres.mutable_data();
  for (std::size_t i = 0; i < plan.centre_corners.size(); ++i) {
    for (int j = 0; j < 4; ++j) {
      const VertexId v = plan.centre_corners[i][j];
      c[4 * i + j] = v == kNoNode ? -1 : std::int64_t{v};
    }
  }
  d["centre_corners"] = centres;
  d["split_quality"] = py::array_t<double>(plan.split_quality.size(), plan.split_quality.data());
  d["faces"] = plan.faces;
  d["certified"] = plan.certified;
  return d;
}

// Step 4: the part's faces cut into quads over the output's vertex ids, as (corners, arity).
py::tuple part_all_quads_py(const std::string& path, const Int64Array& corners,
                            const UInt8Array& arity, const Int64Array& midpoints,
                            std::int64_t vertex_count, std::int64_t first_centre,
                            const std::string& objective, bool keep_polygons,
                            std::uint32_t threads) {
  PartFaces faces = part_faces_of(corners, arity);
  const std::vector<Ends> all = ends_of(midpoints, "midpoints");
  if (!std::is_sorted(all.begin(), all.end())) throw py::value_error("midpoints: ascending");
  const QuadOptions options = quad_options_of(objective, keep_polygons, threads);
  const VertexId n = vertex_of(vertex_count, "vertex_count");
  const VertexId centre = vertex_of(first_centre, "first_centre");
  PolygonMesh quads;
  {
    py::gil_scoped_release release;
    read_corner_positions(path, faces);
    quads = part_all_quads(faces, all, n, centre, options);
  }
  py::array_t<std::int64_t> out_corners(quads.corners.size());
  std::copy(quads.corners.begin(), quads.corners.end(), out_corners.mutable_data());
  py::array_t<std::uint8_t> out_arity(quads.face_count());
  std::uint8_t* a = out_arity.mutable_data();
  for (FaceId f = 0; f < quads.face_count(); ++f) {
    const std::size_t k = quads.arity(f);
    if (k != 3 && k != 4) {
      throw std::logic_error("internal error: all-quad made a face of " + std::to_string(k) +
                             " corners");
    }
    a[f] = static_cast<std::uint8_t>(k);
  }
  return py::make_tuple(out_corners, out_arity);
}

// The records of the vertices all-quad adds, as out of core writes them: each midpoint's (its
// edge's two ends blended), then each centre's (its 3 or 4 corners, -1 after the last).
py::bytes blended_records_py(const std::string& path, const Int64Array& midpoints,
                             const Int64Array& centres) {
  const std::vector<Ends> edges = ends_of(midpoints, "midpoints");
  const std::size_t c = row_count(centres, 4, "centres");
  std::vector<std::array<VertexId, 4>> corners(c);
  std::vector<std::uint8_t> count(c);
  for (std::size_t i = 0; i < c; ++i) {
    for (int j = 0; j < 4; ++j) {
      const std::int64_t v = centres.data()[4 * i + j];
      if (v < 0) break;
      corners[i][count[i]++] = vertex_of(v, "centres");
    }
    if (count[i] < 3) throw py::value_error("centres: 3 or 4 corners each");
  }
  std::string records;
  {
    py::gil_scoped_release release;
    const PlyTriangleStream in(path);
    for (const Ends& e : edges) {
      if (e[0] >= in.vertex_count() || e[1] >= in.vertex_count()) {
        throw FileError(
            path, 0,
            "midpoint of vertex " + std::to_string(std::max(e[0], e[1])) + ", out of range");
      }
      in.append_blended_record(e, records);
    }
    for (std::size_t i = 0; i < c; ++i) {
      for (std::uint8_t j = 0; j < count[i]; ++j) {
        if (corners[i][j] >= in.vertex_count()) {
          throw FileError(path, 0,
                          "centre of vertex " + std::to_string(corners[i][j]) + ", out of range");
        }
      }
      in.append_blended_record(std::span<const VertexId>(corners[i].data(), count[i]), records);
    }
  }
  return py::bytes(records);
}

// quality_figures_in_place's median and 95th percentile of the split pieces' worst corners.
py::tuple split_quality_figures_py(const DoubleArray& quality) {
  std::vector<double> costs(quality.data(), quality.data() + quality.size());
  const QualityFigures figures = quality_figures_in_place(costs);
  return py::make_tuple(figures.median, figures.p95);
}

}  // namespace

void add_all_quad(py::module_& m) {
  m.def("part_parity", &part_parity_py, py::arg("corners"), py::arg("arity"));
  m.def("split_seams", &split_seams_py, py::arg("borders"), py::arg("component_odd"));
  m.def("plan_part_all_quad", &plan_part_all_quad_py, py::arg("path"), py::arg("corners"),
        py::arg("arity"), py::arg("part"), py::arg("seam_edges"), py::arg("node_start"),
        py::arg("node_odd"), py::arg("earlier_cut_midpoints"), py::arg("objective"),
        py::arg("keep_polygons") = false, py::arg("threads") = 1);
  m.def("part_all_quads", &part_all_quads_py, py::arg("path"), py::arg("corners"), py::arg("arity"),
        py::arg("midpoints"), py::arg("vertex_count"), py::arg("first_centre"),
        py::arg("objective"), py::arg("keep_polygons") = false, py::arg("threads") = 1);
  m.def("blended_records", &blended_records_py, py::arg("path"), py::arg("midpoints"),
        py::arg("centres"));
  m.def("split_quality_figures", &split_quality_figures_py, py::arg("quality"));
}

}  // namespace petersen::python
