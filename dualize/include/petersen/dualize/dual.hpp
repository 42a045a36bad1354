#pragma once
// The dual graph of a closed triangle mesh: one node per triangle, one edge per mesh edge.

#include <vector>

#include "petersen/graph/cubic_graph.hpp"
#include "petersen/mesh/mesh.hpp"

namespace petersen {

/// A halfedge is edge k of triangle t, numbered 3t + k; it runs from corner k to corner (k+1)%3.
using HalfedgeId = std::uint32_t;

/// The dual graph with its correspondence to the mesh: node t's k-th incident edge,
/// graph.incident_edge(t, k), is the dual of edge k of triangle t (corners k, (k+1)%3).
struct Dual {
  CubicGraph graph;

  EdgeId dual_edge(FaceId t, int k) const { return graph.incident_edge(t, k); }
  /// The halfedge that dual edge e crosses in triangle graph.endpoints(e)[end]; the halfedges of
  /// the two ends run along the same mesh edge in opposite directions. O(1).
  HalfedgeId side(EdgeId e, int end) const {
    const FaceId t = graph.endpoints(e)[end];
    const auto slots = graph.incident_edges(t);
    // e has two distinct ends, each listed once, so exactly one slot of t names it.
    const int k = slots[0] == e ? 0 : slots[1] == e ? 1 : 2;
    return 3 * t + static_cast<HalfedgeId>(k);
  }
};

/// Builds the dual of a closed, edge-manifold, consistently oriented triangle mesh (every face a
/// triangle): triangle i is node i. Dual edges are numbered by their mesh edge {a, b} in order of
/// (min(a, b), max(a, b)), and the first endpoint of each is the triangle with the smaller
/// halfedge id. Pinched vertices and several components are allowed (the dual stays cubic; it is
/// then disconnected). Throws MeshError naming the face when a face is not a triangle, and the
/// triangle or edge (a, b) when a corner is out of range, a triangle repeats a corner, an edge has
/// one triangle (boundary) or more than two, or its two triangles run along it in the same
/// direction (inconsistent orientation).
/// O(F log d) for maximum vertex degree d, no hashing: halfedges are bucketed by their smaller
/// vertex and each bucket is sorted by the larger one.
Dual build_dual(const PolygonMesh& mesh);

/// The dual graph alone (see build_dual for the numbering and the errors).
CubicGraph dual_graph(const PolygonMesh& mesh);

}  // namespace petersen
