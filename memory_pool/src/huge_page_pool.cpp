#include "petersen/memory_pool/huge_page_pool.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace petersen {

namespace {

constexpr std::size_t kPageBytes = HugePagePool::kPageBytes;

std::size_t round_up(std::size_t bytes) {
  return (bytes + kPageBytes - 1) / kPageBytes * kPageBytes;
}

// Mid-size blocks from the heap (a pool that keeps nothing) are aligned like a cache line.
constexpr std::size_t kBlockAlignment = 64;

#if defined(__linux__)
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

void unmap(void* range, std::size_t bytes) {
  munmap(range, bytes);
}

// Moves the pages of [from, from + bytes) over [to, to + bytes), a part of a fresh mapping not
// yet touched: the page tables move, not the bytes, and huge pages stay huge (every range is
// aligned to them). mremap moves one mapping at a time, and a range assembled from several (by
// obtain) is several: a failed move is split in halves down to single huge pages, each in one
// mapping, so it takes O(mappings · log(bytes)) calls. A page that still cannot move is given
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
#else  // no huge pages to advise, and no ranges to keep: aligned heap blocks
void* map_fresh(std::size_t bytes) {
  void* range = std::aligned_alloc(kPageBytes, bytes);
  if (range == nullptr) throw std::bad_alloc();
  return range;
}
void unmap(void* range, std::size_t) {
  std::free(range);
}
#endif

}  // namespace

#if defined(__linux__)
HugePagePool::HugePagePool(std::size_t retained_bytes, std::size_t footprint_bytes)
    : limit_(retained_bytes), footprint_(footprint_bytes) {}
#else
HugePagePool::HugePagePool(std::size_t, std::size_t footprint_bytes)
    : limit_(0), footprint_(footprint_bytes) {}
#endif

HugePagePool::~HugePagePool() {
  release_retained();
}

void* HugePagePool::do_allocate(std::size_t bytes, std::size_t alignment) {
  if (bytes < kPooledBytes || alignment > kPageBytes)
    return ::operator new (bytes, std::align_val_t{alignment});
  if (bytes < kPageBytes && limit_ == 0)
    return ::operator new (bytes, std::align_val_t{std::max(alignment, kBlockAlignment)});
  return acquire(round_up(bytes), bytes);
}

void HugePagePool::do_deallocate(void* block, std::size_t bytes, std::size_t alignment) {
  if (bytes < kPooledBytes || alignment > kPageBytes) {
    ::operator delete (block, std::align_val_t{alignment});
  } else if (bytes < kPageBytes && limit_ == 0) {
    ::operator delete (block, std::align_val_t{std::max(alignment, kBlockAlignment)});
  } else {
    release(block, round_up(bytes));
  }
}

void* HugePagePool::obtain(std::size_t bytes) {
  if (limit_ == 0) return map_fresh(bytes);
  std::vector<Range> pieces;
  {
    const std::lock_guard lock(mutex_);
    // The smallest kept range that is large enough; its tail stays kept.
    auto best = ranges_.end();
    for (auto r = ranges_.begin(); r != ranges_.end(); ++r) {
      if (r->bytes >= bytes && (best == ranges_.end() || r->bytes < best->bytes)) best = r;
    }
    if (best != ranges_.end()) {
      char* const start = best->start;
      if (best->bytes == bytes) {
        ranges_.erase(best);
      } else {
        best->start += bytes;
        best->bytes -= bytes;
      }
      bytes_ -= bytes;
      return start;
    }
    // None fits alone: the new range is assembled from the largest kept ranges, as many bytes as
    // it takes, their pages moved into it (move_pages), and only the rest is fresh. Giving them
    // back and mapping the range afresh instead faulted in 50 MB more on armadillo-sub2's `quad`
    // (120 MB fresh for an 87 MB peak), and a fresh page costs 10-60x a reused one on a virtual
    // machine. The largest go first: the fewest moves, and no kept memory piles up beside the
    // live arrays.
    std::sort(ranges_.begin(), ranges_.end(),
              [](const Range& a, const Range& b) { return a.bytes < b.bytes; });
    std::size_t taken = 0;
    while (taken < bytes && !ranges_.empty()) {
      Range& largest = ranges_.back();
      const std::size_t part = std::min(largest.bytes, bytes - taken);
      pieces.push_back({largest.start, part});
      taken += part;
      bytes_ -= part;
      if (part == largest.bytes) {
        ranges_.pop_back();
      } else {  // the head is moved, the tail stays kept
        largest.start += part;
        largest.bytes -= part;
      }
    }
  }
  char* const range = static_cast<char*>(map_fresh(bytes));
#if defined(__linux__)
  char* at = range;
  for (const Range& piece : pieces) {
    move_pages(piece.start, piece.bytes, at);
    at += piece.bytes;
  }
#endif
  return range;
}

void* HugePagePool::acquire(std::size_t bytes, std::size_t used) {
  void* range = obtain(bytes);
  {
    const std::lock_guard lock(mutex_);
    live_ += bytes;
  }
#if defined(__linux__) && defined(MADV_HUGEPAGE) && defined(MADV_NOHUGEPAGE)
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

void HugePagePool::release(void* range, std::size_t bytes) {
  {
    const std::lock_guard lock(mutex_);
    live_ -= bytes;
    if (limit_ != 0 && bytes_ + bytes <= limit_ && bytes_ + bytes + live_ <= footprint_) {
      ranges_.push_back({static_cast<char*>(range), bytes});
      bytes_ += bytes;
      return;
    }
  }
  unmap(range, bytes);
}

void HugePagePool::give_back(std::vector<Range>& ranges) {
  for (const Range& r : ranges) unmap(r.start, r.bytes);
}

void HugePagePool::release_retained() {
  std::vector<Range> ranges;
  {
    const std::lock_guard lock(mutex_);
    ranges.swap(ranges_);
    bytes_ = 0;
  }
  give_back(ranges);
}

void HugePagePool::trim_retained(std::size_t keep_bytes) {
  std::vector<Range> given_back;
  {
    const std::lock_guard lock(mutex_);
    std::sort(ranges_.begin(), ranges_.end(),
              [](const Range& a, const Range& b) { return a.bytes < b.bytes; });
    while (bytes_ > keep_bytes) {
      given_back.push_back(ranges_.back());
      bytes_ -= ranges_.back().bytes;
      ranges_.pop_back();
    }
  }
  give_back(given_back);
}

std::size_t HugePagePool::retained_bytes() const {
  const std::lock_guard lock(mutex_);
  return bytes_;
}

std::size_t HugePagePool::shrink(void* block, std::size_t bytes, std::size_t keep_bytes) {
  if (keep_bytes < kPageBytes || bytes < keep_bytes) return bytes;
  const std::size_t kept = round_up(keep_bytes), had = round_up(bytes);
#if defined(__linux__)
  if (kept < had) release(static_cast<char*>(block) + kept, had - kept);
  return keep_bytes;
#else
  (void)block;
  (void)kept;
  (void)had;
  return bytes;  // one heap block, given back whole
#endif
}

}  // namespace petersen
