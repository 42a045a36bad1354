// The weighted solver's monotone queue against a sorted reference: every pop returns the
// smallest key left, whatever the spread of keys across its digits.

#include "weighted/radix_queue.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cstdint>
#include <map>
#include <vector>

namespace petersen::weighted_detail {
namespace {

// Random interleavings of pushes (keys at or above the last key taken, at gaps from 0 to 2^k
// for a drawn k, so that keys land on every digit) and pops; each pop is checked against a
// multimap of what was pushed: its key is the smallest left and its item was pushed with it.
RC_GTEST_PROP(RadixQueue, PopsTheSmallestKeyLeft, ()) {
  const auto steps = *rc::gen::inRange(1, 3000);
  RadixQueue<std::uint32_t> queue;
  std::multimap<std::uint64_t, std::uint32_t> reference;
  std::uint64_t last = *rc::gen::inRange<std::uint64_t>(0, std::uint64_t{1} << 40);
  for (int step = 0; step < steps; ++step) {
    if (reference.empty() || *rc::gen::inRange(0, 5) < 3) {
      const int bits = *rc::gen::inRange(0, 48);
      const std::uint64_t gap = *rc::gen::inRange<std::uint64_t>(0, std::uint64_t{1} << bits);
      const auto item = static_cast<std::uint32_t>(step);
      queue.push(last + gap, item);
      reference.emplace(last + gap, item);
    } else {
      std::uint32_t item = 0;
      const std::uint64_t key = queue.pop(item);
      RC_ASSERT(key == reference.begin()->first);
      auto [first, end] = reference.equal_range(key);
      bool found = false;
      for (auto at = first; at != end; ++at) {
        if (at->second == item) {
          reference.erase(at);
          found = true;
          break;
        }
      }
      RC_ASSERT(found);
      last = key;
    }
    RC_ASSERT(queue.empty() == reference.empty());
  }
}

TEST(RadixQueue, EqualKeysAllComeOutBeforeALargerOne) {
  RadixQueue<int> queue;
  queue.push(5, 1);
  queue.push(5, 2);
  queue.push(7, 3);
  int item = 0;
  EXPECT_EQ(queue.pop(item), 5u);
  const int first = item;
  EXPECT_EQ(queue.pop(item), 5u);
  EXPECT_NE(item, first);
  EXPECT_EQ(queue.pop(item), 7u);
  EXPECT_EQ(item, 3);
  EXPECT_TRUE(queue.empty());
}

// Keys differing from the last one in the top bits land on the top digit, which covers fewer
// bits than the others when the digit width does not divide 64.
TEST(RadixQueue, KeysUpToTheTopBit) {
  RadixQueue<int> queue;
  constexpr std::uint64_t top = std::uint64_t{1} << 63;
  queue.push(top + 7, 3);
  queue.push(~std::uint64_t{0}, 4);
  queue.push(top - 1, 2);
  queue.push(1, 1);
  int item = 0;
  EXPECT_EQ(queue.pop(item), 1u);
  EXPECT_EQ(item, 1);
  EXPECT_EQ(queue.pop(item), top - 1);
  EXPECT_EQ(item, 2);
  EXPECT_EQ(queue.pop(item), top + 7);
  EXPECT_EQ(item, 3);
  EXPECT_EQ(queue.pop(item), ~std::uint64_t{0});
  EXPECT_EQ(item, 4);
  EXPECT_TRUE(queue.empty());
}

// Buckets hold their items in blocks of 64: thousands of items on a few keys fill many blocks
// per bucket, and every item still comes out once, in key order.
RC_GTEST_PROP(RadixQueue, CrowdedBucketsGiveBackEveryItemInKeyOrder, ()) {
  const auto count = *rc::gen::inRange(1, 5000);
  const auto spread = *rc::gen::inRange<std::uint64_t>(1, 300);
  RadixQueue<std::uint32_t> queue;
  std::multimap<std::uint64_t, std::uint32_t> reference;
  for (int i = 0; i < count; ++i) {
    const std::uint64_t key = *rc::gen::inRange<std::uint64_t>(0, spread);
    queue.push(key, static_cast<std::uint32_t>(i));
    reference.emplace(key, static_cast<std::uint32_t>(i));
  }
  std::vector<char> seen(static_cast<std::size_t>(count), 0);
  std::uint64_t last = 0;
  while (!queue.empty()) {
    std::uint32_t item = 0;
    const std::uint64_t key = queue.pop(item);
    RC_ASSERT(key >= last);
    RC_ASSERT(key == reference.begin()->first);
    RC_ASSERT(item < seen.size());
    RC_ASSERT(seen[item] == 0);
    seen[item] = 1;
    reference.erase(reference.begin());
    last = key;
  }
  RC_ASSERT(reference.empty());
}

}  // namespace
}  // namespace petersen::weighted_detail
