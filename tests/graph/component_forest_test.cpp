// The project's disjoint sets (ComponentForest) and its stopwatch.

#include "petersen/graph/component_forest.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <chrono>
#include <thread>
#include <utility>
#include <vector>

#include "petersen/graph/stopwatch.hpp"

namespace petersen {
namespace {

TEST(ComponentForest, CountsTheComponentsOfAnEdgeList) {
  // Two triangles and a lone node; the roots are each set's smallest node.
  const std::vector<NodeId> ends = {0, 1, 1, 2, 2, 0, 4, 3, 5, 4};
  ComponentForest forest(7, ends);
  EXPECT_EQ(forest.root_count(), 3u);
  EXPECT_EQ(forest.find(2), 0u);
  EXPECT_EQ(forest.find(5), 3u);
  EXPECT_EQ(forest.find(6), 6u);
  EXPECT_FALSE(forest.unite(5, 3));
  EXPECT_TRUE(forest.unite(6, 1));
  EXPECT_EQ(forest.find(6), 0u);
  EXPECT_EQ(forest.root_count(), 2u);
}

RC_GTEST_PROP(ComponentForest, AgreesWithALabelWalk, ()) {
  // Against relabelling: each union renames one whole set, its smallest node the label.
  const auto n = *rc::gen::inRange<std::uint32_t>(1, 60);
  const auto pairs = *rc::gen::container<std::vector<std::pair<std::uint32_t, std::uint32_t>>>(
      rc::gen::pair(rc::gen::inRange<std::uint32_t>(0, n), rc::gen::inRange<std::uint32_t>(0, n)));
  ComponentForest forest(n);
  std::vector<std::uint32_t> label(n);
  for (std::uint32_t v = 0; v < n; ++v) label[v] = v;
  std::uint32_t sets = n;
  for (const auto& [a, b] : pairs) {
    const std::uint32_t la = label[a], lb = label[b];
    RC_ASSERT(forest.unite(a, b) == (la != lb));
    if (la == lb) continue;
    --sets;
    const std::uint32_t keep = std::min(la, lb), gone = std::max(la, lb);
    for (std::uint32_t& l : label)
      if (l == gone) l = keep;
  }
  RC_ASSERT(forest.root_count() == sets);
  for (std::uint32_t v = 0; v < n; ++v) RC_ASSERT(forest.find(v) == label[v]);
}

TEST(Stopwatch, LapsAddUpToTheTimeSinceStart) {
  Stopwatch clock;
  std::this_thread::sleep_for(std::chrono::milliseconds(2));
  const double first = clock.lap();
  std::this_thread::sleep_for(std::chrono::milliseconds(2));
  const double second = clock.lap();
  const double total = clock.seconds();
  EXPECT_GE(first, 0.002);
  EXPECT_GE(second, 0.002);
  EXPECT_GE(total, first + second);
}

}  // namespace
}  // namespace petersen
