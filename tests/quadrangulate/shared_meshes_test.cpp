// Every shared mesh, the invalid ones included, through the front door with every algorithm:
// each answer checked by result_check, and --all-quad's output too.

#include "shared_meshes.hpp"

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>

#include "peers.hpp"
#include "petersen/dualize/dual.hpp"
#include "petersen/dualize/pairable_graph.hpp"
#include "petersen/dualize/quad_quality.hpp"
#include "petersen/io/read_mesh.hpp"
#include "petersen/matching/min_cost_matching.hpp"
#include "petersen/quadrangulate/quadrangulate.hpp"
#include "result_check.hpp"

namespace petersen {
namespace {

// The independent check sorts the edges and runs LEMON (and Boost below 20k nodes), so the full
// set of algorithms runs on the meshes below this size; the larger ones run ps and lrs, and
// frink (O(n^2), the reductions' test oracle) the meshes below kFrinkUpTo.
// PETERSEN_FULL_SHARED=1 runs every algorithm on every mesh (frink still by size): minutes.
#ifdef PETERSEN_SANITIZE
constexpr std::uint32_t kAllAlgorithmsUpTo = 15000;
constexpr std::uint32_t kMaxTriangles = 100000;
constexpr std::uint32_t kFrinkUpTo = 2000;
#else
constexpr std::uint32_t kAllAlgorithmsUpTo = 100000;
constexpr std::uint32_t kMaxTriangles = 600000;
constexpr std::uint32_t kFrinkUpTo = 10000;  // cheburashka, fandisk, homer: 5-9 s of frink each
#endif

// The mesh's positions and faces alone: what the front door pairs when a file has no attributes.
PolygonMesh read_bare_mesh(const std::string& path) {
  PolygonMesh mesh = read_mesh(path);
  mesh.attributes = {};
  return mesh;
}

bool full_run() {
  const char* full = std::getenv("PETERSEN_FULL_SHARED");
  return full != nullptr && std::string(full) == "1";
}

std::vector<std::string> all_shared_files() {
  std::vector<std::string> files;
  for (const auto& mesh : testing::shared_meshes_up_to(full_run() ? 0xFFFFFFFFu : kMaxTriangles)) {
    files.push_back(mesh.file);
  }
  for (const char* invalid : {"invalid/beetle.obj.gz", "invalid/cow.obj.gz",
                              "invalid/stanford-bunny.obj.gz", "invalid/teapot.obj.gz"}) {
    files.push_back(invalid);
  }
  return files;
}

// One test per mesh, so that CTest's shards of this binary (tests/CMakeLists.txt) run them on
// every core: as one test, the meshes were 88 of the Release tests' 105 s on two cores.
class EveryAlgorithm : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryAlgorithm, ConvertsTheMesh) {
  const auto dir = testing::shared_mesh_dir();
  if (!dir) GTEST_SKIP() << "no ../shared/meshes (set PETERSEN_SHARED_MESHES)";
  const std::string& file = GetParam();
  const PolygonMesh mesh = read_bare_mesh(*dir + "/" + file);
  const bool small = full_run() || mesh.face_count() <= kAllAlgorithmsUpTo;
  const PairingAlgorithm algorithms[] = {
      Algorithm::automatic, Algorithm::sg,    Algorithm::ps, Algorithm::ds,
      Algorithm::gw,        Algorithm::frink, kLrs};
  for (const PairingAlgorithm& algorithm : algorithms) {
    const bool lrs = std::holds_alternative<Lrs>(algorithm);
    if (!small && algorithm != PairingAlgorithm{Algorithm::automatic} && !lrs) continue;
    if (algorithm == PairingAlgorithm{Algorithm::frink} && mesh.face_count() > kFrinkUpTo) continue;
    SCOPED_TRACE(std::string(to_string(algorithm)));
    const QuadResult result =
        quadrangulate(mesh, {.objective = Objective::pairs, .algorithm = algorithm});
    EXPECT_TRUE(result.stats.maximum_certified);
    EXPECT_EQ(testing::check_quad_result(mesh, result, false, lrs), "");
  }
  try {
    const QuadOptions options{.all_quad = true};
    const QuadResult all_quad = quadrangulate(mesh, options);
    EXPECT_EQ(testing::check_quad_result(mesh, all_quad, options), "");
  } catch (const MeshError& e) {
    ADD_FAILURE() << file << ": " << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(SharedMeshes, EveryAlgorithm, ::testing::ValuesIn(all_shared_files()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return testing::test_name_of_file(info.param);
                         });

// Fandisk's creases kept with a 30-degree fold threshold, a maximum pairing of
// what is left, and all quads on request.
TEST(SharedMeshes, FandiskKeepsItsCreases) {
  const auto dir = testing::shared_mesh_dir();
  if (!dir) GTEST_SKIP() << "no ../shared/meshes (set PETERSEN_SHARED_MESHES)";
  const PolygonMesh mesh = read_bare_mesh(*dir + "/fandisk.obj.gz");
  const CutOptions cuts{.sharp_angle_degrees = 30.0};
  for (bool all_quad : {false, true}) {
    const QuadOptions options{.all_quad = all_quad, .cuts = cuts};
    const QuadResult result = quadrangulate(mesh, options);
    EXPECT_GT(result.stats.cuts.by_cause[int(CutCause::sharp)], 0u);
    EXPECT_EQ(testing::check_quad_result(mesh, result, options), "");
  }
}

// --objective quality on the closed meshes: all quads, both certificates, and the optimum LEMON's
// weighted perfect matching finds on the dual build_dual makes, with the pairable graph's costs
// (on a closed triangle mesh the pairable graph is the dual, edge for edge).
TEST(SharedMeshes, QualityObjectiveMatchesLemonsOptimum) {
  const auto dir = testing::shared_mesh_dir();
  if (!dir) GTEST_SKIP() << "no ../shared/meshes (set PETERSEN_SHARED_MESHES)";
  for (const auto& shared : testing::shared_meshes_up_to(kAllAlgorithmsUpTo / 5)) {
    SCOPED_TRACE(shared.file);
    const PolygonMesh mesh = read_bare_mesh(*dir + "/" + shared.file);
    const QuadResult result = quadrangulate(mesh, {.objective = Objective::quality});
    EXPECT_TRUE(result.stats.optimality_certified);
    EXPECT_EQ(result.stats.triangles_left, 0u);
    EXPECT_EQ(testing::check_quad_result(mesh, result, false, false), "");
    const Dual dual = build_dual(mesh);
    const PairableGraph pairable = build_pairable_graph(mesh);
    ASSERT_EQ(pairable.edge_count(), dual.graph.edge_count());
    const std::pmr::vector<Cost> costs = scale_costs(pairable_edge_quality(pairable, mesh));
    std::vector<std::array<std::uint32_t, 2>> edges(dual.graph.edge_count());
    for (EdgeId e = 0; e < edges.size(); ++e) edges[e] = dual.graph.endpoints(e);
    const auto lemon = testing::lemon_min_cost_perfect(dual.graph.node_count(), edges, costs);
    ASSERT_TRUE(lemon.has_value());
    EXPECT_EQ(std::llround(result.stats.objective_total * kDefaultCostScale), *lemon);
  }
}

// Attribute cuts on a real textured mesh: spot's 288 UV seams cut, every triangle still paired,
// every quad corner with its triangle corner's texture coordinates, and all quads on request.
TEST(SharedMeshes, SpotKeepsItsTextureCoordinates) {
  const auto dir = testing::shared_mesh_dir();
  if (!dir) GTEST_SKIP() << "no ../shared/meshes (set PETERSEN_SHARED_MESHES)";
  const PolygonMesh mesh = read_mesh(*dir + "/spot.obj.gz");
  ASSERT_FALSE(mesh.attributes.corner_texcoord.empty());
  for (bool all_quad : {false, true}) {
    const QuadOptions options{.all_quad = all_quad};
    const QuadResult result = quadrangulate(mesh, options);
    EXPECT_GT(result.stats.cuts.by_cause[int(CutCause::uv_seam)], 0u);
    EXPECT_EQ(testing::check_quad_result(mesh, result, options), "");
    EXPECT_EQ(testing::check_attributes_kept(mesh, result), "");
  }
}

}  // namespace
}  // namespace petersen
