#include "petersen/memory_pool/huge_page_pool.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <thread>

#include "petersen/graph/memory.hpp"

namespace petersen {
namespace {

constexpr std::size_t kPage = HugePagePool::kPageBytes;
constexpr std::size_t kRange = 4 * kPage;

bool all_bytes(const void* range, std::size_t bytes, unsigned char value) {
  const auto* p = static_cast<const unsigned char*>(range);
  return std::all_of(p, p + bytes, [&](unsigned char b) { return b == value; });
}

TEST(HugePagePool, KeepingNothingUnmapsAtOnce) {
  HugePagePool pool(0);
  void* range = pool.allocate(kRange);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(range) % kPage, 0u);  // whole huge pages
  std::memset(range, 0xAB, kRange);
  pool.deallocate(range, kRange);
  EXPECT_EQ(pool.retained_bytes(), 0u);
  void* fresh = pool.allocate(kRange);
  EXPECT_TRUE(all_bytes(fresh, kRange, 0));  // mapped afresh, zero-filled
  pool.deallocate(fresh, kRange);
}

TEST(HugePagePool, KeepsNoMoreThanItsLimit) {
  HugePagePool pool(kRange);
  void* a = pool.allocate(kRange);
  void* b = pool.allocate(kRange);
  pool.deallocate(a, kRange);
  pool.deallocate(b, kRange);
  EXPECT_EQ(pool.retained_bytes(), kRange);
  EXPECT_EQ(pool.retained_limit(), kRange);
}

// Under a footprint, a range is kept only while the kept ranges and the live blocks fit in it:
// with two blocks live, the first given back would take the pool past the footprint and is
// unmapped; the second, with nothing live, is kept.
TEST(HugePagePool, KeepsNothingPastItsFootprint) {
  HugePagePool pool(4 * kRange, kRange + kRange / 2);
  void* a = pool.allocate(kRange);
  void* b = pool.allocate(kRange);
  pool.deallocate(a, kRange);
  EXPECT_EQ(pool.retained_bytes(), 0u);
  pool.deallocate(b, kRange);
  EXPECT_EQ(pool.retained_bytes(), kRange);
  void* again = pool.allocate(kRange);
  EXPECT_EQ(again, b);  // the kept range handed out again
  pool.deallocate(again, kRange);
}

TEST(HugePagePool, MidSizeBlocksAreKeptRanges) {
  constexpr std::size_t kBlock = std::size_t{1} << 20;
  HugePagePool pool;
  void* pooled = pool.allocate(kBlock);
  std::memset(pooled, 0xAB, kBlock);
  pool.deallocate(pooled, kBlock);
  EXPECT_EQ(pool.retained_bytes(), kPage);  // kept whole
  void* again = pool.allocate(kBlock);
  EXPECT_EQ(again, pooled);  // the kept range handed out again, its pages already in
  EXPECT_TRUE(all_bytes(again, kBlock, 0xAB));
  pool.deallocate(again, kBlock);
  // A pool that keeps nothing takes mid-size blocks from the heap.
  HugePagePool heap(0);
  void* block = heap.allocate(kBlock);
  std::memset(block, 0xCD, kBlock);
  heap.deallocate(block, kBlock);
  EXPECT_EQ(heap.retained_bytes(), 0u);
}

TEST(HugePagePool, SmallBlocksComeFromTheHeap) {
  HugePagePool pool;
  void* small = pool.allocate(100, 8);
  std::memset(small, 1, 100);
  pool.deallocate(small, 100, 8);
  EXPECT_EQ(pool.retained_bytes(), 0u);
}

TEST(HugePagePool, ReleasedRangeIsHandedOutAgain) {
  HugePagePool pool;
  void* first = pool.allocate(kRange);
  std::memset(first, 0xAB, kRange);
  pool.deallocate(first, kRange);
  void* again = pool.allocate(kRange);
  EXPECT_EQ(again, first);
  EXPECT_TRUE(all_bytes(again, kRange, 0xAB));  // reused as it was, not mapped afresh
  pool.deallocate(again, kRange);
}

TEST(HugePagePool, SmallerRequestsSplitAKeptRange) {
  HugePagePool pool;
  auto* range = static_cast<char*>(pool.allocate(kRange));
  pool.deallocate(range, kRange);
  void* front = pool.allocate(kPage);
  void* rest = pool.allocate(kRange - kPage);
  EXPECT_EQ(front, range);
  EXPECT_EQ(rest, range + kPage);
  pool.deallocate(front, kPage);
  pool.deallocate(rest, kRange - kPage);
}

// A request no kept range fits alone takes the kept ranges' pages, moved, not copied or zeroed,
// and fresh zeroed pages for the rest; the pool keeps nothing of them.
TEST(HugePagePool, ALargerRequestIsMadeOfTheKeptRanges) {
  HugePagePool pool;
  void* a = pool.allocate(kRange);
  void* b = pool.allocate(2 * kRange);
  std::memset(a, 0xAB, kRange);
  std::memset(b, 0xCD, 2 * kRange);
  pool.deallocate(a, kRange);
  pool.deallocate(b, 2 * kRange);
  auto* whole = static_cast<unsigned char*>(pool.allocate(4 * kRange));
  EXPECT_EQ(pool.retained_bytes(), 0u);
  EXPECT_TRUE(all_bytes(whole, 2 * kRange, 0xCD));           // the largest first
  EXPECT_TRUE(all_bytes(whole + 2 * kRange, kRange, 0xAB));  // then the next
  EXPECT_TRUE(all_bytes(whole + 3 * kRange, kRange, 0));     // fresh
  std::memset(whole, 0x5A, 4 * kRange);                      // all of it writable
  pool.deallocate(whole, 4 * kRange);
  EXPECT_EQ(pool.retained_bytes(), 4 * kRange);
  // Part of a kept range: its head is taken, its tail stays kept where it was.
  void* c = pool.allocate(kRange);
  void* d = pool.allocate(4 * kRange);
  EXPECT_EQ(pool.retained_bytes(), 0u);
  EXPECT_TRUE(all_bytes(d, 3 * kRange, 0x5A));
  EXPECT_TRUE(all_bytes(static_cast<char*>(d) + 3 * kRange, kRange, 0));
  pool.deallocate(c, kRange);
  pool.deallocate(d, 4 * kRange);
}

TEST(HugePagePool, ReleaseRetainedReturnsKeptRangesToTheKernel) {
  HugePagePool pool;
  void* range = pool.allocate(kRange);
  std::memset(range, 0xAB, kRange);
  pool.deallocate(range, kRange);
  pool.release_retained();
  EXPECT_EQ(pool.retained_bytes(), 0u);
  void* fresh = pool.allocate(kRange);
  EXPECT_TRUE(all_bytes(fresh, kRange, 0));  // a new anonymous mapping, zero-filled
  pool.deallocate(fresh, kRange);
}

TEST(HugePagePool, TrimGivesBackTheLargestKeptRangesFirst) {
  HugePagePool pool;
  auto* small = static_cast<char*>(pool.allocate(kPage));
  void* large = pool.allocate(kRange);
  std::memset(small, 0xAB, kPage);
  pool.deallocate(small, kPage);
  pool.deallocate(large, kRange);
  EXPECT_EQ(pool.retained_bytes(), kRange + kPage);
  pool.trim_retained(kRange);  // over by the small range: the large one goes
  EXPECT_EQ(pool.retained_bytes(), kPage);
  void* again = pool.allocate(kPage);
  EXPECT_EQ(again, small);  // the small one is still kept, as it was
  EXPECT_TRUE(all_bytes(again, kPage, 0xAB));
  pool.deallocate(again, kPage);
  pool.trim_retained(kPage);  // within the limit: nothing goes
  EXPECT_EQ(pool.retained_bytes(), kPage);
  pool.trim_retained(0);
  EXPECT_EQ(pool.retained_bytes(), 0u);
}

// A shrunk buffer keeps its head, gives back the whole pages past it at once (kept by the pool
// here), and releases only what it kept when freed; below a page nothing is given back.
TEST(HugePagePool, ShrinkGivesBackTheWholePagesPastTheHead) {
  HugePagePool pool;
  const std::size_t ints = 3 * kPage / sizeof(std::uint32_t);
  {
    RawArray<std::uint32_t> array = make_raw_array<std::uint32_t>(ints, &pool);
    for (std::size_t i = 0; i < ints; ++i) array[i] = static_cast<std::uint32_t>(i);
    const std::size_t head = ints / 2;  // a page and a half
    shrink_raw_array(array, head);
    EXPECT_EQ(array.get_deleter().size, head);
    EXPECT_EQ(pool.retained_bytes(), kPage);  // the third page
    for (std::size_t i = 0; i < head; ++i) ASSERT_EQ(array[i], i);
    shrink_raw_array(array, 16);  // below a page: kept whole
    EXPECT_EQ(array.get_deleter().size, head);
    EXPECT_EQ(pool.retained_bytes(), kPage);
  }
  EXPECT_EQ(pool.retained_bytes(), 3 * kPage);
  // On any other resource a buffer is kept whole.
  RawArray<std::uint32_t> other = make_raw_array<std::uint32_t>(ints);
  shrink_raw_array(other, 16);
  EXPECT_EQ(other.get_deleter().size, ints);
}

// A forked child that drops what its parent's pool keeps gets fresh ranges; the parent keeps its.
TEST(HugePagePool, ForkedChildDropsItsParentsRanges) {
  HugePagePool pool;
  void* range = pool.allocate(kRange);
  std::memset(range, 0xAB, kRange);
  pool.deallocate(range, kRange);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    // Reusing the parent's range would copy every page it writes; a fresh one is zero-filled.
    pool.release_retained();
    _exit(all_bytes(pool.allocate(kRange), kRange, 0) ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  void* again = pool.allocate(kRange);
  EXPECT_EQ(again, range);  // the parent keeps it
  pool.deallocate(again, kRange);
}

TEST(HugePagePool, VectorsOnThePoolKeepTheirElementsAcrossGrowth) {
  HugePagePool pool;
  {
    std::pmr::vector<std::uint32_t> values(&pool);
    for (std::uint32_t i = 0; i < 3'000'000; ++i) values.push_back(i);  // 12 MB, several ranges
    for (std::uint32_t i = 0; i < values.size(); i += 4099) ASSERT_EQ(values[i], i);
    EXPECT_EQ(values.back(), 2'999'999u);
  }
  EXPECT_GT(pool.retained_bytes(), 0u);
}

// Two pools are two objects: what one keeps the other never hands out, on any thread.
TEST(HugePagePool, PoolsShareNothing) {
  HugePagePool a, b;
  std::thread ta([&] {
    for (int i = 0; i < 20; ++i) a.deallocate(a.allocate(kRange), kRange);
  });
  std::thread tb([&] {
    for (int i = 0; i < 20; ++i) b.deallocate(b.allocate(2 * kRange), 2 * kRange);
  });
  ta.join();
  tb.join();
  EXPECT_EQ(a.retained_bytes(), kRange);
  EXPECT_EQ(b.retained_bytes(), 2 * kRange);
  EXPECT_FALSE(a.is_equal(b));
}

}  // namespace
}  // namespace petersen
