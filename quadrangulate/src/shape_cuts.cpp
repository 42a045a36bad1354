#include "shape_cuts.hpp"

namespace petersen::quad_detail {

namespace {

// Whether the triangles of edge e run along it the same way: node v's side k starts at the same
// vertex as the other node's side across e.
bool runs_same_way(const PairableGraph& graph, const PolygonMesh& mesh, EdgeId e) {
  const NodeId v = graph.edge_ends[2 * std::size_t{e}], w = graph.edge_ends[2 * std::size_t{e} + 1];
  VertexId from[2] = {};
  for (int end = 0; end < 2; ++end) {
    const NodeId node = end == 0 ? v : w;
    const auto corners = mesh.face(graph.face_of(node));
    for (int k = 0; k < 3; ++k) {
      if (graph.node_edges[3 * std::size_t{node} + k] == e) from[end] = corners[k];
    }
  }
  return from[0] == from[1];
}

}  // namespace

void cut_by_shape(PairableGraph& graph, const PolygonMesh& mesh, std::pmr::vector<double>& degrees,
                  double max_degrees, std::pmr::vector<double>* also) {
  // Edges kept are renumbered in order; new_id[e] is kNoEdge for an edge cut.
  std::pmr::vector<EdgeId> new_id(graph.edge_count(), kNoEdge);
  EdgeId kept = 0;
  for (EdgeId e = 0; e < graph.edge_count(); ++e) {
    // "At most DEG" is pairable; a NaN cost cannot happen (quad_corner_deviation never gives one).
    if (degrees[e] > max_degrees) {
      ++graph.cuts.by_cause[static_cast<int>(CutCause::shape)];
      const bool same_way = runs_same_way(graph, mesh, e);
      graph.inconsistent_edges -= same_way;
      graph.inconsistent_chosen_cuts += same_way;
      graph.chosen_cut_ends.push_back(graph.edge_ends[2 * std::size_t{e}]);
      graph.chosen_cut_ends.push_back(graph.edge_ends[2 * std::size_t{e} + 1]);
      continue;
    }
    graph.edge_ends[2 * std::size_t{kept}] = graph.edge_ends[2 * std::size_t{e}];
    graph.edge_ends[2 * std::size_t{kept} + 1] = graph.edge_ends[2 * std::size_t{e} + 1];
    degrees[kept] = degrees[e];
    if (also != nullptr) (*also)[kept] = (*also)[e];
    new_id[e] = kept++;
  }
  graph.edge_ends.resize(2 * std::size_t{kept});
  degrees.resize(kept);
  if (also != nullptr) also->resize(kept);
  for (EdgeId& e : graph.node_edges) {
    if (e != kNoEdge) e = new_id[e];
  }
  graph.cubic = 2 * std::size_t{kept} == graph.node_edges.size();
}

}  // namespace petersen::quad_detail
