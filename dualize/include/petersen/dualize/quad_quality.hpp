#pragma once
// The shape of a quad as its worst corner's deviation from a right angle, that cost for every
// quad two pairable triangles could form, and the figures that summarise a mesh's quads
// (quadrangulate's stats, `petersen info`, the pictures' captions).

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "petersen/dualize/pairable_graph.hpp"
#include "petersen/graph/memory.hpp"
#include "petersen/mesh/mesh.hpp"

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

/// For each edge of `graph` (the pairable graph of `mesh`), the cost of the quad its two triangles
/// make, with the corners quadrangulate gives it: the lower face t1 = (a, b, c) sharing edge a-b
/// with t2 = {a, b, d} forms (a, d, b, c), whichever way t2 runs. O(F), on `threads` threads (0:
/// every core); the costs do not depend on the threads. The array is allocated from `memory`.
std::pmr::vector<double> pairable_edge_quality(
    const PairableGraph& graph, const PolygonMesh& mesh, std::uint32_t threads = 1,
    std::pmr::memory_resource* memory = std::pmr::get_default_resource());

/// Quads summarised by their costs: how many, the median and 95th percentile (the nearest-rank
/// element of the sorted costs; 0 when there are no quads), how many are non-convex (cost above
/// 90°), and the sum of the costs.
struct QualityFigures {
  std::uint64_t quads = 0;
  double median = 0, p95 = 0, total = 0;
  std::uint64_t nonconvex = 0;
};

/// The cost of every face of four corners of `mesh`, in face order. O(F).
std::vector<double> quad_costs(const PolygonMesh& mesh);

/// The figures of the given costs. O(q).
QualityFigures quality_figures(std::vector<double> costs);

/// The same figures, reordering `costs` in place rather than copying them. O(q).
QualityFigures quality_figures_in_place(std::span<double> costs);

/// One line for people: "1550 quads, worst corner median 12.3°, p95 40.2°, 3 non-convex, total
/// 9876.5°".
std::string describe(const QualityFigures& figures);

}  // namespace petersen
