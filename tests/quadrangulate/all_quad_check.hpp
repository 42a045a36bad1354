#pragma once
// The independent check of all_quad's output (result_check.hpp's all-quad part): the output is
// judged from the input and the result's sources alone, sharing no code with quadrangulate.
//
// The faces of the pairing ("pre-split faces") are the distinct sources of the output faces: a
// pair {t1, t2} is the quad of its two triangles in t1's orientation, {f, kNoFace} the input face
// f. Every group of output faces with one source must tile its pre-split face: the pieces follow
// its orientation, their boundary is its cycle with at most one new vertex on each side, their
// inner vertices are new ones (centres), and they form a disk (V − E + F = 1). Every side is
// split in all the faces on it or in none, with one midpoint.

#include <cstdint>
#include <string>

#include "petersen/quadrangulate/quadrangulate.hpp"

namespace petersen::testing {

/// How the input's faces that are not triangles must come out of an all-quad run.
enum class KeptPolygons {
  either,   ///< kept exactly or rebuilt into quads (a caller that does not know the options)
  kept,     ///< QuadOptions::keep_polygons: exactly as in the input
  rebuilt,  ///< into quads like every other face
};

/// What check_all_quad_mesh found: the first problem (empty when none), and the output's split
/// edges (pre-split sides given a midpoint) and centre vertices (new vertices inside a face).
struct AllQuadCheck {
  std::string problem;
  std::uint64_t split_edges = 0, centre_vertices = 0;
};

/// Checks the output of an all-quad run as described at the top of this file, plus: every output
/// face is a quad (but kept polygons, and faces repeating a vertex kept exactly as they were),
/// input vertices are unmoved, every added vertex is a midpoint or a centre, no inner edge of a
/// face's pieces is an edge of another face, and each component (faces joined through edges) keeps
/// its Euler characteristic, boundary loops and orientability. `flips_allowed`: lrs's quads with a
/// triangle its flips made are skipped (they are checked by the pairing check). O(C log C) for C
/// output corners.
AllQuadCheck check_all_quad_mesh(const PolygonMesh& input, const QuadResult& result,
                                 KeptPolygons polygons, bool flips_allowed);

/// Empty when QuadStats' all-quad figures agree with the output and the options: added_vertices
/// is the count of new positions and split_edges + centre_vertices, both as counted by
/// check_all_quad_mesh; added_vertices_minimum ≤ split_edges; with Objective::pairs no centre
/// and split_edges == added_vertices_minimum; the split quads' quality median ≤ p95.
std::string check_all_quad_counts(const PolygonMesh& input, const QuadResult& result,
                                  const QuadOptions& options, const AllQuadCheck& counted);

}  // namespace petersen::testing
