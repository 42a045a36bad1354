#pragma once
// A memory resource for arrays of millions of elements, made by a program and handed to the
// library through its options (`memory`): large blocks on transparent huge pages, and blocks given
// back kept for the next arrays. It belongs to the programs (the CLI, the bench, the Python
// module), not to the library: this module is not installed, no library type or options struct
// includes it, and the library allocates from whatever std::pmr::memory_resource its caller
// passes, the standard one by default, never making or finding a pool by itself.
//
// Why: a fresh array of n bytes costs n / 4 KiB page faults, and every random access a TLB miss;
// on virtual machines a fresh page is dearer still, as the host backs guest memory lazily and
// takes freed memory back: filling fresh memory runs at 0.25-1.2 GB/s against 15 GB/s for reused
// huge pages (a touch loop on such a machine, 256 MB at a time); bench/RESULTS.md has what the
// pool buys end to end. Linux only honours the advice with transparent huge pages in "always" or
// "madvise" mode; elsewhere the large blocks are plain aligned allocations and nothing is kept.

#include <cstddef>
#include <cstdint>
#include <memory_resource>
#include <mutex>
#include <vector>

#include "petersen/graph/memory.hpp"

namespace petersen {

/// Serves allocations by size:
/// - below kPooledBytes: operator new, as the default resource would;
/// - from kPooledBytes up to a huge page: with a retained limit above 0, the start of a kept range
///   of whole huge pages (a fresh one if none is kept), so that a mid-size array (a 10^5-triangle
///   mesh's dual is about 1 MiB an array) reuses pages already faulted in, where malloc would map
///   it afresh or trim it back to the kernel between calls; with a limit of 0, operator new;
/// - from a huge page up: a range of whole huge pages, kPageBytes-aligned, advised onto huge pages
///   over the array's whole huge pages and onto ordinary ones over the rest, so that a partial
///   last huge page becomes resident only as far as the array writes it (armadillo-sub2's lrs:
///   five arrays at its peak, 2.1 MiB of unwritten tails). The smallest kept range that is large
///   enough is handed out again (split if larger); when none is, the range is made of the largest
///   kept ranges, as many bytes as it takes (their pages moved into it with mremap, neither copied
///   nor faulted in again), and fresh pages for whatever they lack, so that kept memory does not
///   pile up beside the live arrays.
/// A range given back is kept while the pool keeps less than its limit, else unmapped. Kept ranges
/// are searched linearly (a handful at a time). Thread-safe (one mutex, taken only when a range is
/// kept or handed out). Its blocks must be given back before it is destroyed, which unmaps what it
/// keeps.
///
/// A process that forks with ranges kept shares them with the child, copy on write: the first
/// write to each 4 KiB page would copy it (LRS's contraction on the 4.1M-triangle D6: 7,583 such
/// copies). A child that allocates from an inherited pool calls release_retained() first (the
/// bench harness does), as fresh memory is cheaper.
class HugePagePool final : public TailReleasingResource {
 public:
  static constexpr std::size_t kPageBytes = std::size_t{2} << 20;
  static constexpr std::size_t kPooledBytes = std::size_t{64} << 10;
  static constexpr std::size_t kDefaultRetainedBytes = std::size_t{1} << 30;

  /// Keeps released ranges up to `retained_bytes` in all; 0 keeps none (large blocks are still
  /// mapped on huge pages, and given back to the kernel at once). A range is kept only while the
  /// kept ranges and the blocks handed out from kPooledBytes up stay within `footprint_bytes`
  /// too: a program under a memory limit passes it, so that what the pool keeps never adds to
  /// what its live arrays hold past the limit.
  explicit HugePagePool(std::size_t retained_bytes = kDefaultRetainedBytes,
                        std::size_t footprint_bytes = SIZE_MAX);
  HugePagePool(const HugePagePool&) = delete;
  HugePagePool& operator=(const HugePagePool&) = delete;
  ~HugePagePool() override;

  /// Returns every kept range to the kernel.
  void release_retained();
  /// Returns kept ranges to the kernel, largest first, until the pool keeps at most `keep_bytes`:
  /// for a caller that frees an array nothing will reuse. O(r log r) for r kept ranges.
  void trim_retained(std::size_t keep_bytes);
  /// The bytes kept now.
  std::size_t retained_bytes() const;
  /// The limit given at construction.
  std::size_t retained_limit() const { return limit_; }

  /// Shrinks a block of `bytes` (from this pool, alignment at most kPageBytes) to its first
  /// `keep_bytes`, giving back at once the whole huge pages past them (kept or unmapped, as any
  /// released range): for an array whose tail is dead while its head lives on. Returns the size
  /// the block must be deallocated with from now on: `keep_bytes` when pages were given back,
  /// else `bytes` (nothing is given back when either size is below a huge page). O(1).
  std::size_t shrink(void* block, std::size_t bytes, std::size_t keep_bytes) override;

 private:
  struct Range {
    char* start;
    std::size_t bytes;
  };

  void* do_allocate(std::size_t bytes, std::size_t alignment) override;
  void do_deallocate(void* block, std::size_t bytes, std::size_t alignment) override;
  bool do_is_equal(const std::pmr::memory_resource& other) const noexcept override {
    return this == &other;
  }

  // A range of `bytes` (a multiple of kPageBytes) for an array of `used` bytes, advised.
  void* acquire(std::size_t bytes, std::size_t used);
  // A range of `bytes` from the kept ones or the kernel, not yet advised.
  void* obtain(std::size_t bytes);
  // Keeps the range while under the limit, else unmaps it.
  void release(void* range, std::size_t bytes);
  void give_back(std::vector<Range>& ranges);

  const std::size_t limit_;
  mutable std::mutex mutex_;
  const std::size_t footprint_;
  std::vector<Range> ranges_;  // under mutex_
  std::size_t bytes_ = 0;      // under mutex_: kept
  std::size_t live_ = 0;       // under mutex_: handed out as ranges (acquire), not yet released
};

}  // namespace petersen
