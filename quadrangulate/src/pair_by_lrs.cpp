#include "pair_by_lrs.hpp"

#include <array>
#include <functional>
#include <optional>
#include <utility>

#include "petersen/lrs/lrs.hpp"

namespace petersen::quad_detail {

namespace {

// A closed component as a mesh of triangles on its own vertices, for lrs.
struct ComponentMesh {
  PolygonMesh mesh;
  std::vector<VertexId> vertex_of;  // local vertex -> input vertex; empty: the same ids
  VertexId input_vertex(VertexId v) const { return vertex_of.empty() ? v : vertex_of[v]; }
};

ComponentMesh component_mesh(const PolygonMesh& mesh, const PairableGraph& graph,
                             std::span<const NodeId> nodes, std::vector<VertexId>& local) {
  ComponentMesh part;
  if (nodes.size() == graph.node_count && mesh.all_triangles()) {
    // The whole mesh is one closed component: no renumbering, and lrs's refusal names the
    // input's own vertices and edges.
    part.mesh.positions = mesh.positions;
    part.mesh.corners = mesh.corners;
    return part;
  }
  part.mesh.corners.reserve(3 * nodes.size());
  for (NodeId v : nodes) {
    for (const VertexId corner : mesh.face(graph.face_of(v)).first(3)) {
      VertexId& id = local[corner];
      if (id == kNoNode) {
        id = static_cast<VertexId>(part.vertex_of.size());
        part.vertex_of.push_back(corner);
        part.mesh.positions.push_back(mesh.positions[corner]);
      }
      part.mesh.corners.push_back(id);
    }
  }
  for (VertexId v : part.vertex_of) local[v] = kNoNode;
  return part;
}

void refuse(QuadStats& stats, const char* reason) {
  if (stats.lrs_fallback_components++ == 0) stats.lrs_fallback_reason = reason;
}

// The whole graph by lrs from its own arrays. The caller has counted one component (the choice
// of this path). Without sources, the consuming door's corners are freed as soon as the
// triangulation has read them, 12 bytes per triangle off the rest of lrs.
std::optional<LrsPairing> pair_whole_graph(PairableGraph& graph, const PolygonMesh& mesh,
                                           std::pmr::vector<VertexId>* releasable_corners,
                                           const QuadOptions& options, QuadStats& stats) {
  LrsDualInput input{.positions = mesh.positions,
                     .corners = mesh.corners,
                     .node_edges = std::move(graph.node_edges),
                     .edge_ends = std::move(graph.edge_ends),
                     .connected = true};
  if (!options.sources && releasable_corners != nullptr) {
    input.corners_read = [releasable_corners] {
      free_storage(*releasable_corners);  // `= {}` would keep the buffer
    };
  }
  try {
    return pair_closed_component_by_lrs(std::move(input), {.augment = options.augment,
                                                           .sources = options.sources,
                                                           .threads = options.threads,
                                                           .memory = options.memory});
  } catch (const MeshError& e) {
    // A pinched vertex: the default algorithm pairs the mesh instead, on the graph made again. No
    // cut touched this mesh (every side of every triangle is pairable), so it is the graph built
    // before.
    refuse(stats, e.what());
    PairableGraph again = build_pairable_graph(mesh, {}, options.threads, options.memory);
    graph.node_edges = std::move(again.node_edges);
    graph.edge_ends = std::move(again.edge_ends);
    return std::nullopt;
  }
}

void add_lrs_stats(const LrsStats& lrs, double elapsed, QuadStats& stats) {
  const double matching = lrs.contraction_seconds + lrs.expansion_seconds + lrs.augment_seconds;
  stats.matching.initial_seconds += lrs.contraction_seconds + lrs.expansion_seconds;
  stats.matching.augment_seconds += lrs.augment_seconds;
  stats.matching.unpaired_after_initial += lrs.unpaired_after_expansion;
  stats.matching.augmenting_paths += lrs.augmenting_paths;
  stats.matching.blossoms += lrs.blossoms;
  stats.matching.nodes_labelled += lrs.nodes_labelled;
  stats.verify_seconds += lrs.verify_seconds;
  // Beside its phases, lrs builds its triangulation and the quads: set-up, like a dual.
  stats.dual_seconds += elapsed - matching - lrs.verify_seconds;
  stats.flipped_edges += lrs.flipped_edges;
  stats.irreducible_vertices += lrs.irreducible_vertices;
}

}  // namespace

bool pair_component_by_lrs(PairableGraph& graph, const PolygonMesh& mesh,
                           std::span<const NodeId> nodes,
                           std::pmr::vector<VertexId>* releasable_corners,
                           const QuadOptions& options, std::vector<VertexId>& local,
                           TrianglePairing& pairing, QuadStats& stats, Stopwatch& clock) {
  if (mesh.attributes.has_corner_attributes() || mesh.attributes.has_face_attributes()) {
    // A triangle lrs's flips make has no input corners or face to take these from.
    refuse(stats,
           "texture coordinates, normals or face attributes, which lrs's flipped triangles would "
           "not have");
    return false;
  }
  if (nodes.empty()) {
    std::optional<LrsPairing> whole =
        pair_whole_graph(graph, mesh, releasable_corners, options, stats);
    if (!whole) return false;
    pairing.lrs_quads = std::move(whole->quads);  // node t is face t: the sources are face ids
    pairing.partner.assign(graph.node_count, kLrsNode);
    add_lrs_stats(whole->stats, clock.lap(), stats);
    return true;
  }
  const ComponentMesh part = component_mesh(mesh, graph, nodes, local);
  LrsPairing lrs;
  try {
    lrs = pair_closed_component_by_lrs(part.mesh,
                                       {.augment = options.augment, .sources = true, .threads = 1});
  } catch (const MeshError& e) {
    // Its surface check: lrs needs a connected, orientable manifold (no pinched vertex).
    refuse(stats, e.what());
    return false;
  }
  for (LrsQuad quad : lrs.quads) {
    for (VertexId& corner : quad.corners) corner = part.input_vertex(corner);
    for (FaceId& source : quad.sources) {
      if (source != kNoFace) source = graph.face_of(nodes[source]);
    }
    pairing.lrs_quads.push_back(quad);
  }
  for (NodeId v : nodes) pairing.partner[v] = kLrsNode;
  add_lrs_stats(lrs.stats, clock.lap(), stats);
  return true;
}

}  // namespace petersen::quad_detail
