#pragma once
// Large arrays on transparent huge pages, for graphs and meshes of millions of elements: a fresh
// array of n bytes costs n / 4 KiB page faults otherwise, and every random access a TLB miss.
// Linux only honours the advice with transparent huge pages in "always" or "madvise" mode;
// elsewhere these are plain allocations.

#include <cstddef>
#include <memory>
#include <new>
#include <vector>

namespace petersen {

namespace huge_pages {

inline constexpr std::size_t kPageBytes = std::size_t{2} << 20;
inline constexpr std::size_t kRetainedBytes = std::size_t{1} << 30;

/// `bytes` (a multiple of kPageBytes) of kPageBytes-aligned memory for an array of `used` bytes,
/// its contents unspecified, advised onto huge pages over its whole huge pages and ordinary ones
/// over the rest, so that a partial last huge page becomes resident only as far as the array
/// writes it, not 2 MiB at its first touch (armadillo-sub2's lrs: five arrays at its peak, 2.1 MiB
/// of unwritten tails). With the pool off (the default) it is mapped fresh from the kernel. With
/// the pool on, the smallest kept range that is large enough is handed out again (split if
/// larger); when none is, the range is made of the largest kept ranges, as many bytes as it takes
/// (their pages moved into it with mremap, neither copied nor faulted in again), and fresh pages
/// for whatever they lack, so that kept memory does not pile up beside the live arrays. Throws
/// std::bad_alloc.
void* acquire(std::size_t bytes, std::size_t used);

/// Gives back a range from acquire(): unmapped at once with the pool off; with it on, kept for
/// the next acquire() while the pool holds less than its limit (the rest goes back to the kernel).
void release(void* range, std::size_t bytes);

/// A block of `bytes` (below kPageBytes) for an array of that size, aligned to 64 bytes: with the
/// pool on, the start of a kept range (a fresh one if none is kept), so that a mid-size array
/// reuses pages already faulted in; with it off, a heap block (operator new), as for any other
/// allocation. Either way release_block() gives it back the way it was taken, even when the pool
/// was switched in between. Throws std::bad_alloc.
void* acquire_block(std::size_t bytes);
void release_block(void* block, std::size_t bytes);
/// Turns the pool on for this process: released ranges, up to `retained_bytes` in all, are kept
/// for reuse, because on virtual machines a fresh page is expensive: here the host backs guest
/// memory lazily and takes freed memory back, so filling fresh memory runs at 0.25-1.2 GB/s
/// against 15 GB/s for reused huge pages (a touch loop on such a machine, 256 MB at a time);
/// bench/RESULTS.md has what the pool buys end to end. The first call installs a fork handler
/// (pthread_atfork): a forked child drops the ranges its parent kept, as writing them would copy
/// every page. Off by default: a program that never calls this gets plain mappings, keeps no
/// memory and has no handler installed. The CLI and the bench call it first thing in main().
/// (malloc keeps freed memory in its heap for the same reason, but maps blocks above 32 MiB
/// afresh every time and hands reused blocks out on whatever pages they had.)
void enable_pool(std::size_t retained_bytes = kRetainedBytes);

/// enable_pool() unless the environment variable PETERSEN_HUGE_PAGE_POOL is "off": what the CLI
/// and the bench call, so that the same binaries measure what the pool buys.
void enable_pool_unless_switched_off();

/// Turns the pool off and returns every kept range to the kernel (the fork handler stays, and
/// does nothing while the pool is empty).
void disable_pool();

/// Returns every kept range to the kernel; the pool stays on if it was.
void release_retained();

/// Returns kept ranges to the kernel, largest first, until the pool keeps at most `keep_bytes`;
/// the pool stays on if it was. For a caller that frees an array nothing will reuse: with the
/// retained_bytes() from before freeing it, the pool gives back about that much and keeps what
/// the next arrays can take again. O(r log r) for r kept ranges.
void trim_retained(std::size_t keep_bytes);

/// The bytes the pool keeps now (0 while it is off).
std::size_t retained_bytes();

}  // namespace huge_pages

/// Arrays from this size up to a huge page are blocks of huge_pages::acquire_block (from the pool
/// when it is on); smaller ones come from operator new. Below a huge page the pool still pays: an
/// array of a 10^5-triangle mesh's dual is about 1 MiB, which malloc maps afresh or trims back to
/// the kernel between calls, so each call would fault its pages in again (on virtual machines
/// that costs more than the search that writes them: armadillo's lrs augmentation, 14 ms of
/// faults for 0.2 ms of search).
inline constexpr std::size_t kPooledBytes = std::size_t{64} << 10;

/// Allocates arrays of at least kPageBytes through huge_pages::acquire, mid-size ones (from
/// kPooledBytes) through huge_pages::acquire_block, smaller ones with operator new.
template <class T>
struct HugePageAllocator {
  using value_type = T;

  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) {}  // NOLINT: allocators convert implicitly

  T* allocate(std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < kPooledBytes)
      return static_cast<T*>(::operator new (bytes, std::align_val_t{alignof(T)}));
    if (bytes < huge_pages::kPageBytes) return static_cast<T*>(huge_pages::acquire_block(bytes));
    return static_cast<T*>(huge_pages::acquire(round_up(bytes), bytes));
  }
  void deallocate(T* p, std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < kPooledBytes) {
      ::operator delete (p, std::align_val_t{alignof(T)});
    } else if (bytes < huge_pages::kPageBytes) {
      huge_pages::release_block(p, bytes);
    } else {
      huge_pages::release(p, round_up(bytes));
    }
  }
  static std::size_t round_up(std::size_t bytes) {
    return (bytes + huge_pages::kPageBytes - 1) / huge_pages::kPageBytes * huge_pages::kPageBytes;
  }

  template <class U>
  bool operator==(const HugePageAllocator<U>&) const {
    return true;
  }
};

/// A std::vector whose large buffers sit on huge pages.
template <class T>
using HugeVector = std::vector<T, HugePageAllocator<T>>;

/// A fixed-size array on huge pages whose elements the owner writes before reading (no
/// initialising pass): for trivially constructible T.
template <class T>
struct HugeArrayRelease {
  std::size_t size = 0;
  void operator()(T* p) const { HugePageAllocator<T>().deallocate(p, size); }
};
template <class T>
using HugeArray = std::unique_ptr<T[], HugeArrayRelease<T>>;
template <class T>
HugeArray<T> make_huge_array(std::size_t size) {
  return HugeArray<T>(HugePageAllocator<T>().allocate(size), HugeArrayRelease<T>{size});
}

/// Shrinks `array` (of array.get_deleter().size elements) to its first `size`, giving back at once
/// the whole huge pages past them, released as the array's own are (kept by the pool or unmapped):
/// for an array whose tail is dead while its head lives on. Nothing is given back when either
/// size is below a huge page.
template <class T>
void shrink_huge_array(HugeArray<T>& array, std::size_t size) {
  const std::size_t had = array.get_deleter().size * sizeof(T), keep = size * sizeof(T);
  if (keep < huge_pages::kPageBytes || had < keep) return;
  const std::size_t kept_bytes = HugePageAllocator<T>::round_up(keep);
  const std::size_t had_bytes = HugePageAllocator<T>::round_up(had);
  if (kept_bytes < had_bytes) {
    huge_pages::release(reinterpret_cast<char*>(array.get()) + kept_bytes, had_bytes - kept_bytes);
  }
  array.get_deleter().size = size;
}

}  // namespace petersen
