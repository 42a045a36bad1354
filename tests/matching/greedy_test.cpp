// SG and PS (paper §3.1) alone: valid matchings, maximal, seeded.

#include "greedy/greedy.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "petersen/testing/arbitrary.hpp"

namespace petersen {
namespace {

// No edge joins two unpaired nodes: both greedy pairings run until no free edge is left.
bool is_maximal(const CubicGraph& g, const Matching& m) {
  for (EdgeId e = 0; e < g.edge_count(); ++e) {
    auto [a, b] = g.endpoints(e);
    if (!m.is_matched(a) && !m.is_matched(b)) return false;
  }
  return true;
}

RC_GTEST_PROP(SimpleGreedy, ReturnsAValidMaximalMatching, ()) {
  CubicGraph g = *rc::gen::arbitrary<CubicGraph>();
  Matching m(g.node_count());
  simple_greedy(g, m, *rc::gen::arbitrary<std::uint64_t>());
  RC_ASSERT(verify_matching(g, m).ok());
  RC_ASSERT(is_maximal(g, m));
}

RC_GTEST_PROP(PuliSegal, ReturnsAValidMaximalMatching, ()) {
  CubicGraph g = *rc::gen::arbitrary<CubicGraph>();
  Matching m(g.node_count());
  puli_segal(g, m, *rc::gen::arbitrary<std::uint64_t>());
  RC_ASSERT(verify_matching(g, m).ok());
  RC_ASSERT(is_maximal(g, m));
}

RC_GTEST_PROP(Greedy, SameSeedSamePairing, ()) {
  CubicGraph g = *rc::gen::arbitrary<CubicGraph>();
  const auto seed = *rc::gen::arbitrary<std::uint64_t>();
  for (auto pairing : {&simple_greedy, &puli_segal}) {
    Matching first(g.node_count()), second(g.node_count());
    pairing(g, first, seed);
    pairing(g, second, seed);
    RC_ASSERT(first.mate_edge == second.mate_edge);
  }
}

TEST(PuliSegal, PairsFarMoreThanSimpleGreedyOnASurface) {
  // The paper's §4 finding: SG pairs about 87 % of the triangles, PS more than 99 %.
  CubicGraph g = dual_graph(voxel_plate({.holes_x = 3, .holes_y = 3, .subdivision = 6}));
  Matching sg(g.node_count()), ps(g.node_count());
  simple_greedy(g, sg, 7);
  puli_segal(g, ps, 7);
  const double n = g.node_count();
  EXPECT_GT(sg.unmatched_count() / n, 0.08);
  EXPECT_LT(sg.unmatched_count() / n, 0.18);
  EXPECT_LT(ps.unmatched_count() / n, 0.01);
}

}  // namespace
}  // namespace petersen
