#include "shape_cuts.hpp"

namespace petersen::quad_detail {

void cut_by_shape(PairableGraph& graph, HugeVector<double>& degrees, double max_degrees) {
  // Edges kept are renumbered in order; new_id[e] is kNoEdge for an edge cut.
  HugeVector<EdgeId> new_id(graph.edge_count(), kNoEdge);
  EdgeId kept = 0;
  for (EdgeId e = 0; e < graph.edge_count(); ++e) {
    // "At most DEG" is pairable; a NaN cost cannot happen (quad_corner_deviation never gives one).
    if (degrees[e] > max_degrees) {
      ++graph.cuts.by_cause[static_cast<int>(CutCause::shape)];
      continue;
    }
    graph.edge_ends[2 * std::size_t{kept}] = graph.edge_ends[2 * std::size_t{e}];
    graph.edge_ends[2 * std::size_t{kept} + 1] = graph.edge_ends[2 * std::size_t{e} + 1];
    degrees[kept] = degrees[e];
    new_id[e] = kept++;
  }
  graph.edge_ends.resize(2 * std::size_t{kept});
  degrees.resize(kept);
  for (EdgeId& e : graph.node_edges) {
    if (e != kNoEdge) e = new_id[e];
  }
  graph.cubic = 2 * std::size_t{kept} == graph.node_edges.size();
}

}  // namespace petersen::quad_detail
