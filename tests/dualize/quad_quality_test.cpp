// The quad measure (worst-corner deviation from 90°) on hand-made quads, and the per-edge costs
// of the pairable graph against the quads a matching of the dual makes.

#include "petersen/dualize/quad_quality.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <random>

#include "petersen/dualize/dual.hpp"
#include "petersen/dualize/pairable_graph.hpp"
#include "petersen/generators/surface_generators.hpp"
#include "petersen/matching/perfect_matching.hpp"
#include "quad_mesh_check.hpp"

namespace petersen {
namespace {

using P = std::array<double, 3>;

// The measure as its definition reads, every corner's angle by atan2: the fast path (one atan2,
// for the corner the diamond angle finds worst) must give the same cost.
double reference_deviation(const P& a, const P& b, const P& c, const P& d) {
  auto sub = [](const P& p, const P& q) { return P{p[0] - q[0], p[1] - q[1], p[2] - q[2]}; };
  auto dot = [](const P& p, const P& q) { return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]; };
  auto cross = [](const P& p, const P& q) {
    return P{p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
  };
  const P corners[4] = {a, b, c, d};
  P n = cross(sub(c, a), sub(d, b));
  const double length = std::sqrt(dot(n, n));
  for (double& x : n) x /= length;
  double worst = 0;
  for (int k = 0; k < 4; ++k) {
    auto project = [&](P p) {
      const double along = dot(p, n);
      return P{p[0] - along * n[0], p[1] - along * n[1], p[2] - along * n[2]};
    };
    const P u = project(sub(corners[(k + 1) % 4], corners[k]));
    const P v = project(sub(corners[(k + 3) % 4], corners[k]));
    double theta = std::atan2(dot(n, cross(u, v)), dot(u, v)) * 180.0 / std::numbers::pi;
    if (theta < 0) theta += 360.0;
    if (theta >= 360.0) theta = 0;
    worst = std::max(worst, std::abs(90.0 - theta));
  }
  return worst;
}

TEST(QuadQuality, AgreesWithEveryCornersAngle) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  int nonconvex = 0;
  for (int i = 0; i < 200000; ++i) {
    P q[4];
    // Near-planar quads around a unit square, and free ones in space.
    const double spread = i % 2 ? 0.6 : 2.0;
    const P square[4] = {P{0, 0, 0}, P{1, 0, 0}, P{1, 1, 0}, P{0, 1, 0}};
    for (int k = 0; k < 4; ++k)
      for (int d = 0; d < 3; ++d) q[k][d] = square[k][d] + spread * coordinate(rng);
    const double fast = quad_corner_deviation(q[0], q[1], q[2], q[3]);
    if (fast == kDegenerateQuadCost) continue;
    nonconvex += fast > 90;
    ASSERT_NEAR(fast, reference_deviation(q[0], q[1], q[2], q[3]), 1e-9) << "quad " << i;
  }
  EXPECT_GT(nonconvex, 1000);  // the reflex corners were reached too
}

TEST(QuadQuality, SquareAndRectangleCostNothing) {
  EXPECT_NEAR(quad_corner_deviation({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}), 0, 1e-12);
  EXPECT_NEAR(quad_corner_deviation({0, 0, 0}, {3, 0, 0}, {3, 1, 0}, {0, 1, 0}), 0, 1e-12);
  // Either orientation: the normal follows the corner order.
  EXPECT_NEAR(quad_corner_deviation({0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}), 0, 1e-12);
  // A rectangle tilted in space.
  EXPECT_NEAR(quad_corner_deviation({0, 0, 0}, {1, 1, 0}, {1, 1, 2}, {0, 0, 2}), 0, 1e-12);
}

TEST(QuadQuality, RhombusCostsItsAngleDefect) {
  // Interior angles 60° and 120°: worst deviation 30°.
  const double h = std::sqrt(3.0) / 2;
  EXPECT_NEAR(quad_corner_deviation({0, 0, 0}, {1, 0, 0}, {1.5, h, 0}, {0.5, h, 0}), 30, 1e-9);
}

TEST(QuadQuality, NonConvexQuadCostsMoreThanNinety) {
  // A dart: the corner at (1, 0.3) is reflex (its interior angle is above 180°).
  const double cost = quad_corner_deviation({0, 0, 0}, {2, 0, 0}, {1, 0.3, 0}, {1, 2, 0});
  EXPECT_GT(cost, 90);
  EXPECT_LE(cost, 270);
}

TEST(QuadQuality, DegenerateQuadsCostTheMaximumWithoutNaN) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  // Repeated corner: zero-length edge.
  EXPECT_EQ(quad_corner_deviation({0, 0, 0}, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}), kDegenerateQuadCost);
  // All corners on a line: the diagonals are parallel, no normal.
  EXPECT_EQ(quad_corner_deviation({0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}), kDegenerateQuadCost);
  EXPECT_EQ(quad_corner_deviation({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {nan, 1, 0}),
            kDegenerateQuadCost);
  EXPECT_EQ(quad_corner_deviation({0, 0, 0}, {1, 0, 0}, {1, inf, 0}, {0, 1, 0}),
            kDegenerateQuadCost);
  // Huge but finite coordinates: the cross product overflows.
  EXPECT_EQ(quad_corner_deviation({0, 0, 0}, {1e200, 0, 0}, {1e200, 1e200, 0}, {0, 1e200, 0}),
            kDegenerateQuadCost);
}

// On a closed triangle mesh the pairable graph is the dual, edge for edge (both number edges by
// their mesh edge), and each edge's cost is that of the quad a matching of the dual makes.
TEST(QuadQuality, PairableEdgeCostIsTheCostOfTheQuadsFromAMatchingOfTheDual) {
  const PolygonMesh mesh = random_closed_surface(2, 60, 60, 5);
  const Dual dual = build_dual(mesh);
  const PairableGraph graph = build_pairable_graph(mesh);
  ASSERT_EQ(graph.edge_count(), dual.graph.edge_count());
  for (EdgeId e = 0; e < graph.edge_count(); ++e) {
    ASSERT_EQ(graph.edge_ends[2 * e], dual.graph.endpoints(e)[0]);
    ASSERT_EQ(graph.edge_ends[2 * e + 1], dual.graph.endpoints(e)[1]);
  }
  const std::pmr::vector<double> cost = pairable_edge_quality(graph, mesh);
  const PerfectMatchingResult r = perfect_matching(dual.graph);
  const PolygonMesh quads = testing::quads_of_matching(mesh, dual.graph, r.matching);
  std::size_t q = 0;
  std::size_t checked = 0;
  for (FaceId t = 0; t < mesh.face_count(); ++t) {
    const EdgeId e = r.matching.mate_edge[t];
    if (dual.graph.endpoints(e)[0] != t) continue;
    const auto c = quads.face(static_cast<FaceId>(q++));
    const auto& p = mesh.positions;
    // Two triangles sharing two edges (a parallel dual edge) may give quad_of the other shared
    // edge's quad; such pairs are skipped.
    const auto a = mesh.face(t);
    const auto b = mesh.face(dual.graph.other_end(e, t));
    int shared = 0;
    for (VertexId x : a)
      for (VertexId y : b) shared += x == y;
    if (shared != 2) continue;
    EXPECT_DOUBLE_EQ(cost[e], quad_corner_deviation(p[c[0]], p[c[1]], p[c[2]], p[c[3]]));
    ++checked;
  }
  EXPECT_EQ(q, quads.face_count());
  EXPECT_GT(checked, quads.face_count() / 2);
}

// The pairable graph's costs are measured in blocks of 65,536 nodes on the threads: the same
// costs, bit for bit, on one thread or three, each the cost of the quad its two faces make.
TEST(QuadQuality, PairableEdgeCostsDoNotDependOnTheThreads) {
  const PolygonMesh mesh = random_closed_surface(1, 70000, 20000, 3);
  const PairableGraph graph = build_pairable_graph(mesh);
  ASSERT_GT(graph.node_count, 2u << 16);  // three blocks
  const std::pmr::vector<double> one = pairable_edge_quality(graph, mesh, 1);
  const std::pmr::vector<double> three = pairable_edge_quality(graph, mesh, 3);
  ASSERT_EQ(one.size(), graph.edge_count());
  ASSERT_EQ(three.size(), one.size());
  for (EdgeId e = 0; e < one.size(); ++e) {
    ASSERT_EQ(std::memcmp(&one[e], &three[e], sizeof(double)), 0) << "edge " << e;
  }
  // Spot checks against the quad of the edge's two faces, in the lower face's orientation.
  for (EdgeId e = 0; e < graph.edge_count(); e += 997) {
    NodeId v = graph.edge_ends[2 * std::size_t{e}], w = graph.edge_ends[2 * std::size_t{e} + 1];
    if (graph.face_of(w) < graph.face_of(v)) std::swap(v, w);
    const auto t1 = mesh.face(graph.face_of(v)), t2 = mesh.face(graph.face_of(w));
    int k = 0;
    while (graph.node_edges[3 * std::size_t{v} + k] != e) ++k;
    const VertexId a = t1[k], b = t1[(k + 1) % 3], c = t1[(k + 2) % 3];
    const VertexId d = t2[0] != a && t2[0] != b ? t2[0] : t2[1] != a && t2[1] != b ? t2[1] : t2[2];
    const auto& p = mesh.positions;
    EXPECT_EQ(one[e], quad_corner_deviation(p[a], p[d], p[b], p[c])) << "edge " << e;
  }
}

TEST(QuadQuality, ATrapezoidOf45And135DegreesCosts45InAnyPlane) {
  EXPECT_NEAR(quad_corner_deviation({0, 0, 0}, {4, 0, 0}, {3, 1, 0}, {1, 1, 0}), 45, 1e-9);
  // Rotated into the plane x = z: the same quad.
  const double r = 1 / std::sqrt(2.0);
  EXPECT_NEAR(quad_corner_deviation({0, 0, 0}, {4 * r, 0, 4 * r}, {3 * r, 1, 3 * r}, {r, 1, r}), 45,
              1e-9);
}

TEST(QuadQuality, ADartCostsItsReflexCornerMinus90) {
  // Corner c = (0.5, 0.5) is reflex: its edges (1.5, −0.5) and (−0.5, 1.5) meet at acos(−0.6),
  // so the interior angle is 360° minus that, and the cost that minus 90°.
  const double cost = quad_corner_deviation({0, 0, 0}, {2, 0, 0}, {0.5, 0.5, 0}, {0, 2, 0});
  EXPECT_NEAR(cost, 270 - std::acos(-0.6) * 180 / std::numbers::pi, 1e-9);
}

TEST(QuadQuality, FiguresAreNearestRankOverTheQuadsOnly) {
  PolygonMesh mesh;
  const double s = 1 / std::sqrt(3.0);
  for (P p :
       {P{0, 0, 0}, P{1, 0, 0}, P{1, 1, 0}, P{0, 1, 0}, P{1 + s, 1, 0}, P{s, 1, 0}, P{2, 0, 0}}) {
    mesh.positions.push_back(p);
  }
  mesh.add_face(std::vector<VertexId>{0, 1, 2, 3});  // 0°
  mesh.add_face(std::vector<VertexId>{0, 1, 4, 5});  // a parallelogram of 60° and 120°: 30°
  mesh.add_face(std::vector<VertexId>{1, 6, 2});     // a triangle: not a quad, not counted
  mesh.add_face(std::vector<VertexId>{0, 6, 2, 3});  // (0,0) (2,0) (1,1) (0,1): 90, 45, 135, 90
  const std::vector<double> costs = quad_costs(mesh);
  ASSERT_EQ(costs.size(), 3u);
  EXPECT_NEAR(costs[0], 0, 1e-9);
  EXPECT_NEAR(costs[1], 30, 1e-9);
  EXPECT_NEAR(costs[2], 45, 1e-9);
  const QualityFigures f = quality_figures(costs);
  EXPECT_EQ(f.quads, 3u);
  EXPECT_NEAR(f.median, 30, 1e-9);
  EXPECT_NEAR(f.p95, 45, 1e-9);
  EXPECT_NEAR(f.total, 75, 1e-9);
  EXPECT_EQ(f.nonconvex, 0u);
  EXPECT_EQ(quality_figures({}).quads, 0u);
  EXPECT_EQ(quality_figures({100, 10}).nonconvex, 1u);
  EXPECT_EQ(describe(f),
            "3 quads, worst corner median 30.0\xc2\xb0, p95 45.0\xc2\xb0, 0 non-convex, total "
            "75.0\xc2\xb0");
}

// The selections give the nearest-rank elements of the sorted costs, with ties and any count.
TEST(QuadQuality, FiguresBySelectionMatchTheSortedCosts) {
  std::mt19937 random(7);
  for (std::size_t count : {1, 2, 3, 19, 20, 21, 1000, 1001}) {
    std::vector<double> costs(count);
    // Few distinct values, so that ranks fall on ties.
    for (double& c : costs) c = double(std::uniform_int_distribution<int>(0, 9)(random)) * 12.5;
    std::vector<double> sorted = costs;
    std::sort(sorted.begin(), sorted.end());
    const double median = sorted[std::size_t(std::ceil(0.5 * double(count))) - 1];
    const double p95 = sorted[std::size_t(std::ceil(0.95 * double(count))) - 1];
    const QualityFigures by_copy = quality_figures(costs);
    EXPECT_EQ(by_copy.median, median) << count;
    EXPECT_EQ(by_copy.p95, p95) << count;
    std::vector<double> reordered = costs;
    const QualityFigures in_place = quality_figures_in_place(reordered);
    EXPECT_EQ(in_place.median, median) << count;
    EXPECT_EQ(in_place.p95, p95) << count;
    EXPECT_EQ(in_place.quads, count);
    EXPECT_EQ(in_place.nonconvex, by_copy.nonconvex);
    std::sort(reordered.begin(), reordered.end());
    EXPECT_EQ(reordered, sorted) << "the same costs, reordered";
  }
}

}  // namespace
}  // namespace petersen
