// The extension module petersen._petersen: a thin skin over the C++ front doors. The public
// Python API (names, defaults, result classes, docstrings) is in petersen/__init__.py.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "all_quad.hpp"
#include "arrays.hpp"
#include "attributes.hpp"
#include "graph_functions.hpp"
#include "partition.hpp"
#include "petersen/dualize/pairable_graph.hpp"
#include "petersen/io/read_mesh.hpp"
#include "petersen/io/write_mesh.hpp"
#include "petersen/matching/any_graph.hpp"
#include "petersen/matching/perfect_matching.hpp"
#include "petersen/memory_pool/huge_page_pool.hpp"
#include "petersen/mesh/duplicate_faces.hpp"
#include "petersen/quadrangulate/quadrangulate.hpp"
#include "petersen/quadrangulate/stats_fields.hpp"
#include "ply_stream.hpp"
#include "render.hpp"

namespace petersen::python {
namespace {

PairingAlgorithm algorithm_of(const std::string& name) {
  if (auto a = parse_pairing_algorithm(name)) return *a;
  throw py::value_error("unknown algorithm '" + name + "': auto, sg, ps, ds, gw, frink or lrs");
}

// The graph functions run perfect_matching's algorithms; lrs is a name they know but cannot run.
Algorithm graph_algorithm_of(const std::string& name) {
  const PairingAlgorithm a = algorithm_of(name);
  if (const Algorithm* graph = std::get_if<Algorithm>(&a)) return *graph;
  throw py::value_error(
      "lrs contracts and flips a triangulation, so it needs a mesh (use quadrangulate)");
}

Augment augment_of(const std::string& name) {
  if (auto a = parse_augment(name)) return *a;
  throw py::value_error("unknown augment '" + name + "': local or faithful");
}

Objective objective_of(const std::string& name) {
  if (auto o = parse_objective(name)) return *o;
  throw py::value_error("unknown objective '" + name + "': quads, pairs or quality");
}

PolygonMesh mesh_from(const py::handle& V, const py::handle& F, const py::handle& attributes) {
  PolygonMesh mesh;
  mesh.positions = positions_from(V);
  add_faces_from(F, mesh);
  attributes_from(attributes, mesh);
  return mesh;
}

// The causes QuadOptions::cross accepts, by name: petersen.CROSSABLE and the error messages.
std::vector<std::string> crossable_names() {
  std::vector<std::string> names;
  for (CutCause cause : attribute_causes()) names.emplace_back(to_string(cause));
  return names;
}

std::vector<CutCause> causes_from(const py::handle& cross) {
  std::vector<CutCause> causes;
  if (cross.is_none()) return causes;
  for (py::handle item : py::reinterpret_borrow<py::iterable>(cross)) {
    const std::string name = py::cast<std::string>(item);
    const std::optional<CutCause> cause = parse_cut_cause(name);
    if (!cause) {
      std::string known;
      for (const std::string& c : crossable_names()) known += (known.empty() ? "" : ", ") + c;
      throw py::value_error("cross: unknown cause '" + name + "' (crossable: " + known + ")");
    }
    causes.push_back(*cause);
  }
  return causes;
}

// A numpy copy of integers.
template <class Values>
py::array_t<std::int64_t> int64_array(const Values& values) {
  py::array_t<std::int64_t> out(values.size());
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

py::dict stats_dict(const QuadStats& stats, const QuadOptions& options) {
  py::dict out;
  for (const StatField& field : stats_fields(stats, options)) {
    std::visit(
        [&](const auto& v) {
          using T = std::decay_t<decltype(v)>;
          if constexpr (std::is_same_v<T, std::vector<std::pair<std::string, std::uint64_t>>>) {
            py::dict by_key;
            for (const auto& [key, count] : v) by_key[py::str(key)] = count;
            out[py::str(field.key)] = by_key;
          } else {
            out[py::str(field.key)] = v;
          }
        },
        field.value);
  }
  return out;
}

py::dict quadrangulate_py(const py::handle& V, const py::handle& F, const std::string& algorithm,
                          const std::string& augment, std::uint64_t seed, bool all_quad,
                          const std::string& objective, std::optional<double> sharp_angle,
                          const py::handle& keep_edges, std::optional<double> max_corner_deviation,
                          const py::handle& attributes, const py::handle& cross,
                          std::uint32_t threads, bool keep_polygons, double triangle_cost,
                          double flow_weight, bool drop_duplicates) {
  std::vector<std::array<VertexId, 2>> kept_edges;
  if (!keep_edges.is_none()) {
    for (const auto& [a, b] : pairs_from(keep_edges, "keep_edges")) {
      for (std::int64_t v : {a, b}) {
        if (v < 0 || v > std::int64_t{0xFFFFFFFEu}) {
          throw py::value_error("keep_edges: vertex index " + std::to_string(v) +
                                " is out of range");
        }
      }
      kept_edges.push_back({VertexId(a), VertexId(b)});
    }
  }
  QuadOptions options;
  options.algorithm = algorithm_of(algorithm);
  options.augment = augment_of(augment);
  options.seed = seed;
  options.all_quad = all_quad;
  options.keep_polygons = keep_polygons;
  options.objective = objective_of(objective);
  options.triangle_cost = triangle_cost;
  options.flow_weight = flow_weight;
  options.cuts.sharp_angle_degrees = sharp_angle;
  options.max_corner_deviation = max_corner_deviation;
  options.cuts.user_edges = kept_edges;
  options.cross = causes_from(cross);
  options.threads = threads;
  PolygonMesh mesh = mesh_from(V, F, attributes);
  std::vector<FaceId> input_face;  // with drop_duplicates: the caller's face of each face kept
  if (drop_duplicates) {
    DroppedFaces copies = drop_duplicate_faces(mesh);
    for (FaceId f = 0, d = 0; f < mesh.face_count(); ++f) {
      if (d < copies.dropped.size() && copies.dropped[d] == f) {
        ++d;
      } else {
        input_face.push_back(f);
      }
    }
    mesh = std::move(copies.mesh);
  }
  // The library pairs an empty mesh into an empty result; here, as in `petersen quad`, no faces
  // is a mistake worth naming (an empty array, or a mesh object that was not filled).
  if (mesh.face_count() == 0) {
    throw py::value_error("quadrangulate: the mesh has no faces (" +
                          std::to_string(mesh.positions.size()) + " vertices): nothing to pair");
  }
  // The call's own pool: the stages reuse the memory the ones before them freed, and it is all
  // given back when the call returns (the result is copied into numpy arrays before). Nothing is
  // kept between calls, so a process that forks (Dask, multiprocessing) shares no kept pages.
  HugePagePool pool;
  options.memory = &pool;
  QuadResult result = [&] {
    py::gil_scoped_release release;
    return quadrangulate(mesh, options);
  }();
  // Output faces in three groups, each in output order: quads, left triangles, kept polygons (a
  // face whose only source is an input face that is not a triangle).
  const PolygonMesh& out = result.mesh;
  std::vector<FaceId> quads, triangles, kept;
  for (FaceId f = 0; f < out.face_count(); ++f) {
    const auto [s0, s1] = result.sources[f];
    if (s0 != kNoFace && s1 == kNoFace && mesh.arity(s0) != 3) {
      kept.push_back(f);
    } else {
      (out.arity(f) == 4 ? quads : triangles).push_back(f);
    }
  }
  auto corners = [&](const std::vector<FaceId>& faces, std::size_t k) {
    return rows_array(faces.size(), k, [&](std::size_t i, std::int64_t* row) {
      const auto face = out.face(faces[i]);
      for (std::size_t c = 0; c < k; ++c) row[c] = face[c];
    });
  };
  for (FaceId f : triangles) {
    if (out.arity(f) != 3) throw std::logic_error("an output face that is neither quad nor kept");
  }
  py::list polygons;
  for (FaceId f : kept) {
    const auto face = out.face(f);
    py::array_t<std::int64_t> row(face.size());
    std::copy(face.begin(), face.end(), row.mutable_data());
    polygons.append(std::move(row));
  }
  if (drop_duplicates) {
    // Sources and the Tutte set name the caller's faces, as without the option.
    for (auto& pair : result.sources)
      for (FaceId& f : pair) f = f == kNoFace ? kNoFace : input_face[f];
    for (FaceId& f : result.tutte_set) f = input_face[f];
  }
  std::vector<FaceId> order = quads;
  order.insert(order.end(), triangles.begin(), triangles.end());
  order.insert(order.end(), kept.begin(), kept.end());
  auto source = [](FaceId s) { return s == kNoFace ? std::int64_t{-1} : std::int64_t{s}; };
  py::dict d;
  d["V"] = positions_array(out.positions);
  d["quads"] = corners(quads, 4);
  d["triangles"] = corners(triangles, 3);
  d["polygons"] = polygons;
  d["sources"] = rows_array(order.size(), 2, [&](std::size_t i, std::int64_t* row) {
    row[0] = source(result.sources[order[i]][0]);
    row[1] = source(result.sources[order[i]][1]);
  });
  d["tutte_set"] = int64_array(result.tutte_set);
  d["stats"] = stats_dict(result.stats, options);
  d["attributes"] = attributes_dict(attributes_in_order(out, order));
  return d;
}

py::tuple read_mesh_py(const std::string& path, bool strict) {
  PolygonMesh mesh;
  std::vector<std::string> dropped;
  {
    py::gil_scoped_release release;
    mesh = read_mesh(path, &dropped, {.strict = strict});
  }
  return py::make_tuple(positions_array(mesh.positions), faces_object(mesh),
                        attributes_dict(mesh.attributes), dropped);
}

std::vector<std::string> write_mesh_py(const std::string& path, const py::handle& V,
                                       const py::handle& F, const py::handle& attributes) {
  PolygonMesh mesh;
  mesh.positions = positions_from(V);
  add_faces_from(F, mesh);
  for (VertexId v : mesh.corners) {
    if (v >= mesh.positions.size()) {
      throw py::value_error("vertex index " + std::to_string(v) + " is out of range (" +
                            std::to_string(mesh.positions.size()) + " vertices)");
    }
  }
  attributes_from(attributes, mesh);
  py::gil_scoped_release release;
  return write_mesh(path, mesh);
}

// The options of perfect_matching and maximum_matching.
PerfectMatchingOptions graph_options(const std::string& algorithm, const std::string& augment,
                                     std::uint64_t seed) {
  PerfectMatchingOptions options;
  options.algorithm = graph_algorithm_of(algorithm);
  options.augment = augment_of(augment);
  options.seed = seed;
  return options;
}

py::array_t<std::int64_t> perfect_matching_py(std::uint32_t n, const py::handle& edges,
                                              const std::string& algorithm,
                                              const std::string& augment, std::uint64_t seed) {
  const PerfectMatchingOptions options = graph_options(algorithm, augment, seed);
  const std::vector<std::array<NodeId, 2>> list = node_pairs(n, edges);
  std::vector<std::int64_t> matched;
  {
    py::gil_scoped_release release;
    const CubicGraph graph = CubicGraph::from_edges(n, list);
    const PerfectMatchingResult result = perfect_matching(graph, options);
    const MatchingCheck check = verify_perfect_matching(graph, result.matching);
    if (!check.ok()) throw std::logic_error("the matching failed the verifier: " + check.message);
    matched = matched_edges(list, result.matching.mate_edge);
  }
  return int64_array(matched);
}

// A maximum matching of any graph (match_any_graph, verified): the sorted indices of its edges,
// whether it is perfect, and the Tutte–Berge set proving it maximum (empty on a cubic bridgeless
// graph, whose matching is perfect).
py::tuple maximum_matching_py(std::uint32_t n, const py::handle& edges,
                              const std::string& algorithm, const std::string& augment,
                              std::uint64_t seed) {
  const PerfectMatchingOptions options = graph_options(algorithm, augment, seed);
  const std::vector<std::array<NodeId, 2>> list = node_pairs(n, edges);
  std::vector<std::int64_t> matched;
  AnyGraphMatching result;
  {
    py::gil_scoped_release release;
    result = match_any_graph(n, list, options);
    matched = matched_edges(list, result.mate_edge);
  }
  return py::make_tuple(int64_array(matched), result.perfect, int64_array(result.tutte_set));
}

// The cheapest maximum matching (cheapest_matching_any_graph, certified): the sorted indices of
// its edges, its total cost and whether it is perfect.
py::tuple min_cost_matching_py(
    std::uint32_t n, const py::handle& edges,
    const py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>& costs,
    std::uint32_t threads) {
  const std::vector<std::array<NodeId, 2>> list = node_pairs(n, edges);
  if (costs.ndim() != 1 || static_cast<std::size_t>(costs.shape(0)) != list.size()) {
    throw py::value_error("costs: one per edge, " + std::to_string(list.size()) +
                          ", in a flat array");
  }
  const std::vector<std::int64_t> cost_list(costs.data(), costs.data() + list.size());
  std::vector<std::int64_t> matched;
  AnyGraphCheapestMatching result;
  {
    py::gil_scoped_release release;
    result = cheapest_matching_any_graph(n, list, cost_list, threads);
    matched = matched_edges(list, result.mate_edge);
  }
  return py::make_tuple(int64_array(matched), result.total_cost, result.perfect);
}

}  // namespace
}  // namespace petersen::python

PYBIND11_MODULE(_petersen, m) {
  using namespace petersen;
  using namespace petersen::python;
  m.doc() = "The C++ core of petersen; use the functions of the petersen package.";
  // The library's located messages, as ValueError (std::invalid_argument already is one).
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const FileError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const MeshError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const GraphError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  m.def("quadrangulate", &quadrangulate_py, py::arg("V"), py::arg("F"), py::arg("algorithm"),
        py::arg("augment"), py::arg("seed"), py::arg("all_quad"), py::arg("objective"),
        py::arg("sharp_angle"), py::arg("keep_edges"), py::arg("max_corner_deviation"),
        py::arg("attributes"), py::arg("cross"), py::arg("threads"),
        py::arg("keep_polygons") = false, py::arg("triangle_cost") = kDefaultTriangleCost,
        py::arg("flow_weight") = kDefaultFlowWeight, py::arg("drop_duplicate_faces") = false);
  m.def("read_mesh", &read_mesh_py, py::arg("path"), py::arg("strict") = false);
  m.def("write_mesh", &write_mesh_py, py::arg("path"), py::arg("V"), py::arg("F"),
        py::arg("attributes"));
  m.def("perfect_matching", &perfect_matching_py, py::arg("n"), py::arg("edges"),
        py::arg("algorithm"), py::arg("augment"), py::arg("seed"));
  m.def("maximum_matching", &maximum_matching_py, py::arg("n"), py::arg("edges"),
        py::arg("algorithm"), py::arg("augment"), py::arg("seed"));
  m.def("min_cost_matching", &min_cost_matching_py, py::arg("n"), py::arg("edges"),
        py::arg("costs"), py::arg("threads"));
  m.attr("CROSSABLE") = crossable_names();
  m.attr("DEFAULT_TRIANGLE_COST") = kDefaultTriangleCost;
  add_render(m);
  add_partition(m);
  add_ply_stream(m);
  add_all_quad(m);
  add_graph_functions(m);
}
