#pragma once
// A smooth cross field (4-direction field) on a mesh's triangles, and how far each triangle's sides
// lie from it: the edge flow that the quads objective weighs beside the quads' shape.
//
// The field is the smoothest 4-direction field aligned where the mesh says so (Knöppel, Crane,
// Pinkall, Schröder 2013, "Globally optimal direction fields", section 5: the connection Laplacian
// with an alignment term). A cross on triangle t is a complex number u_t in t's own frame whose
// argument is four times the cross's angle, so the four directions of a cross are one value. It
// minimises
//   sum over pairable edges {s, t} of |u_s − r_st u_t|²  +  λ · sum over triangles t of |u_t −
//   q_t|²
// where r_st turns t's frame into s's across their shared edge (the discrete Levi-Civita
// connection, raised to the fourth power), and q_t is what the triangle's own sides say: three
// times the mean of e^{4iα} over its sides at angles α (a cut side: boundary, sharp fold, seam,
// polygon border, counting kFeatureSideWeight times), at most 1 in modulus, so that a right
// isosceles triangle says 1 and an equilateral one nothing. On a triangulated quad mesh two of each
// triangle's three sides are quad sides at right angles, which agree in the fourth power, while the
// diagonal near 45° points the other way: the smoothed field follows the quads' edge loops. The
// field is fixed before any pairing, so each pair's flow cost is its own and the minimum-cost
// matching stays exact.

#include <array>
#include <complex>
#include <cstdint>
#include <span>
#include <vector>

#include "petersen/dualize/pairable_graph.hpp"
#include "petersen/graph/memory.hpp"
#include "petersen/mesh/mesh.hpp"

namespace petersen {

/// How much more a cut side of a triangle says about the field than a pairable one: features and
/// boundaries are where quads must run along.
inline constexpr double kFeatureSideWeight = 4.0;

struct CrossFieldOptions {
  /// λ, the weight of alignment against smoothness (per triangle, against one per pairable edge):
  /// larger follows each triangle's own sides, smaller smooths over more neighbours.
  double alignment = 1.0;
  /// The conjugate-gradient solve stops when the residual falls below this, relative to the right
  /// side, or after max_iterations.
  double tolerance = 1e-6;
  std::uint32_t max_iterations = 200;
};

struct CrossField {
  /// Per node of the pairable graph: u_t in the frame whose first axis runs along the triangle's
  /// side 0 (corner 0 to corner 1) and whose normal is the triangle's. |u_t| is near 1 where the
  /// neighbourhood agrees on one cross and near 0 where it does not (no preferred direction).
  std::vector<std::complex<double>> cross;
  /// Per node and side k: the side's direction in the same frame, raised to the fourth power
  /// (e^{4iα}); all 0 for a triangle without a frame. What side_alignment reads the cross against.
  std::vector<std::array<std::complex<double>, 3>> side_power;
  std::uint32_t iterations = 0;  ///< conjugate-gradient iterations taken
  double residual = 0;           ///< the final relative residual
};

/// The cross field of the triangles of `mesh` over its pairable graph (see the top of this file).
/// A degenerate triangle (no normal, or a side of zero length) has no frame: its cross is 0 and no
/// edge couples it. O(n) per iteration, on a sparse Hermitian positive definite system solved by
/// Eigen's conjugate gradient with a diagonal preconditioner (λ > 0 keeps it well conditioned:
/// a few dozen iterations). Throws std::invalid_argument for alignment not positive and finite.
CrossField cross_field(const PairableGraph& graph, const PolygonMesh& mesh,
                       const CrossFieldOptions& options = {});

/// Per node t and side k (index 3t + k): how closely side k runs along t's cross, in degrees:
/// 45 − δ for δ in [0, 45] the angle between the side and the cross's nearest direction, weighted
/// by the cross's confidence min(1, |u_t|). 45 where the side runs along the field (a quad side),
/// 0 where it runs diagonally across it (a quad's diagonal) or where the field says nothing. O(n).
std::pmr::vector<double> side_alignment(const CrossField& field);

/// For each edge of `graph`, the flow cost of removing it to pair its two triangles: its alignment
/// (side_alignment) in each of them, summed, in [0, 90]. Removing a quad's diagonal costs nothing;
/// removing a side that an edge loop runs along costs up to 90. O(m).
std::pmr::vector<double> pairable_edge_flow(const PairableGraph& graph,
                                            std::span<const double> alignment);

}  // namespace petersen
