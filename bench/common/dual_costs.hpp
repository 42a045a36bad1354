#pragma once
// The quad cost of every edge of a closed triangle mesh's dual: the costs the weighted matchings
// are measured on, the same --objective quality gives the pairable graph of a closed mesh.

#include "petersen/dualize/dual.hpp"
#include "petersen/dualize/quad_of.hpp"
#include "petersen/dualize/quad_quality.hpp"

namespace petersen::bench {

/// For each edge e of `dual` (build_dual of the all-triangle `mesh`), the worst-corner cost of the
/// quad its two triangles make, in the orientation of its first end: quad_across at the side e
/// crosses, with the other triangle's corner off that side. O(F).
inline std::pmr::vector<double> dual_edge_costs(const PolygonMesh& mesh, const Dual& dual) {
  const CubicGraph& graph = dual.graph;
  const auto& p = mesh.positions;
  std::pmr::vector<double> cost(graph.edge_count());
  for (EdgeId e = 0; e < graph.edge_count(); ++e) {
    // Halfedge 3t + k runs from corner k to corner k + 1 of triangle t; its twin runs back, so
    // the other triangle's corner off the edge is the one after the twin's end.
    const HalfedgeId h1 = dual.side(e, 0), h2 = dual.side(e, 1);
    const VertexId off = mesh.face(h2 / 3)[(h2 % 3 + 2) % 3];
    const auto q = quad_across(mesh.face(h1 / 3), static_cast<int>(h1 % 3), off);
    cost[e] = quad_corner_deviation(p[q[0]], p[q[1]], p[q[2]], p[q[3]]);
  }
  return cost;
}

}  // namespace petersen::bench
