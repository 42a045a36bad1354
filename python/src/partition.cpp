// The part, cut and repair steps for petersen.distributed: numpy arrays in and out, ids as int64
// with -1 for none (kNoFace), the GIL released while the library works.

#include "partition.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "petersen/dualize/quad_of.hpp"
#include "petersen/partition/partition.hpp"

namespace petersen::python {
namespace {

using Int64Array = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;

Augment augment_named(const std::string& name) {
  if (auto a = parse_augment(name)) return *a;
  throw py::value_error("unknown augment '" + name + "': local or faithful");
}

std::int64_t id_or_none(FaceId f) {
  return f == kNoFace ? -1 : std::int64_t{f};
}

// An (n, k) int64 array's rows, checked for shape; `what` names it in the ValueError.
const std::int64_t* rows_of(const Int64Array& a, std::size_t k, const char* what) {
  if (a.ndim() != 2 || static_cast<std::size_t>(a.shape(1)) != k) {
    throw py::value_error(std::string(what) + ": an (n, " + std::to_string(k) + ") array");
  }
  return a.data();
}

// A global face or vertex id as the library holds it; ValueError outside [0, 2^32 - 1).
std::uint32_t id_of(std::int64_t v, const char* what) {
  if (v < 0 || v >= std::int64_t{0xFFFFFFFF}) {
    throw py::value_error(std::string(what) + ": id " + std::to_string(v) + " out of range");
  }
  return static_cast<std::uint32_t>(v);
}

template <class Values, class Get>
py::array_t<std::int64_t> column(const Values& values, Get get) {
  py::array_t<std::int64_t> out(values.size());
  std::int64_t* data = out.mutable_data();
  for (std::size_t i = 0; i < values.size(); ++i) data[i] = get(values[i]);
  return out;
}

py::dict band_dict(const std::vector<BandFace>& band, const std::pmr::vector<FaceId>& partner,
                   FaceId first_face) {
  py::dict d;
  d["faces"] = column(band, [](const BandFace& b) { return std::int64_t{b.face}; });
  d["corners"] = rows_array(band.size(), 3, [&](std::size_t i, std::int64_t* row) {
    for (int c = 0; c < 3; ++c) row[c] = band[i].corners[c];
  });
  py::array_t<std::uint8_t> sides({band.size(), std::size_t{3}});
  std::uint8_t* s = sides.mutable_data();
  for (std::size_t i = 0; i < band.size(); ++i) {
    for (int c = 0; c < 3; ++c) s[3 * i + c] = static_cast<std::uint8_t>(band[i].sides[c]);
  }
  d["sides"] = sides;
  d["distance"] = column(band, [](const BandFace& b) { return std::int64_t{b.distance}; });
  d["partner"] =
      column(band, [&](const BandFace& b) { return id_or_none(partner[b.face - first_face]); });
  return d;
}

using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

// The objective and its costs as the library takes them; ValueError for an unknown objective.
PartCosts costs_of(const std::string& objective, double triangle_cost,
                   std::optional<double> max_corner_deviation, std::optional<double> sharp_angle) {
  const std::optional<Objective> o = parse_objective(objective);
  if (!o) throw py::value_error("unknown objective '" + objective + "': quads, quality or pairs");
  return {*o, triangle_cost, max_corner_deviation, sharp_angle};
}

// (k, 3, 3) positions of the corners of k triangles, as one array per corner.
std::vector<std::array<double, 3>> corner_positions_of(const DoubleArray& positions,
                                                       std::size_t triangles) {
  if (positions.ndim() != 3 || static_cast<std::size_t>(positions.shape(0)) != triangles ||
      positions.shape(1) != 3 || positions.shape(2) != 3) {
    throw py::value_error("positions: a (" + std::to_string(triangles) +
                          ", 3, 3) array, each triangle's corners' x, y, z");
  }
  std::vector<std::array<double, 3>> out(3 * triangles);
  std::copy_n(positions.data(), 9 * triangles, out.front().data());
  return out;
}

py::dict seam_dict(const std::vector<SeamFace>& seam) {
  py::dict d;
  d["faces"] = column(seam, [](const SeamFace& f) { return std::int64_t{f.face}; });
  d["corners"] = rows_array(seam.size(), 3, [&](std::size_t i, std::int64_t* row) {
    for (int c = 0; c < 3; ++c) row[c] = seam[i].corners[c];
  });
  DoubleArray positions({seam.size(), std::size_t{3}, std::size_t{3}});
  double* p = positions.mutable_data();
  py::array_t<std::uint8_t> sides({seam.size(), std::size_t{3}});
  std::uint8_t* s = sides.mutable_data();
  for (std::size_t i = 0; i < seam.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      for (int k = 0; k < 3; ++k) p[9 * i + 3 * c + k] = seam[i].positions[c][k];
      s[3 * i + c] = static_cast<std::uint8_t>(seam[i].sides[c]);
    }
  }
  d["positions"] = positions;
  d["sides"] = sides;
  d["distance"] = column(seam, [](const SeamFace& f) { return std::int64_t{f.distance}; });
  d["partner"] = column(seam, [](const SeamFace& f) { return id_or_none(f.partner); });
  d["dual"] = rows_array(seam.size(), 2, [&](std::size_t i, std::int64_t* row) {
    row[0] = seam[i].dual[0], row[1] = seam[i].dual[1];
  });
  d["price"] = column(seam, [](const SeamFace& f) { return std::int64_t{f.price}; });
  d["stay_dual"] = column(seam, [](const SeamFace& f) { return f.stay_dual; });
  return d;
}

// pair_part on faces first_face.. with corners (m, 3) (and, for a cost objective, positions
// (m, 3, 3)): the part's partners (per triangle), its open edges as (low, high, face, apex) rows,
// its band (objective pairs) or seam (the cost objectives) and figures.
py::dict pair_part_py(std::int64_t first_face, const Int64Array& corners,
                      const std::string& augment, std::uint32_t band_radius, std::uint32_t threads,
                      const std::string& objective, double triangle_cost,
                      std::optional<double> max_corner_deviation, std::optional<double> sharp_angle,
                      std::optional<DoubleArray> positions) {
  const std::int64_t* rows = rows_of(corners, 3, "corners");
  const std::size_t m = static_cast<std::size_t>(corners.shape(0));
  std::vector<VertexId> flat(3 * m);
  for (std::size_t i = 0; i < 3 * m; ++i) flat[i] = id_of(rows[i], "corners");
  PartPairingOptions options;
  options.costs = costs_of(objective, triangle_cost, max_corner_deviation, sharp_angle);
  options.augment = augment_named(augment);
  options.band_radius = band_radius;
  options.threads = threads;
  const std::vector<std::array<double, 3>> at =
      positions ? corner_positions_of(*positions, m) : std::vector<std::array<double, 3>>{};
  PartTriangles part;
  part.first_face = id_of(first_face, "first_face");
  part.corners = flat;
  part.corner_positions = at;
  PartPairing r;
  {
    py::gil_scoped_release release;
    r = pair_part(part, options);
  }
  py::dict d;
  d["partner"] = column(r.partner, id_or_none);
  d["unpaired"] = column(r.unpaired, [](FaceId f) { return std::int64_t{f}; });
  d["open_edges"] = rows_array(r.open_edges.size(), 4, [&](std::size_t i, std::int64_t* row) {
    const OpenEdge& e = r.open_edges[i];
    row[0] = e.low, row[1] = e.high, row[2] = e.face, row[3] = e.apex;
  });
  d["band"] = band_dict(r.band, r.partner, r.first_face);
  d["seam"] = seam_dict(r.seam);
  d["objective_units"] = r.objective_units;
  d["optimality_certified"] = r.optimality_certified;
  d["inner_structural_cuts"] = r.inner_structural_cuts;
  d["pairs"] = r.pairs;
  d["moved_to_border"] = r.moved_to_border;
  d["stranded"] = r.stranded;
  d["maximum_certified"] = r.maximum_certified;
  d["seconds"] = r.seconds;
  return d;
}

// The rows of an (r, 4) array of ids as records of four ids each (OpenEdge, CutAdjacency).
template <class Record>
std::vector<Record> records_of(const Int64Array& array, const char* name) {
  const std::int64_t* rows = rows_of(array, 4, name);
  std::vector<Record> records(static_cast<std::size_t>(array.shape(0)));
  for (std::size_t i = 0; i < records.size(); ++i) {
    const std::int64_t* row = rows + 4 * i;
    records[i] = {id_of(row[0], name), id_of(row[1], name), id_of(row[2], name),
                  id_of(row[3], name)};
  }
  return records;
}

// pair_open_edges on (r, 4) rows (low, high, face, apex): the cut adjacencies as (first, second,
// low, high) rows and the counts that tell whether the mesh is closed.
py::dict pair_open_edges_py(const Int64Array& records) {
  std::vector<OpenEdge> list = records_of<OpenEdge>(records, "open_edges");
  CutPairing cut;
  {
    py::gil_scoped_release release;
    cut = pair_open_edges(std::move(list));
  }
  py::dict d;
  d["adjacencies"] = rows_array(cut.adjacencies.size(), 4, [&](std::size_t i, std::int64_t* row) {
    const CutAdjacency& a = cut.adjacencies[i];
    row[0] = a.first, row[1] = a.second, row[2] = a.low, row[3] = a.high;
  });
  d["boundary_edges"] = cut.boundary_edges;
  d["non_manifold_edges"] = cut.non_manifold_edges;
  d["duplicate_edges"] = cut.duplicate_edges;
  d["closed"] = cut.closed();
  return d;
}

std::vector<BandFace> band_from(const Int64Array& faces, const Int64Array& corners,
                                const py::array_t<std::uint8_t, py::array::c_style>& sides,
                                const Int64Array& distance) {
  const std::size_t b = static_cast<std::size_t>(faces.size());
  const std::int64_t* c = rows_of(corners, 3, "band corners");
  if (static_cast<std::size_t>(corners.shape(0)) != b ||
      static_cast<std::size_t>(sides.size()) != 3 * b ||
      static_cast<std::size_t>(distance.size()) != b) {
    throw py::value_error("band: faces, corners, sides and distance of different lengths");
  }
  std::vector<BandFace> band(b);
  for (std::size_t i = 0; i < b; ++i) {
    band[i].face = id_of(faces.data()[i], "band faces");
    for (int k = 0; k < 3; ++k) {
      band[i].corners[k] = id_of(c[3 * i + k], "band corners");
      const std::uint8_t side = sides.data()[3 * i + k];
      if (side > static_cast<std::uint8_t>(SideState::open)) throw py::value_error("band sides");
      band[i].sides[k] = static_cast<SideState>(side);
    }
    band[i].distance = static_cast<std::uint32_t>(std::max<std::int64_t>(distance.data()[i], 0));
  }
  return band;
}

// repair_cuts on the concatenated bands (with each band face's partner, -1 for none) and the
// cut adjacencies: the band faces' new partners and the repair's figures.
py::dict repair_cuts_py(const Int64Array& faces, const Int64Array& corners,
                        const py::array_t<std::uint8_t, py::array::c_style>& sides,
                        const Int64Array& distance, const Int64Array& partner,
                        const Int64Array& adjacencies, const std::string& augment,
                        std::uint32_t first_radius) {
  const std::vector<BandFace> band = band_from(faces, corners, sides, distance);
  if (static_cast<std::size_t>(partner.size()) != band.size()) {
    throw py::value_error("partner: one per band face");
  }
  std::vector<FaceId> partners(band.size());
  for (std::size_t i = 0; i < band.size(); ++i) {
    const std::int64_t p = partner.data()[i];
    partners[i] = p < 0 ? kNoFace : id_of(p, "partner");
  }
  std::vector<CutAdjacency> adjacent = records_of<CutAdjacency>(adjacencies, "adjacencies");
  RepairOptions options;
  options.augment = augment_named(augment);
  options.first_radius = first_radius;
  RepairResult r;
  {
    py::gil_scoped_release release;
    r = repair_cuts({band, partners, adjacent}, options);
  }
  py::dict d;
  d["partner"] = column(r.partner, id_or_none);
  d["unpaired_before"] = r.unpaired_before;
  d["unpaired_after"] = r.unpaired_after;
  d["augmenting_paths"] = r.augmenting_paths;
  d["band_graph_faces"] = r.band_graph_faces;
  d["radius"] = r.radius;
  d["maximum_in_band_certified"] = r.maximum_in_band_certified;
  d["seconds"] = r.seconds;
  return d;
}

// pair_seams on the concatenated seams of all parts and the cut adjacencies, with the sum of the
// parts' objective_units: each seam face's partner after the step (-1 for none), the whole
// pairing's total and (objective quads) the stitched lower bound in degrees, and the figures.
py::dict pair_seams_py(const Int64Array& faces, const Int64Array& corners,
                       const DoubleArray& positions,
                       const py::array_t<std::uint8_t, py::array::c_style>& sides,
                       const Int64Array& distance, const Int64Array& partner,
                       const Int64Array& dual, const Int64Array& price, const Int64Array& stay_dual,
                       const Int64Array& adjacencies, std::int64_t parts_units,
                       const std::string& objective, double triangle_cost,
                       std::optional<double> max_corner_deviation,
                       std::optional<double> sharp_angle, std::uint32_t threads) {
  const std::vector<BandFace> band = band_from(faces, corners, sides, distance);
  const std::size_t k = band.size();
  const std::int64_t* y = rows_of(dual, 2, "seam dual");
  const std::vector<std::array<double, 3>> at = corner_positions_of(positions, k);
  if (static_cast<std::size_t>(partner.size()) != k ||
      static_cast<std::size_t>(dual.shape(0)) != k || static_cast<std::size_t>(price.size()) != k ||
      static_cast<std::size_t>(stay_dual.size()) != k) {
    throw py::value_error(
        "seam: faces, positions, partner, dual, price and stay_dual of different lengths");
  }
  std::vector<SeamFace> seam(k);
  for (std::size_t i = 0; i < k; ++i) {
    seam[i].face = band[i].face;
    seam[i].corners = band[i].corners;
    seam[i].sides = band[i].sides;
    seam[i].distance = band[i].distance;
    for (int j = 0; j < 3; ++j) seam[i].positions[j] = at[3 * i + j];
    const std::int64_t p = partner.data()[i];
    seam[i].partner = p < 0 ? kNoFace : id_of(p, "partner");
    seam[i].dual = {y[2 * i], y[2 * i + 1]};
    seam[i].price = price.data()[i];
    seam[i].stay_dual = stay_dual.data()[i];
  }
  const std::vector<CutAdjacency> adjacent = records_of<CutAdjacency>(adjacencies, "adjacencies");
  const PartCosts costs = costs_of(objective, triangle_cost, max_corner_deviation, sharp_angle);
  SeamResult r;
  {
    py::gil_scoped_release release;
    r = pair_seams({seam, adjacent}, costs, threads);
  }
  py::dict d;
  d["partner"] = column(r.partner, id_or_none);
  const Cost total = parts_units + r.objective_change;
  d["objective_total"] = double(total) / kDefaultCostScale;
  if (costs.objective == Objective::quads) {
    d["triangle_cost"] = costs.triangle_cost;
    d["lower_bound"] = lower_bound_degrees(parts_units, r.dual_lowering);
    d["optimality_certified"] = r.certified && 4 * total == 4 * parts_units - r.dual_lowering;
  }
  d["pairs_across"] = r.pairs_across;
  d["seam_graph_faces"] = r.seam_graph_faces;
  d["seam_graph_edges"] = r.seam_graph_edges;
  d["certified"] = r.certified;
  d["seconds"] = r.seconds;
  return d;
}

// quad_of on each row of two (k, 3) arrays of paired triangles: the (k, 4) quads, in the first's
// orientation. RuntimeError naming the first pair whose triangles do not share exactly two
// corners. O(k), the GIL released.
py::array_t<std::int64_t> quads_of_pairs_py(const Int64Array& first, const Int64Array& second) {
  const std::int64_t* a = rows_of(first, 3, "first");
  const std::int64_t* b = rows_of(second, 3, "second");
  if (first.shape(0) != second.shape(0)) {
    throw py::value_error("first and second: arrays of as many rows");
  }
  const std::size_t k = static_cast<std::size_t>(first.shape(0));
  for (std::size_t i = 0; i < 3 * k; ++i) {
    id_of(a[i], "first");
    id_of(b[i], "second");
  }
  py::array_t<std::int64_t> quads({k, std::size_t{4}});
  std::int64_t* q = quads.mutable_data();
  std::size_t bad = k;
  {
    py::gil_scoped_release release;
    for (std::size_t i = 0; i < k; ++i) {
      const std::array<VertexId, 3> t1{VertexId(a[3 * i]), VertexId(a[3 * i + 1]),
                                       VertexId(a[3 * i + 2])};
      const std::array<VertexId, 3> t2{VertexId(b[3 * i]), VertexId(b[3 * i + 1]),
                                       VertexId(b[3 * i + 2])};
      int common = 0;
      for (VertexId v : t1) common += v == t2[0] || v == t2[1] || v == t2[2];
      if (common != 2) {
        bad = i;
        break;
      }
      const std::array<VertexId, 4> quad = quad_of(t1, t2);
      for (int c = 0; c < 4; ++c) q[4 * i + c] = quad[c];
    }
  }
  if (bad < k) {
    throw std::runtime_error("verification failed: triangles (" + std::to_string(a[3 * bad]) +
                             ", " + std::to_string(a[3 * bad + 1]) + ", " +
                             std::to_string(a[3 * bad + 2]) + ") and (" +
                             std::to_string(b[3 * bad]) + ", " + std::to_string(b[3 * bad + 1]) +
                             ", " + std::to_string(b[3 * bad + 2]) + ") share no single edge");
  }
  return quads;
}

}  // namespace

void add_partition(py::module_& m) {
  m.def("pair_part", &pair_part_py, py::arg("first_face"), py::arg("corners"), py::arg("augment"),
        py::arg("band_radius"), py::arg("threads"), py::arg("objective") = "pairs",
        py::arg("triangle_cost") = kDefaultTriangleCost,
        py::arg("max_corner_deviation") = py::none(), py::arg("sharp_angle") = py::none(),
        py::arg("positions") = py::none());
  m.def("pair_seams", &pair_seams_py, py::arg("faces"), py::arg("corners"), py::arg("positions"),
        py::arg("sides"), py::arg("distance"), py::arg("partner"), py::arg("dual"),
        py::arg("price"), py::arg("stay_dual"), py::arg("adjacencies"), py::arg("parts_units"),
        py::arg("objective"), py::arg("triangle_cost") = kDefaultTriangleCost,
        py::arg("max_corner_deviation") = py::none(), py::arg("sharp_angle") = py::none(),
        py::arg("threads") = 1);
  m.def("pair_open_edges", &pair_open_edges_py, py::arg("open_edges"));
  m.def("repair_cuts", &repair_cuts_py, py::arg("faces"), py::arg("corners"), py::arg("sides"),
        py::arg("distance"), py::arg("partner"), py::arg("adjacencies"), py::arg("augment"),
        py::arg("first_radius"));
  m.def("quads_of_pairs", &quads_of_pairs_py, py::arg("first"), py::arg("second"));
}

}  // namespace petersen::python
