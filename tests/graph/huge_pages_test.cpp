#include "petersen/graph/huge_pages.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>

namespace petersen {
namespace {

constexpr std::size_t kRange = 4 * huge_pages::kPageBytes;

bool all_bytes(const void* range, std::size_t bytes, unsigned char value) {
  const auto* p = static_cast<const unsigned char*>(range);
  return std::all_of(p, p + bytes, [&](unsigned char b) { return b == value; });
}

// The pool is off unless a program turns it on; these tests turn it on and off again.
struct PoolOn {
  PoolOn() { huge_pages::enable_pool(); }
  ~PoolOn() { huge_pages::disable_pool(); }
};

TEST(HugePages, WithThePoolOffNothingIsKept) {
  void* range = huge_pages::acquire(kRange, kRange);
  std::memset(range, 0xAB, kRange);
  huge_pages::release(range, kRange);
  EXPECT_EQ(huge_pages::retained_bytes(), 0u);
  void* fresh = huge_pages::acquire(kRange, kRange);
  EXPECT_TRUE(all_bytes(fresh, kRange, 0));  // mapped afresh, zero-filled
  huge_pages::release(fresh, kRange);
}

TEST(HugePages, DisablingThePoolReturnsWhatItKept) {
  huge_pages::enable_pool();
  huge_pages::release(huge_pages::acquire(kRange, kRange), kRange);
  EXPECT_EQ(huge_pages::retained_bytes(), kRange);
  huge_pages::disable_pool();
  EXPECT_EQ(huge_pages::retained_bytes(), 0u);
  huge_pages::release(huge_pages::acquire(kRange, kRange), kRange);
  EXPECT_EQ(huge_pages::retained_bytes(), 0u);
}

TEST(HugePages, ThePoolKeepsNoMoreThanItsLimit) {
  huge_pages::enable_pool(kRange);
  void* a = huge_pages::acquire(kRange, kRange);
  void* b = huge_pages::acquire(kRange, kRange);
  huge_pages::release(a, kRange);
  huge_pages::release(b, kRange);
  EXPECT_EQ(huge_pages::retained_bytes(), kRange);
  huge_pages::disable_pool();
}

TEST(HugePages, MidSizeBlocksComeFromThePoolOnlyWhenItIsOn) {
  constexpr std::size_t kBlock = std::size_t{1} << 20;
  void* heap_block = huge_pages::acquire_block(kBlock);  // pool off: a heap block
  std::memset(heap_block, 0xCD, kBlock);
  {
    const PoolOn pool;
    void* pooled = huge_pages::acquire_block(kBlock);
    std::memset(pooled, 0xAB, kBlock);
    huge_pages::release_block(pooled, kBlock);
    EXPECT_EQ(huge_pages::retained_bytes(), huge_pages::kPageBytes);  // kept whole
    void* again = huge_pages::acquire_block(kBlock);
    EXPECT_EQ(again, pooled);  // the kept range handed out again, its pages already in
    EXPECT_TRUE(all_bytes(again, kBlock, 0xAB));
    // Taken from the heap before the pool was on, given back to the heap: the pool keeps no more.
    huge_pages::release_block(heap_block, kBlock);
    EXPECT_EQ(huge_pages::retained_bytes(), 0u);
    heap_block = again;
  }
  // Taken from the pool, given back with the pool off: unmapped, and nothing kept.
  huge_pages::release_block(heap_block, kBlock);
  EXPECT_EQ(huge_pages::retained_bytes(), 0u);
}

TEST(HugePages, ReleasedRangeIsHandedOutAgain) {
  const PoolOn pool;
  void* first = huge_pages::acquire(kRange, kRange);
  std::memset(first, 0xAB, kRange);
  huge_pages::release(first, kRange);
  void* again = huge_pages::acquire(kRange, kRange);
  EXPECT_EQ(again, first);
  EXPECT_TRUE(all_bytes(again, kRange, 0xAB));  // reused as it was, not mapped afresh
  huge_pages::release(again, kRange);
  huge_pages::release_retained();
}

TEST(HugePages, SmallerRequestsSplitAKeptRange) {
  const PoolOn pool;
  auto* range = static_cast<char*>(huge_pages::acquire(kRange, kRange));
  huge_pages::release(range, kRange);
  void* front = huge_pages::acquire(huge_pages::kPageBytes, huge_pages::kPageBytes);
  void* rest =
      huge_pages::acquire(kRange - huge_pages::kPageBytes, kRange - huge_pages::kPageBytes);
  EXPECT_EQ(front, range);
  EXPECT_EQ(rest, range + huge_pages::kPageBytes);
  huge_pages::release(front, huge_pages::kPageBytes);
  huge_pages::release(rest, kRange - huge_pages::kPageBytes);
  huge_pages::release_retained();
}

// A request no kept range fits alone takes the kept ranges' pages, moved, not copied or zeroed,
// and fresh zeroed pages for the rest; the pool keeps nothing of them.
TEST(HugePages, ALargerRequestIsMadeOfTheKeptRanges) {
  const PoolOn pool;
  void* a = huge_pages::acquire(kRange, kRange);
  void* b = huge_pages::acquire(2 * kRange, 2 * kRange);
  std::memset(a, 0xAB, kRange);
  std::memset(b, 0xCD, 2 * kRange);
  huge_pages::release(a, kRange);
  huge_pages::release(b, 2 * kRange);
  auto* whole = static_cast<unsigned char*>(huge_pages::acquire(4 * kRange, 4 * kRange));
  EXPECT_EQ(huge_pages::retained_bytes(), 0u);
  EXPECT_TRUE(all_bytes(whole, 2 * kRange, 0xCD));           // the largest first
  EXPECT_TRUE(all_bytes(whole + 2 * kRange, kRange, 0xAB));  // then the next
  EXPECT_TRUE(all_bytes(whole + 3 * kRange, kRange, 0));     // fresh
  std::memset(whole, 0x5A, 4 * kRange);                      // all of it writable
  huge_pages::release(whole, 4 * kRange);
  EXPECT_EQ(huge_pages::retained_bytes(), 4 * kRange);
  // Part of a kept range: its head is taken, its tail stays kept where it was.
  void* c = huge_pages::acquire(kRange, kRange);
  void* d = huge_pages::acquire(4 * kRange, 4 * kRange);
  EXPECT_EQ(huge_pages::retained_bytes(), 0u);
  EXPECT_TRUE(all_bytes(d, 3 * kRange, 0x5A));
  EXPECT_TRUE(all_bytes(static_cast<char*>(d) + 3 * kRange, kRange, 0));
  huge_pages::release(c, kRange);
  huge_pages::release(d, 4 * kRange);
  huge_pages::release_retained();
}

TEST(HugePages, ReleaseRetainedReturnsKeptRangesToTheKernel) {
  const PoolOn pool;
  void* range = huge_pages::acquire(kRange, kRange);
  std::memset(range, 0xAB, kRange);
  huge_pages::release(range, kRange);
  huge_pages::release_retained();
  void* fresh = huge_pages::acquire(kRange, kRange);
  EXPECT_TRUE(all_bytes(fresh, kRange, 0));  // a new anonymous mapping, zero-filled
  huge_pages::release(fresh, kRange);
  huge_pages::release_retained();
}

TEST(HugePages, TrimGivesBackTheLargestKeptRangesFirst) {
  const PoolOn pool;
  auto* small =
      static_cast<char*>(huge_pages::acquire(huge_pages::kPageBytes, huge_pages::kPageBytes));
  void* large = huge_pages::acquire(kRange, kRange);
  std::memset(small, 0xAB, huge_pages::kPageBytes);
  huge_pages::release(small, huge_pages::kPageBytes);
  huge_pages::release(large, kRange);
  EXPECT_EQ(huge_pages::retained_bytes(), kRange + huge_pages::kPageBytes);
  huge_pages::trim_retained(kRange);  // over by the small range: the large one goes
  EXPECT_EQ(huge_pages::retained_bytes(), huge_pages::kPageBytes);
  void* again = huge_pages::acquire(huge_pages::kPageBytes, huge_pages::kPageBytes);
  EXPECT_EQ(again, small);  // the small one is still kept, as it was
  EXPECT_TRUE(all_bytes(again, huge_pages::kPageBytes, 0xAB));
  huge_pages::release(again, huge_pages::kPageBytes);
  huge_pages::trim_retained(huge_pages::kPageBytes);  // within the limit: nothing goes
  EXPECT_EQ(huge_pages::retained_bytes(), huge_pages::kPageBytes);
  huge_pages::trim_retained(0);
  EXPECT_EQ(huge_pages::retained_bytes(), 0u);
}

// A shrunk array keeps its head, gives back the whole pages past it at once (kept by the pool
// here), and releases only what it kept when freed; below a page nothing is given back.
TEST(HugePages, ShrinkGivesBackTheWholePagesPastTheHead) {
  const PoolOn pool;
  const std::size_t ints = 3 * huge_pages::kPageBytes / sizeof(std::uint32_t);
  {
    HugeArray<std::uint32_t> array = make_huge_array<std::uint32_t>(ints);
    for (std::size_t i = 0; i < ints; ++i) array[i] = static_cast<std::uint32_t>(i);
    const std::size_t head = ints / 2;  // a page and a half
    shrink_huge_array(array, head);
    EXPECT_EQ(array.get_deleter().size, head);
    EXPECT_EQ(huge_pages::retained_bytes(), huge_pages::kPageBytes);  // the third page
    for (std::size_t i = 0; i < head; ++i) ASSERT_EQ(array[i], i);
    shrink_huge_array(array, 16);  // below a page: kept whole
    EXPECT_EQ(array.get_deleter().size, head);
    EXPECT_EQ(huge_pages::retained_bytes(), huge_pages::kPageBytes);
  }
  EXPECT_EQ(huge_pages::retained_bytes(), 3 * huge_pages::kPageBytes);
  huge_pages::release_retained();
}

TEST(HugePages, ForkedChildDoesNotReuseItsParentsRanges) {
  const PoolOn pool;
  void* range = huge_pages::acquire(kRange, kRange);
  std::memset(range, 0xAB, kRange);
  huge_pages::release(range, kRange);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    // Reusing the parent's range would copy every page it writes; a fresh one is zero-filled.
    _exit(all_bytes(huge_pages::acquire(kRange, kRange), kRange, 0) ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  EXPECT_EQ(huge_pages::acquire(kRange, kRange), range);  // the parent keeps it
  huge_pages::release(range, kRange);
  huge_pages::release_retained();
}

TEST(HugePages, HugeVectorKeepsItsElementsAcrossGrowth) {
  HugeVector<std::uint32_t> values;
  for (std::uint32_t i = 0; i < 3'000'000; ++i) values.push_back(i);  // 12 MB, several ranges
  for (std::uint32_t i = 0; i < values.size(); i += 4099) ASSERT_EQ(values[i], i);
  EXPECT_EQ(values.back(), 2'999'999u);
}

}  // namespace
}  // namespace petersen
