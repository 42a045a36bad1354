#pragma once
// The quads of a mesh summarised by issue 14's measure (quad_corner_deviation, in
// petersen/dualize/quad_quality.hpp), which the pictures colour quads by.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "petersen/dualize/mesh.hpp"
#include "petersen/dualize/quad_quality.hpp"

namespace petersen {

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
