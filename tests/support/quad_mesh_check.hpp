#pragma once
// Quads made from a perfect matching of a closed triangle mesh's dual, and the check that they
// form a closed quad mesh of the same surface: what the dual and the matchings promise, checked
// end to end.

#include <cstdint>
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

/// The first way the faces of `output` fail to be the triangles of the all-triangle `source`,
/// each used exactly once, or "": a triangle face stands for itself, a quad for the two triangles
/// on its diagonal from corner 0 to corner 2 (quad_of's corners (a, d, b, c) for triangles
/// (a, b, c) and (b, a, d)) and has four distinct corners; no other arity. Counts the quads into
/// `quads`. O(F log F).
std::string pairing_problem(const PolygonMesh& source, const PolygonMesh& output,
                            std::uint64_t& quads);

/// The first way `quads` fails to be a closed quad mesh of the surface of `source`, or "": the
/// same positions and the same set of referenced vertices, four distinct in-range corners per
/// face, every edge in exactly two quads that run along it in opposite directions, and the same
/// Euler characteristic V - E + F. O(F log F).
std::string quad_mesh_problem(const PolygonMesh& source, const PolygonMesh& quads);

/// What all_quad_file_problem counted.
struct AllQuadFileCounts {
  std::uint64_t quads = 0, kept_triangles = 0, midpoints = 0, centres = 0;
};

/// The first way `output` fails to be an all-quad refinement of the triangle mesh `source` as
/// --all-quad makes it from the files alone (no sources, no library code but the mesh type), or
/// "": the source's positions first and unmoved; every face a quad of four distinct in-range
/// corners (but a source triangle that repeats a vertex, kept); every added vertex either the
/// midpoint of a source edge (its position the average of the ends' within float rounding, an
/// output edge to each end, that source edge gone) or a centre (an inner vertex: every edge at it
/// in two faces); every edge in one or two faces, two running along it in opposite directions
/// where the source's do; every source edge kept, split in two halves, or removed (then it had
/// two source faces: a pair's diagonal); the boundary the source's, split edges in halves; the
/// same Euler characteristic V − E + F over the used vertices. O(F log F).
std::string all_quad_file_problem(const PolygonMesh& source, const PolygonMesh& output,
                                  AllQuadFileCounts& counts);

}  // namespace petersen::testing
