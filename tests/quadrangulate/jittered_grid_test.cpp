// The acceptance test for the quality objective: a grid of near-square quads with jittered
// vertices, each cut along a random diagonal, is paired back into (almost) the same quads by
// Objective::quality; the pairs objective is measured beside it for comparison.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <set>

#include "petersen/generators/polygon_generators.hpp"
#include "petersen/quadrangulate/quadrangulate.hpp"
#include "result_check.hpp"
#include "shuffled_faces.hpp"

namespace petersen {
namespace {

// The fraction of the grid's squares that come back as an output quad on the same four vertices.
double recovered(const PolygonMesh& grid, const JitteredGrid& spec, const QuadResult& result) {
  std::set<std::array<VertexId, 4>> quads;
  for (FaceId o = 0; o < result.mesh.face_count(); ++o) {
    const auto c = result.mesh.face(o);
    if (c.size() != 4) continue;
    std::array<VertexId, 4> q{c[0], c[1], c[2], c[3]};
    std::sort(q.begin(), q.end());
    quads.insert(q);
  }
  std::size_t found = 0;
  const std::uint32_t columns = spec.torus ? spec.nx : spec.nx + 1;
  const std::uint32_t rows = spec.torus ? spec.ny : spec.ny + 1;
  auto vertex = [&](std::uint32_t x, std::uint32_t y) { return y % rows * columns + x % columns; };
  for (std::uint32_t y = 0; y < spec.ny; ++y) {
    for (std::uint32_t x = 0; x < spec.nx; ++x) {
      std::array<VertexId, 4> q{vertex(x, y), vertex(x + 1, y), vertex(x + 1, y + 1),
                                vertex(x, y + 1)};
      std::sort(q.begin(), q.end());
      found += quads.count(q);
    }
  }
  EXPECT_EQ(result.mesh.positions.size(), grid.positions.size());
  return double(found) / (double(spec.nx) * spec.ny);
}

// The open grid turns out forced: from its corners in, a perfect pairing has no choice, and ps
// gives back every quad too (100 % on these seeds). On the torus every triangle has three
// partners and ps gives back 8-10 %, the minimum-cost pairing all of them.
TEST(JitteredGrid, QualityGivesBackAtLeast99PercentOfTheQuads) {
  for (bool torus : {false, true}) {
    for (std::uint64_t seed : {1, 2, 3}) {
      const JitteredGrid spec{
          .nx = torus ? 180u : 60u, .ny = 60, .jitter = 0.1, .torus = torus, .seed = seed};
      SCOPED_TRACE(::testing::Message() << (torus ? "torus" : "open") << " seed " << seed);
      const PolygonMesh grid = testing::shuffled_faces(jittered_grid(spec), seed);
      const QuadResult best = quadrangulate(grid, {.objective = Objective::quality});
      EXPECT_TRUE(best.stats.optimality_certified);
      EXPECT_EQ(petersen::testing::check_quad_result(grid, best, false, false), "");
      const QuadResult ps = quadrangulate(
          grid, {.objective = Objective::pairs, .algorithm = Algorithm::ps, .seed = seed});
      EXPECT_EQ(petersen::testing::check_quad_result(grid, ps, false, false), "");
      const double by_quality = recovered(grid, spec, best), by_ps = recovered(grid, spec, ps);
      std::printf("%s seed %llu: quality gives back %.2f %% of the quads, ps %.2f %%\n",
                  torus ? "torus" : "open grid", static_cast<unsigned long long>(seed),
                  100 * by_quality, 100 * by_ps);
      EXPECT_GE(by_quality, 0.99);
      EXPECT_GE(by_quality, by_ps);
      if (torus) {
        EXPECT_LT(by_ps, 0.9);
      }
    }
  }
}

}  // namespace
}  // namespace petersen
