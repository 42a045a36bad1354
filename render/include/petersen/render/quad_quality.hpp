#pragma once
// The shape of a quad as its worst corner's deviation from a right angle (issue 14's measure),
// which the pictures colour quads by.
// The branch of issue 14 declares the same function in petersen/dualize/quad_quality.hpp; when
// both are on main, this file gives way to that one.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "petersen/dualize/mesh.hpp"

namespace petersen {

/// What a degenerate quad costs: the largest deviation any quad can reach.
inline constexpr double kDegenerateQuadCost = 270.0;

/// The worst-corner deviation of quad a, b, c, d (corners in order), in degrees:
/// n = unit((c − a) × (d − b)); at each corner the two quad edges are projected onto the plane
/// orthogonal to n and the interior angle θ is taken in [0°, 360°), counter-clockwise about n
/// from the edge to the next corner to the edge to the previous one, so a reflex corner of a
/// non-convex quad is above 180°; cost = max over the four corners of |90° − θ|. A planar
/// rectangle costs 0, a non-convex quad more than 90. Degenerate quads (a non-finite coordinate,
/// parallel or zero diagonals, a projected edge of zero length) cost kDegenerateQuadCost. O(1).
double quad_corner_deviation(const std::array<double, 3>& a, const std::array<double, 3>& b,
                             const std::array<double, 3>& c, const std::array<double, 3>& d);

/// The quads of a mesh summarised: how many, the median and 95th percentile of their cost (the
/// nearest-rank element of the sorted costs; 0 when there are no quads), how many are non-convex
/// (cost above 90°).
struct QuadQualityFigures {
  std::uint64_t quads = 0;
  double median = 0, p95 = 0;
  std::uint64_t nonconvex = 0;
};

/// The cost of every face of four corners of `mesh`, in face order. O(F).
std::vector<double> quad_costs(const PolygonMesh& mesh);

/// The figures of the given costs. O(q log q).
QuadQualityFigures quality_figures(std::vector<double> costs);

/// One line for people: "1550 quads, worst corner median 12.3°, p95 40.2°, 3 non-convex".
std::string describe(const QuadQualityFigures& figures);

}  // namespace petersen
