// The threshold mode (QuadOptions::max_corner_deviation): no pair's quad over the threshold, the
// pairing still the maximum of what the threshold allows (result_check's own graph and LEMON),
// the cheapest of those with Objective::quality.

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "petersen/dualize/quad_quality.hpp"
#include "petersen/quadrangulate/quadrangulate.hpp"
#include "petersen/testing/arbitrary.hpp"
#include "result_check.hpp"

namespace petersen {
namespace {

using testing::check_quad_result;

// A square (corners 0-3, cut along 0-2) beside a rhombus of 60° and 120° (corners 1, 4, 5, 2,
// cut along its long diagonal 1-5): quads of cost 0 and 30, and across edge 1-2 the pairs of
// one triangle of each.
PolygonMesh square_and_rhombus() {
  const double h = std::sqrt(3.0) / 2;
  PolygonMesh mesh;
  for (std::array<double, 3> p : std::initializer_list<std::array<double, 3>>{
           {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {1 + h, 0.5, 0}, {1 + h, 1.5, 0}}) {
    mesh.positions.push_back(p);
  }
  for (std::vector<VertexId> f :
       std::initializer_list<std::vector<VertexId>>{{0, 1, 2}, {0, 2, 3}, {1, 4, 5}, {1, 5, 2}}) {
    mesh.add_face(f);
  }
  return mesh;
}

TEST(Threshold, CutsPairsOverItAndLeavesTheirTriangles) {
  const PolygonMesh mesh = square_and_rhombus();
  for (Objective objective : {Objective::pairs, Objective::quality}) {
    SCOPED_TRACE(std::string(to_string(objective)));
    auto run = [&](double degrees) {
      const QuadResult result =
          quadrangulate(mesh, {.objective = objective, .max_corner_deviation = degrees});
      EXPECT_EQ(check_quad_result(mesh, result, false, false, {}, {}, degrees), "");
      EXPECT_TRUE(result.stats.maximum_certified);
      EXPECT_EQ(result.stats.optimality_certified, objective == Objective::quality);
      return result;
    };
    const QuadResult loose = run(45);
    EXPECT_EQ(loose.stats.pairs, 2u);
    EXPECT_NEAR(loose.stats.quality_p95, 30, 1e-9);
    const QuadResult tight = run(20);
    EXPECT_EQ(tight.stats.pairs, 1u);
    EXPECT_EQ(tight.stats.triangles_left, 2u);
    EXPECT_NEAR(tight.stats.quality_median, 0, 1e-9);
    // The rhombus's diagonal, and the edge 1-2 between the shapes (its quad is far worse).
    EXPECT_EQ(tight.stats.cuts.by_cause[int(CutCause::shape)], 2u);
    // The least threshold, 0, allows exact right angles only: the square's quad.
    const QuadResult square_only = run(0);
    EXPECT_EQ(square_only.stats.pairs, 1u);
    EXPECT_EQ(square_only.stats.cuts.by_cause[int(CutCause::shape)], 2u);
    EXPECT_NEAR(square_only.stats.quality_p95, 0, 1e-12);
  }
  // Below the measure's range no quad could pass: refused, like NaN (validation_test.cpp).
  EXPECT_THROW(quadrangulate(mesh, {.max_corner_deviation = -1}), std::invalid_argument);
  EXPECT_THROW(quadrangulate(mesh, {.max_corner_deviation = std::nan("")}), std::invalid_argument);
  // The threshold's cuts are the caller's own: never crossed.
  EXPECT_THROW(quadrangulate(mesh, {.max_corner_deviation = 20, .cross = {CutCause::shape}}),
               std::invalid_argument);
}

// The rhombus's second triangle reversed: its edges to the square and to the other half are
// pairable but inconsistent; those the threshold cuts are counted as cuts only.
TEST(Threshold, InconsistentEdgesCountOnlyThePairableOnes) {
  PolygonMesh mesh = square_and_rhombus();
  std::swap(mesh.corners[9], mesh.corners[11]);  // (1, 5, 2) -> (2, 5, 1)
  for (auto [degrees, inconsistent] : {std::pair{45.0, 1u}, {20.0, 0u}, {200.0, 2u}}) {
    SCOPED_TRACE(degrees);
    const QuadResult result = quadrangulate(mesh, {.max_corner_deviation = degrees});
    EXPECT_EQ(result.stats.inconsistent_edges, inconsistent);
    EXPECT_EQ(check_quad_result(mesh, result, false, false, {}, {}, degrees), "");
  }
}

TEST(Threshold, AllQuadStillSplitsTheTrianglesLeft) {
  const PolygonMesh mesh = square_and_rhombus();
  const QuadResult result = quadrangulate(
      mesh, {.objective = Objective::quality, .all_quad = true, .max_corner_deviation = 20});
  EXPECT_EQ(check_quad_result(mesh, result, true, false, {}, {}, 20.0), "");
  EXPECT_EQ(result.stats.pairs, 1u);
  EXPECT_GT(result.stats.split_quads, 0u);
  for (FaceId f = 0; f < result.mesh.face_count(); ++f) EXPECT_EQ(result.mesh.arity(f), 4u);
}

// Every kind of mesh, every algorithm (lrs gives way to ps), either objective, a random threshold
// between whole degrees (where two correct cost computations cannot round apart).
RC_GTEST_PROP(Threshold, MaximumOfWhatIsAllowedAndNothingOver, ()) {
  const PolygonMesh mesh = *testing::mixed_meshes();
  const double degrees = *rc::gen::inRange(0, 180) + 0.5;
  const Objective objective =
      *rc::gen::element(Objective::quads, Objective::pairs, Objective::quality);
  const PairingAlgorithm algorithm = objective == Objective::pairs
                                         ? *rc::gen::elementOf(std::vector<PairingAlgorithm>{
                                               Algorithm::sg, Algorithm::ps, Algorithm::gw, kLrs})
                                         : PairingAlgorithm{Algorithm::automatic};
  const QuadOptions options{.objective = objective,
                            .algorithm = algorithm,
                            .seed = *rc::gen::arbitrary<std::uint64_t>(),
                            .max_corner_deviation = degrees};
  const QuadResult result = quadrangulate(mesh, options);
  RC_CLASSIFY(result.stats.cuts.by_cause[int(CutCause::shape)] > 0, "shape cuts");
  RC_ASSERT(result.stats.maximum_certified || objective == Objective::quads);
  RC_ASSERT(result.stats.optimality_certified == (objective != Objective::pairs));
  RC_ASSERT(result.stats.flipped_edges == 0u);
  const std::string problem = check_quad_result(mesh, result, options);
  RC_LOG() << problem;
  RC_ASSERT(problem.empty());
}

}  // namespace
}  // namespace petersen
