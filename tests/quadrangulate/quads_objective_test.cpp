// The quads objective (the default) against a brute force: on small meshes of every class, no
// matching of any size has a lower total of quad costs plus the price of the triangles left. The
// brute force finds the pairable pairs and their costs on its own (edges of exactly two triangles
// with four distinct vertices, quad_of's corners, quad_corner_deviation), prices each triangle from
// them by the rule triangle_prices.hpp states, and enumerates every matching.

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <vector>

#include "petersen/dualize/quad_of.hpp"
#include "petersen/dualize/quad_quality.hpp"
#include "petersen/generators/polygon_generators.hpp"
#include "petersen/matching/min_cost_matching.hpp"
#include "petersen/quadrangulate/quadrangulate.hpp"
#include "petersen/quadrangulate/triangle_prices.hpp"
#include "petersen/testing/arbitrary.hpp"
#include "petersen/testing/mesh_classes.hpp"
#include "result_check.hpp"

namespace petersen {
namespace {

struct Pair {
  FaceId a, b;
  Cost cost;
};

// The pairs two triangles of `mesh` could make, with their scaled costs.
std::vector<Pair> pairable_pairs(const PolygonMesh& mesh) {
  std::map<std::pair<VertexId, VertexId>, std::vector<FaceId>> faces_of_edge;
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    const auto c = mesh.face(f);
    for (std::size_t k = 0; k < c.size(); ++k) {
      const VertexId u = c[k], v = c[(k + 1) % c.size()];
      faces_of_edge[{std::min(u, v), std::max(u, v)}].push_back(f);
    }
  }
  std::vector<Pair> pairs;
  for (const auto& [edge, faces] : faces_of_edge) {
    if (faces.size() != 2 || faces[0] == faces[1]) continue;
    const auto t1 = mesh.face(faces[0]), t2 = mesh.face(faces[1]);
    if (t1.size() != 3 || t2.size() != 3) continue;
    std::set<VertexId> corners(t1.begin(), t1.end());
    corners.insert(t2.begin(), t2.end());
    if (corners.size() != 4 || std::set<VertexId>(t1.begin(), t1.end()).size() != 3 ||
        std::set<VertexId>(t2.begin(), t2.end()).size() != 3) {
      continue;
    }
    const FaceId lower = std::min(faces[0], faces[1]), upper = std::max(faces[0], faces[1]);
    const auto q = quad_of(mesh.face(lower), mesh.face(upper));
    const auto& p = mesh.positions;
    const double degrees = quad_corner_deviation(p[q[0]], p[q[1]], p[q[2]], p[q[3]]);
    pairs.push_back({lower, upper, std::llround(degrees * kDefaultCostScale)});
  }
  return pairs;
}

// What leaving each triangle (by its index among the triangles) costs, from its partners alone:
// `price`, or kOwnTrianglePriceShare of it where every partner u has a pair of at most
// kOwnTriangleNeighbourShare of it and would pay at least kOwnTriangleRegretShare of it over u's
// own cheapest pair.
std::vector<Cost> prices_of(const std::vector<std::vector<std::pair<int, Cost>>>& partners,
                            Cost price) {
  std::vector<Cost> prices(partners.size(), price);
  for (std::size_t t = 0; t < partners.size(); ++t) {
    if (partners[t].empty()) continue;
    bool regrets = true;
    for (const auto& [u, cost] : partners[t]) {
      Cost cheapest = cost;
      for (const auto& [w, other] : partners[u]) cheapest = std::min(cheapest, other);
      regrets =
          regrets &&
          static_cast<double>(cost - cheapest) >=
              kOwnTriangleRegretShare * static_cast<double>(price) &&
          static_cast<double>(cheapest) <= kOwnTriangleNeighbourShare * static_cast<double>(price);
    }
    if (regrets) prices[t] = std::llround(kOwnTrianglePriceShare * static_cast<double>(price));
  }
  return prices;
}

// The least total over every matching of `pairs`, each triangle left costing its price
// (prices_of): a dynamic program over the set of triangles already decided (the lowest undecided
// one is left or paired with an undecided neighbour), 2^t states at most.
Cost brute_force_optimum(const PolygonMesh& mesh, const std::vector<Pair>& pairs, Cost price) {
  std::vector<int> index_of(mesh.face_count(), -1);
  int triangles = 0;
  for (FaceId f = 0; f < mesh.face_count(); ++f)
    if (mesh.arity(f) == 3) index_of[f] = triangles++;
  std::vector<std::vector<std::pair<int, Cost>>> partners(triangles);
  for (const Pair& pair : pairs) {
    partners[index_of[pair.a]].push_back({index_of[pair.b], pair.cost});
    partners[index_of[pair.b]].push_back({index_of[pair.a], pair.cost});
  }
  const std::vector<Cost> prices = prices_of(partners, price);
  const std::uint32_t all = (1u << triangles) - 1;
  std::map<std::uint32_t, Cost> memo;
  std::function<Cost(std::uint32_t)> best = [&](std::uint32_t decided) -> Cost {
    if (decided == all) return 0;
    if (const auto it = memo.find(decided); it != memo.end()) return it->second;
    const int t = std::countr_one(decided);
    Cost least = prices[t] + best(decided | (1u << t));
    for (const auto& [u, cost] : partners[t]) {
      if (decided & (1u << u)) continue;
      least = std::min(least, cost + best(decided | (1u << t) | (1u << u)));
    }
    return memo[decided] = least;
  };
  return best(0);
}

RC_GTEST_PROP(QuadsObjective, NoMatchingOfAnySizeCostsLess, ()) {
  const auto mesh_class = *rc::gen::elementOf(
      std::vector<testing::MeshClass>(testing::kMeshClasses.begin(), testing::kMeshClasses.end()));
  PolygonMesh mesh = *testing::meshes_of_class(mesh_class, 16);
  mesh.attributes = {};  // the pairs the brute force finds are the structure's alone
  std::uint32_t triangles = 0;
  for (FaceId f = 0; f < mesh.face_count(); ++f) triangles += mesh.arity(f) == 3;
  RC_PRE(triangles <= 22u);  // the brute force's states fit in a 32-bit set
  const double triangle_cost = *rc::gen::element(10.0, 45.0, kDefaultTriangleCost, 200.0);
  const QuadOptions options{.triangle_cost = triangle_cost};
  const QuadResult result = quadrangulate(mesh, options);
  RC_ASSERT(result.stats.optimality_certified);
  RC_ASSERT(testing::check_quad_result(mesh, result, options) == "");
  const Cost optimum = brute_force_optimum(mesh, pairable_pairs(mesh),
                                           std::llround(triangle_cost * kDefaultCostScale));
  RC_ASSERT(std::llround(result.stats.objective_total * kDefaultCostScale) == optimum);
  RC_CLASSIFY(result.stats.triangles_left > 0, "triangles left");
}

// A lattice of near-square quads cut along random diagonals: the default gives every square back.
TEST(QuadsObjective, GivesBackTheSquaresOfATriangulatedGrid) {
  for (bool torus : {false, true}) {
    const PolygonMesh mesh = jittered_grid({.nx = 48, .ny = 16, .torus = torus, .seed = 4});
    const QuadResult result = quadrangulate(mesh);
    ASSERT_TRUE(result.stats.optimality_certified);
    EXPECT_EQ(result.stats.triangles_left, 0u);
    for (FaceId o = 0; o < result.mesh.face_count(); ++o) {
      const auto [f, g] = result.sources[o];
      EXPECT_EQ(f / 2, g / 2) << "output face " << o << " pairs triangles " << f << " and " << g;
    }
  }
}

// A triangle whose every quad is bad stays when its price is low, and is paired when it is high.
TEST(QuadsObjective, TheTrianglePriceDecidesWhatStays) {
  // Two triangles folded onto each other (a quad of cost 270, degenerate): cheaper to leave both
  // at any price under 135.
  PolygonMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, 0.2, 0}};
  mesh.add_face(std::array<VertexId, 3>{0, 1, 2});
  mesh.add_face(std::array<VertexId, 3>{1, 0, 3});
  const QuadResult low = quadrangulate(mesh, {.triangle_cost = 10});
  EXPECT_EQ(low.stats.pairs, 0u);
  EXPECT_EQ(low.stats.triangles_left, 2u);
  EXPECT_FALSE(low.stats.maximum_certified);
  const QuadResult high = quadrangulate(mesh, {.triangle_cost = 1000});
  EXPECT_EQ(high.stats.pairs, 1u);
  EXPECT_TRUE(high.stats.maximum_certified);
  EXPECT_THROW(quadrangulate(mesh, {.triangle_cost = -1}), std::invalid_argument);
  EXPECT_THROW(quadrangulate(mesh, {.objective = Objective::quads, .algorithm = Algorithm::ps}),
               std::invalid_argument);
}

}  // namespace
}  // namespace petersen
