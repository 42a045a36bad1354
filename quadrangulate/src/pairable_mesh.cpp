// Stage 1 of the front door (stages.hpp): the pairable graph, its cuts and the pairs' costs.

#include <bit>
#include <optional>

#include "attribute_cuts.hpp"
#include "petersen/dualize/cross_field.hpp"
#include "petersen/dualize/quad_quality.hpp"
#include "petersen/graph/component_forest.hpp"
#include "petersen/graph/parallel.hpp"
#include "petersen/graph/stopwatch.hpp"
#include "petersen/mesh/duplicate_faces.hpp"
#include "petersen/quadrangulate/stages.hpp"
#include "shape_cuts.hpp"

namespace petersen {

namespace {

// How many vertices some face's corners name (those out of range left out: the graph rejects
// them). A bit per vertex: 86 KB on armadillo-sub2, where a byte each is 692 KB of fresh pages.
std::int64_t referenced_vertex_count(const PolygonMesh& mesh) {
  const std::size_t vertex_count = mesh.positions.size();
  std::vector<std::uint64_t> referenced((vertex_count + 63) / 64, 0);
  for (VertexId v : mesh.corners) {
    if (v < vertex_count) referenced[v / 64] |= std::uint64_t{1} << (v % 64);
  }
  std::int64_t count = 0;
  for (std::uint64_t word : referenced) count += std::popcount(word);
  return count;
}

// The faces that may have the same corners as another: the polygons, and the triangles cut on
// every side (a triangle's copy shares all its edges with it, so each is an edge of three or more
// faces or a duplicate cut). Without non-manifold or duplicate cuts there are no copies of
// triangles, and the caller does not ask. O(F).
std::vector<FaceId> duplicate_candidates(const PolygonMesh& mesh, const PairableGraph& graph) {
  std::vector<FaceId> faces;
  for (NodeId v = 0; v < graph.node_count; ++v) {
    const EdgeId* sides = graph.node_edges.data() + 3 * std::size_t{v};
    if (sides[0] == kNoEdge && sides[1] == kNoEdge && sides[2] == kNoEdge) {
      faces.push_back(graph.face_of(v));
    }
  }
  if (!mesh.all_triangles()) {
    for (FaceId f = 0; f < mesh.face_count(); ++f) {
      if (mesh.arity(f) != 3) faces.push_back(f);
    }
  }
  return faces;
}

void record_graph_figures(const PolygonMesh& mesh, const PairableGraph& graph,
                          std::int64_t referenced_vertices, QuadStats& stats) {
  const FaceId face_count = static_cast<FaceId>(mesh.face_count());
  stats.faces_in = face_count;
  stats.vertices = mesh.positions.size();
  stats.triangles = graph.node_count;
  stats.polygons_kept = face_count - graph.node_count;
  stats.mesh_edges = graph.mesh_edges;
  stats.cuts = graph.cuts;
  if (graph.cuts.by_cause[static_cast<int>(CutCause::non_manifold)] > 0 ||
      graph.cuts.by_cause[static_cast<int>(CutCause::duplicate)] > 0) {
    stats.duplicate_faces = duplicate_faces(mesh, duplicate_candidates(mesh, graph)).size();
  }
  stats.inconsistent_edges = graph.inconsistent_edges;
  stats.euler_characteristic =
      referenced_vertices - std::int64_t(graph.mesh_edges) + std::int64_t(face_count);
}

// A closed, consistently oriented surface of triangles whose pairs some chosen cuts refuse (seams,
// borders, sharp edges): its genus is the surface's, whose components join across those cuts.
// Without chosen cuts pair_triangles counts the components, and the front door the genus.
void genus_across_chosen_cuts(const PairableGraph& graph, QuadStats& stats) {
  if (graph.cuts.structural() != 0 || stats.polygons_kept != 0 ||
      graph.inconsistent_edges + graph.inconsistent_chosen_cuts != 0 ||
      graph.chosen_cut_ends.empty()) {
    return;
  }
  ComponentForest surface(graph.node_count, graph.edge_ends);
  surface.join(graph.chosen_cut_ends);
  stats.genus = (2 * std::int64_t(surface.root_count()) - stats.euler_characteristic) / 2;
}

// Objective::quads with a flow weight: each pair's cost gets its weighted flow against the cross
// field, made over the whole pairable graph before any shape cut (a threshold says which pairs
// are allowed, not where the quads' edge loops run); the threshold then judges shape alone.
std::pmr::vector<double> edge_flow(const PairableGraph& graph, const PolygonMesh& mesh,
                                   QuadStats& stats) {
  Stopwatch clock;
  const CrossField field = cross_field(graph, mesh);
  std::pmr::vector<double> flow = pairable_edge_flow(graph, side_alignment(field));
  stats.field_iterations = field.iterations;
  stats.field_seconds = clock.lap();
  return flow;
}

}  // namespace

PairableMesh pairable_mesh(const PolygonMesh& mesh, const QuadOptions& options, QuadStats& stats) {
  // The graph and the costs are made on options.memory and moved in, never assigned: an
  // assignment across resources would copy them (memory.hpp).
  std::optional<PairableGraph> built;
  // The referenced vertices are counted on a second thread beside the graph's single-threaded
  // start (the corners' range check and the bucket offsets, longer than the count).
  std::int64_t referenced_vertices = 0;
  run_parallel(options.threads, 2, [&](std::uint32_t task) {
    if (task == 1) {
      referenced_vertices = referenced_vertex_count(mesh);
      return;
    }
    quad_detail::AttributeCutIds ids;  // freed once the graph has the cuts
    built.emplace(build_pairable_graph(mesh, quad_detail::attribute_cuts(mesh, options, ids),
                                       options.threads, options.memory));
  });
  PairableMesh pairable{std::move(*built), std::pmr::vector<double>(options.memory)};
  PairableGraph& graph = pairable.graph;
  if (options.objective != Objective::pairs || options.max_corner_deviation) {
    pairable.costs = pairable_edge_quality(graph, mesh, options.threads, options.memory);
  }
  std::pmr::vector<double> flow;
  if (options.objective == Objective::quads && options.flow_weight > 0) {
    flow = edge_flow(graph, mesh, stats);
  }
  if (options.max_corner_deviation) {
    quad_detail::cut_by_shape(graph, mesh, pairable.costs, *options.max_corner_deviation,
                              flow.empty() ? nullptr : &flow);
  }
  for (EdgeId e = 0; e < flow.size(); ++e) pairable.costs[e] += options.flow_weight * flow[e];
  record_graph_figures(mesh, graph, referenced_vertices, stats);
  genus_across_chosen_cuts(graph, stats);
  free_storage(graph.chosen_cut_ends);  // `= {}` would keep the capacity
  return pairable;
}

}  // namespace petersen
