#pragma once
// Quads made from a perfect matching of a closed triangle mesh's dual, and the check that they
// form a closed quad mesh of the same surface: what the dual and the matchings promise, checked
// end to end.

#include <string>

#include "petersen/graph/cubic_graph.hpp"
#include "petersen/matching/matching.hpp"
#include "petersen/mesh/mesh.hpp"

namespace petersen::testing {

/// One quad per matched edge of `dual` (the dual graph of the all-triangle `mesh`, node t =
/// triangle t, any edge numbering), with quad_of's corners for its two triangles, in order of the
/// lower one: triangles (a, b, c) and (b, a, d) give (a, d, b, c). Throws MeshError (with the
/// verifier's message) unless the matching is a perfect matching of `dual`. O(F).
PolygonMesh quads_of_matching(const PolygonMesh& mesh, const CubicGraph& dual,
                              const Matching& matching);

/// The first way `quads` fails to be a closed quad mesh of the surface of `source`, or "": the
/// same positions and the same set of referenced vertices, four distinct in-range corners per
/// face, every edge in exactly two quads that run along it in opposite directions, and the same
/// Euler characteristic V - E + F. O(F log F).
std::string quad_mesh_problem(const PolygonMesh& source, const PolygonMesh& quads);

}  // namespace petersen::testing
