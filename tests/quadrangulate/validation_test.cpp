// The front door's checks of its input: coordinates that are not finite and options out of their
// range are refused before any work, naming the vertex or the option and its value; an empty
// mesh gives an empty, certified result.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "petersen/generators/polygon_generators.hpp"
#include "petersen/quadrangulate/quadrangulate.hpp"
#include "result_check.hpp"

namespace petersen {
namespace {

using testing::check_quad_result;

// The message of what `run` throws as E; fails the test when it throws nothing or something else.
template <class E, class Run>
std::string message_of(Run run) {
  try {
    run();
  } catch (const E& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "threw another exception: " << e.what();
    return {};
  }
  ADD_FAILURE() << "threw nothing";
  return {};
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(Validation, NonFiniteCoordinatesNameTheVertex) {
  for (double bad : {kNaN, kInf, -kInf}) {
    SCOPED_TRACE(bad);
    PolygonMesh mesh = open_grid(3, 3);
    mesh.positions[5][1] = bad;
    const std::string copied = message_of<MeshError>([&] { quadrangulate(mesh); });
    EXPECT_TRUE(contains(copied, "vertex 5")) << copied;
    EXPECT_TRUE(contains(copied, "not finite")) << copied;
    const std::string moved = message_of<MeshError>([&] { quadrangulate(PolygonMesh(mesh)); });
    EXPECT_EQ(moved, copied);
  }
}

// A vertex no face uses is still carried to the output, where no writer could spell it.
TEST(Validation, NonFiniteUnreferencedVertexIsRefusedToo) {
  PolygonMesh mesh = open_grid(2, 2);
  mesh.positions.push_back({0, kNaN, 0});
  const std::string message = message_of<MeshError>([&] { quadrangulate(mesh); });
  EXPECT_TRUE(contains(message, "vertex " + std::to_string(mesh.positions.size() - 1))) << message;
}

TEST(Validation, MaxCornerDeviationOutOfRangeNamesOptionAndValue) {
  const PolygonMesh mesh = open_grid(3, 3);
  for (double bad : {-1.0, -1e-9, 270.5, 1e300, kNaN, kInf, -kInf}) {
    SCOPED_TRACE(bad);
    const std::string message = message_of<std::invalid_argument>(
        [&] { quadrangulate(mesh, {.max_corner_deviation = bad}); });
    EXPECT_TRUE(contains(message, "max_corner_deviation")) << message;
    EXPECT_TRUE(contains(message, "[0, 270]")) << message;
  }
  EXPECT_TRUE(contains(message_of<std::invalid_argument>(
                           [&] { quadrangulate(mesh, {.max_corner_deviation = -2.5}); }),
                       "not -2.5"));
  // The ends of the range are thresholds like any other: 270 allows every pair.
  for (double good : {0.0, 45.0, 270.0}) {
    SCOPED_TRACE(good);
    const QuadResult result = quadrangulate(mesh, {.max_corner_deviation = good});
    EXPECT_EQ(check_quad_result(mesh, result, false, false, {}, {}, good), "");
    EXPECT_TRUE(result.stats.maximum_certified);
  }
  const QuadResult all = quadrangulate(mesh, {.max_corner_deviation = 270.0});
  EXPECT_EQ(all.stats.pairs, quadrangulate(mesh).stats.pairs);
}

TEST(Validation, SharpAngleOutOfRangeNamesOptionAndValue) {
  const PolygonMesh mesh = open_grid(3, 3);
  for (double bad : {-0.5, 180.5, kNaN, kInf}) {
    SCOPED_TRACE(bad);
    CutOptions cuts;
    cuts.sharp_angle_degrees = bad;
    const std::string message =
        message_of<std::invalid_argument>([&] { quadrangulate(mesh, {.cuts = cuts}); });
    EXPECT_TRUE(contains(message, "sharp_angle_degrees")) << message;
    EXPECT_TRUE(contains(message, "[0, 180]")) << message;
  }
  for (double good : {0.0, 180.0}) {
    CutOptions cuts;
    cuts.sharp_angle_degrees = good;
    const QuadResult result = quadrangulate(mesh, {.cuts = cuts});
    EXPECT_EQ(check_quad_result(mesh, result, false, false, cuts), "");
  }
}

TEST(Validation, ThreadsAboveTheLimitAreRefused) {
  const PolygonMesh mesh = open_grid(3, 3);
  const std::string message =
      message_of<std::invalid_argument>([&] { quadrangulate(mesh, {.threads = 1025}); });
  EXPECT_TRUE(contains(message, "threads")) << message;
  EXPECT_TRUE(contains(message, "1025")) << message;
  const QuadResult result = quadrangulate(mesh, {.threads = 1024});
  EXPECT_EQ(check_quad_result(mesh, result, false, false), "");
}

// The front door's algorithms: perfect_matching's, by their names, and lrs; like every one but
// auto, lrs pairs by the pairs objective only.
TEST(Validation, PairingAlgorithmsByNameAndTheObjectiveTheyNeed) {
  const PairingAlgorithm algorithms[] = {
      Algorithm::automatic, Algorithm::sg,    Algorithm::ps, Algorithm::ds,
      Algorithm::gw,        Algorithm::frink, kLrs};
  for (const PairingAlgorithm& a : algorithms) {
    EXPECT_EQ(parse_pairing_algorithm(to_string(a)), a) << to_string(a);
  }
  EXPECT_EQ(to_string(kLrs), "lrs");
  EXPECT_EQ(to_string(PairingAlgorithm{Algorithm::automatic}), "auto");
  EXPECT_EQ(QuadOptions{}.algorithm, PairingAlgorithm{Algorithm::automatic});
  for (const char* other : {"lemon", "blossom", "LRS"}) {
    EXPECT_FALSE(parse_pairing_algorithm(other).has_value()) << other;
  }
  const PolygonMesh mesh = open_grid(3, 3);
  const std::string message = message_of<std::invalid_argument>(
      [&] { quadrangulate(mesh, {.objective = Objective::quality, .algorithm = kLrs}); });
  EXPECT_TRUE(contains(message, "algorithm lrs")) << message;
}

// The library's choice for a mesh with nothing to pair: an empty result, no error (the CLI and
// the Python module refuse such input themselves).
TEST(Validation, EmptyMeshGivesAnEmptyResult) {
  PolygonMesh no_vertices;
  PolygonMesh vertices_only;
  vertices_only.positions.push_back({0, 0, 0});
  for (const PolygonMesh* mesh : {&no_vertices, &vertices_only}) {
    const QuadResult result = quadrangulate(*mesh);
    EXPECT_EQ(result.mesh.face_count(), 0u);
    EXPECT_EQ(result.mesh.positions.size(), mesh->positions.size());
    EXPECT_EQ(result.stats.pairs, 0u);
    EXPECT_EQ(result.stats.triangles_left, 0u);
    EXPECT_TRUE(result.tutte_set.empty());
    EXPECT_TRUE(result.stats.maximum_certified);
    EXPECT_EQ(check_quad_result(*mesh, result, false, false), "");
  }
  // Bad values are refused even where there is nothing to pair.
  EXPECT_THROW(quadrangulate(no_vertices, {.max_corner_deviation = kNaN}), std::invalid_argument);
  vertices_only.positions[0][2] = kInf;
  EXPECT_THROW(quadrangulate(vertices_only), MeshError);
}

}  // namespace
}  // namespace petersen
