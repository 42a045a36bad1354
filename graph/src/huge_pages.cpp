#include "petersen/graph/huge_pages.hpp"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <new>
#include <string_view>
#include <vector>

#if defined(__linux__)
#include <pthread.h>
#include <sys/mman.h>
#endif

namespace petersen::huge_pages {

#if defined(__linux__)
namespace {

struct Range {
  char* start;
  std::size_t bytes;
};

// Ranges given back and kept for reuse while the pool is on: a handful at a time, so searched
// linearly. Made by the first enable_pool() and never destroyed, so that arrays with static
// storage can still be released at exit. A program that never enables the pool never makes it.
struct Retained {
  std::mutex mutex;
  std::vector<Range> ranges;
  std::size_t bytes = 0;
  std::size_t limit = 0;  // 0: the pool is off
};
Retained& retained() {
  static Retained* const kept = new Retained;
  return *kept;
}
// Read without the lock by acquire() and release(), so that with the pool off they touch no
// shared state; the lock decides once it is on.
std::atomic<bool> pool_on{false};

// A forked child shares the kept ranges with its parent, copy on write: the first write to each
// 4 KiB page would copy it (the huge page is split first). The child drops them instead, as
// fresh memory is cheaper (the bench harness forks a child per run: 7,583 such copies in LRS's
// contraction on the 4.1M-triangle D6). The lock is held across fork, so the child finds the
// list whole.
void lock_before_fork() {
  retained().mutex.lock();
}
void unlock_in_parent() {
  retained().mutex.unlock();
}
void drop_in_child() {
  Retained& kept = retained();
  for (const Range& r : kept.ranges) munmap(r.start, r.bytes);
  kept.ranges.clear();
  kept.bytes = 0;
  kept.mutex.unlock();
}

// Straight from the kernel, not through malloc: malloc hands a freed block out again as it is,
// and a block first touched without the advice stays on 4 KiB pages (measured on
// armadillo-sub2's dual: the augmentation took 0.12 s in such a block, 0.07 s on huge pages).
void* map_fresh(std::size_t bytes) {
  // Over-allocated by a page and trimmed to an aligned range of whole huge pages.
  void* mapped =
      mmap(nullptr, bytes + kPageBytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (mapped == MAP_FAILED) throw std::bad_alloc();
  const auto start = reinterpret_cast<std::uintptr_t>(mapped);
  const std::uintptr_t aligned = (start + kPageBytes - 1) & ~(kPageBytes - 1);
  if (aligned > start) munmap(mapped, aligned - start);
  const std::uintptr_t end = aligned + bytes;
  if (start + bytes + kPageBytes > end)
    munmap(reinterpret_cast<void*>(end), start + bytes + kPageBytes - end);
  return reinterpret_cast<void*>(aligned);  // advised by acquire, like a kept range
}

// Moves the pages of [from, from + bytes) over [to, to + bytes), a part of a fresh mapping not
// yet touched: the page tables move, not the bytes, and huge pages stay huge (every range is
// aligned to them). mremap moves one mapping at a time, and a range assembled from several (by
// acquire below) is several: a failed move is split in halves down to single huge pages, each in
// one mapping, so it takes O(mappings · log(bytes)) calls. A page that still cannot move is given
// back, and its place in `to` stays fresh.
void move_pages(char* from, std::size_t bytes, char* to) {
  if (mremap(from, bytes, bytes, MREMAP_MAYMOVE | MREMAP_FIXED, to) != MAP_FAILED) return;
  if (bytes == kPageBytes) {
    munmap(from, bytes);
    return;
  }
  const std::size_t half = bytes / kPageBytes / 2 * kPageBytes;
  move_pages(from, half, to);
  move_pages(from + half, bytes - half, to + half);
}

// A range of `bytes` from the pool or the kernel, not yet advised.
void* obtain(std::size_t bytes) {
  if (!pool_on.load(std::memory_order_acquire)) return map_fresh(bytes);
  Retained& kept = retained();
  std::vector<Range> pieces;
  {
    const std::lock_guard lock(kept.mutex);
    // The smallest kept range that is large enough; its tail stays kept.
    auto best = kept.ranges.end();
    for (auto r = kept.ranges.begin(); r != kept.ranges.end(); ++r) {
      if (r->bytes >= bytes && (best == kept.ranges.end() || r->bytes < best->bytes)) best = r;
    }
    if (best != kept.ranges.end()) {
      char* const start = best->start;
      if (best->bytes == bytes) {
        kept.ranges.erase(best);
      } else {
        best->start += bytes;
        best->bytes -= bytes;
      }
      kept.bytes -= bytes;
      return start;
    }
    // None fits alone: the new range is assembled from the largest kept ranges, as many bytes as
    // it takes, their pages moved into it (move_pages), and only the rest is fresh. Giving them
    // back and mapping the range afresh instead faulted in 50 MB more on armadillo-sub2's `quad`
    // (120 MB fresh for an 87 MB peak), and a fresh page costs 10-60x a reused one here (see
    // enable_pool). The largest go first: the fewest moves, and no kept memory piles up beside
    // the live arrays.
    std::sort(kept.ranges.begin(), kept.ranges.end(),
              [](const Range& a, const Range& b) { return a.bytes < b.bytes; });
    std::size_t taken = 0;
    while (taken < bytes && !kept.ranges.empty()) {
      Range& largest = kept.ranges.back();
      const std::size_t part = std::min(largest.bytes, bytes - taken);
      pieces.push_back({largest.start, part});
      taken += part;
      kept.bytes -= part;
      if (part == largest.bytes) {
        kept.ranges.pop_back();
      } else {  // the head is moved, the tail stays kept
        largest.start += part;
        largest.bytes -= part;
      }
    }
  }
  char* const range = static_cast<char*>(map_fresh(bytes));
  char* at = range;
  for (const Range& piece : pieces) {
    move_pages(piece.start, piece.bytes, at);
    at += piece.bytes;
  }
  return range;
}

}  // namespace

void* acquire(std::size_t bytes, std::size_t used) {
  void* range = obtain(bytes);
#if defined(MADV_HUGEPAGE) && defined(MADV_NOHUGEPAGE)
  // Advice only (a refusal leaves ordinary pages). A kept range may hold a tail advised for an
  // earlier array: the whole range is advised afresh.
  madvise(range, bytes, MADV_HUGEPAGE);
  const std::size_t whole = used / kPageBytes * kPageBytes;
  if (whole < bytes) madvise(static_cast<char*>(range) + whole, bytes - whole, MADV_NOHUGEPAGE);
#else
  (void)used;
#endif
  return range;
}

void release(void* range, std::size_t bytes) {
  if (pool_on.load(std::memory_order_acquire)) {
    Retained& kept = retained();
    const std::lock_guard lock(kept.mutex);
    if (kept.bytes + bytes <= kept.limit) {
      kept.ranges.push_back({static_cast<char*>(range), bytes});
      kept.bytes += bytes;
      return;
    }
  }
  munmap(range, bytes);
}

namespace {
// A block's first 64 bytes say where it came from, so that release_block() gives it back there
// whatever the pool's state is by then.
constexpr std::size_t kBlockHeader = 64;
constexpr std::uint64_t kFromHeap = 0x68656170, kFromPool = 0x706f6f6c;

std::size_t pool_range_bytes(std::size_t bytes) {
  return (bytes + kBlockHeader + kPageBytes - 1) / kPageBytes * kPageBytes;
}
}  // namespace

void* acquire_block(std::size_t bytes) {
  char* base;
  std::uint64_t tag;
  if (pool_on.load(std::memory_order_acquire)) {
    base = static_cast<char*>(acquire(pool_range_bytes(bytes), bytes + kBlockHeader));
    tag = kFromPool;
  } else {
    base =
        static_cast<char*>(::operator new (bytes + kBlockHeader, std::align_val_t{kBlockHeader}));
    tag = kFromHeap;
  }
  std::memcpy(base, &tag, sizeof tag);
  return base + kBlockHeader;
}

void release_block(void* block, std::size_t bytes) {
  char* const base = static_cast<char*>(block) - kBlockHeader;
  std::uint64_t tag;
  std::memcpy(&tag, base, sizeof tag);
  if (tag == kFromPool) {
    release(base, pool_range_bytes(bytes));
  } else {
    ::operator delete (base, std::align_val_t{kBlockHeader});
  }
}

void enable_pool(std::size_t retained_bytes) {
  Retained& kept = retained();
  static const bool installed = [] {
    pthread_atfork(lock_before_fork, unlock_in_parent, drop_in_child);
    return true;
  }();
  (void)installed;
  const std::lock_guard lock(kept.mutex);
  kept.limit = retained_bytes;
  pool_on.store(true, std::memory_order_release);
}

// Empties the pool; with `off`, turns it off under the same lock, so no release() keeps a range
// after.
void empty_pool(bool off) {
  if (!pool_on.load(std::memory_order_acquire)) return;
  Retained& kept = retained();
  std::vector<Range> ranges;
  {
    const std::lock_guard lock(kept.mutex);
    ranges.swap(kept.ranges);
    kept.bytes = 0;
    if (off) {
      kept.limit = 0;
      pool_on.store(false, std::memory_order_release);
    }
  }
  for (const Range& r : ranges) munmap(r.start, r.bytes);
}

void disable_pool() {
  empty_pool(true);
}

void enable_pool_unless_switched_off() {
  const char* setting = std::getenv("PETERSEN_HUGE_PAGE_POOL");
  if (setting == nullptr || std::string_view(setting) != "off") enable_pool();
}

void release_retained() {
  empty_pool(false);
}

void trim_retained(std::size_t keep_bytes) {
  if (!pool_on.load(std::memory_order_acquire)) return;
  Retained& kept = retained();
  std::vector<Range> given_back;
  {
    const std::lock_guard lock(kept.mutex);
    std::sort(kept.ranges.begin(), kept.ranges.end(),
              [](const Range& a, const Range& b) { return a.bytes < b.bytes; });
    while (kept.bytes > keep_bytes) {
      given_back.push_back(kept.ranges.back());
      kept.bytes -= kept.ranges.back().bytes;
      kept.ranges.pop_back();
    }
  }
  for (const Range& r : given_back) munmap(r.start, r.bytes);
}

std::size_t retained_bytes() {
  if (!pool_on.load(std::memory_order_acquire)) return 0;
  Retained& kept = retained();
  const std::lock_guard lock(kept.mutex);
  return kept.bytes;
}

#else  // no huge pages to advise, and no ranges to keep: aligned heap blocks

void* acquire(std::size_t bytes, std::size_t) {
  void* range = std::aligned_alloc(kPageBytes, bytes);
  if (range == nullptr) throw std::bad_alloc();
  return range;
}
void release(void* range, std::size_t) {
  std::free(range);
}
void* acquire_block(std::size_t bytes) {
  return ::operator new (bytes, std::align_val_t{64});
}
void release_block(void* block, std::size_t) {
  ::operator delete (block, std::align_val_t{64});
}
void enable_pool(std::size_t) {}
void enable_pool_unless_switched_off() {}
void disable_pool() {}
void release_retained() {}
void trim_retained(std::size_t) {}
std::size_t retained_bytes() {
  return 0;
}

#endif

}  // namespace petersen::huge_pages
