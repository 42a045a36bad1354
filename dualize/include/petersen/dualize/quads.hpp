#pragma once
// A perfect matching of the dual of a TriangleMesh turned into quads, and the check that they form
// a closed quad mesh of the same surface: for lrs/ (with its tests), which takes TriangleMesh. The
// rest of the library pairs PolygonMesh triangles through quad_of.hpp.

#include <string>

#include "petersen/graph/cubic_graph.hpp"
#include "petersen/matching/matching.hpp"
#include "petersen/mesh/mesh.hpp"

namespace petersen {

/// Merges the two triangles of every matched dual edge into one quad that keeps their
/// orientation: triangles (a, b, c) and (b, a, d) sharing edge a-b give the quad (a, d, b, c).
/// `dual` is the dual graph of `mesh` (node t = triangle t; any edge numbering, so the graph of
/// build_dual and of dual_graph both work). Quads come in order of their first triangle.
/// Throws MeshError if the matching is not a perfect matching of `dual` (with the verifier's
/// message), if the sizes disagree, or if a matched edge joins two triangles that share no edge
/// (naming the edge and triangles). O(F).
QuadMesh quads_from_matching(const TriangleMesh& mesh, const CubicGraph& dual,
                             const Matching& matching);

/// The outcome of check_quad_mesh: ok() or the first problem found.
struct QuadCheck {
  std::string problem;
  bool ok() const { return problem.empty(); }
};

/// Checks `quads` against the triangle mesh it came from: the same positions and the same set of
/// referenced vertices, four distinct in-range corners per quad, every edge in exactly two quads
/// that run along it in opposite directions, and the same Euler characteristic V - E + F.
/// O(F log F).
QuadCheck check_quad_mesh(const TriangleMesh& source, const QuadMesh& quads);

}  // namespace petersen
