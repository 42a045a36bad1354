#pragma once
// The threshold mode (QuadOptions::max_corner_deviation): pairs whose quad is too far from right
// angles become cuts, before any matching.

#include "petersen/dualize/pairable_graph.hpp"

namespace petersen::quad_detail {

/// Removes from `graph` (the pairable graph of `mesh`) every edge whose cost in `degrees`
/// (pairable_edge_quality) is above `max_degrees`, counting each as a CutCause::shape cut and no
/// longer as an inconsistent edge; the edges left keep their relative order and `degrees` (and
/// `also`, another per-edge array, when not null) follows them. The graph is no longer cubic when
/// any edge goes. O(F).
void cut_by_shape(PairableGraph& graph, const PolygonMesh& mesh, std::pmr::vector<double>& degrees,
                  double max_degrees, std::pmr::vector<double>* also = nullptr);

}  // namespace petersen::quad_detail
