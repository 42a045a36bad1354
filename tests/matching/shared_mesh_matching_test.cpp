// SG and PS with both augmentation variants on the duals of the shared real meshes of at most
// 100k triangles: perfect, as large as LEMON's, and paired in the paper's ranges (§4, Table 4.3).

#include <gtest/gtest.h>

#include "peers.hpp"
#include "petersen/dualize/dual.hpp"
#include "petersen/io/read_mesh.hpp"
#include "petersen/matching/perfect_matching.hpp"
#include "shared_meshes.hpp"

namespace petersen {
namespace {

TEST(SharedMeshes, SgAndPsMakePerfectMatchings) {
  const auto dir = testing::shared_mesh_dir();
  if (!dir) GTEST_SKIP() << "no shared meshes";
  for (const testing::SharedMesh& mesh : testing::shared_meshes_up_to(100'000)) {
    SCOPED_TRACE(mesh.file);
    CubicGraph g = dual_graph(read_mesh(*dir + "/" + mesh.file));
    ASSERT_EQ(g.node_count(), mesh.triangles);
    EXPECT_EQ(testing::lemon_matching_size(g.node_count(), testing::edge_list(g)),
              g.node_count() / 2);
    for (Algorithm algorithm : {Algorithm::sg, Algorithm::ps, Algorithm::automatic}) {
      for (Augment augment : {Augment::local, Augment::faithful}) {
        // Faithful SG costs O(k·n) with k ≈ 12 % of n: keep it to the small meshes.
        if (algorithm == Algorithm::sg && augment == Augment::faithful && mesh.triangles > 20'000)
          continue;
        PerfectMatchingResult r =
            perfect_matching(g, {.algorithm = algorithm, .augment = augment, .seed = 3});
        EXPECT_TRUE(verify_perfect_matching(g, r.matching).ok())
            << to_string(algorithm) << "+" << to_string(augment);
        const double paired = r.stats.paired_percent(g.node_count());
        if (algorithm == Algorithm::sg) {
          EXPECT_GT(paired, 85.0);
          EXPECT_LT(paired, 90.0);
        } else {
          EXPECT_GT(paired, 99.0);
        }
      }
    }
  }
}

}  // namespace
}  // namespace petersen
