#pragma once
// The shape of a quad as its worst corner's deviation from a right angle (issue 14's measure),
// and that cost for every quad the dual of a closed triangle mesh could form.

#include <array>

#include "petersen/dualize/dual.hpp"
#include "petersen/dualize/mesh.hpp"
#include "petersen/graph/huge_pages.hpp"

namespace petersen {

/// What a degenerate quad costs: the largest deviation any quad can reach (an interior angle
/// near 360°), so the matching avoids degenerate quads before any other.
inline constexpr double kDegenerateQuadCost = 270.0;

/// The worst-corner deviation of quad a, b, c, d (corners in order), in degrees:
/// n = unit((c − a) × (d − b)); at each corner the two quad edges are projected onto the plane
/// orthogonal to n and the interior angle θ is taken in [0°, 360°), counter-clockwise about n
/// from the edge to the next corner to the edge to the previous one, so a reflex corner of a
/// non-convex quad is above 180°; cost = max over the four corners of |90° − θ|. A planar square
/// or rectangle costs 0; a non-convex quad costs more than 90.
/// Degenerate quads cost kDegenerateQuadCost: a non-finite coordinate, parallel or zero
/// diagonals (no normal n), or a corner whose projected edge has zero length. Never NaN. O(1).
double quad_corner_deviation(const std::array<double, 3>& a, const std::array<double, 3>& b,
                             const std::array<double, 3>& c, const std::array<double, 3>& d);

/// For each edge e of `dual` (built by build_dual from `mesh`), the cost of the quad its two
/// triangles would form, with the corners quads_from_matching gives it: triangles (a, b, c) and
/// (b, a, d) sharing edge a-b form (a, d, b, c). O(F).
HugeVector<double> dual_edge_quality(const TriangleMesh& mesh, const Dual& dual);

}  // namespace petersen
