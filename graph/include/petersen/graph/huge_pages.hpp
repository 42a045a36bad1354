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

/// `bytes` (a multiple of kPageBytes) of kPageBytes-aligned memory, advised onto huge pages, its
/// contents unspecified. The smallest range that release() kept and that is large enough is
/// handed out again (split if larger); when none is, the largest kept ranges go back to the
/// kernel, as many bytes as the request, and the range is mapped fresh, so that kept memory does
/// not pile up beside the live arrays. Throws std::bad_alloc.
void* acquire(std::size_t bytes);

/// Gives back a range from acquire(). Up to kRetainedBytes in all are kept for the next
/// acquire() (the rest goes back to the kernel), because on virtual machines a fresh page is
/// expensive: here the host backs guest memory lazily and takes freed memory back, so filling
/// fresh memory ran at 0.25-1.2 GB/s against 15 GB/s for reused huge pages (a touch loop on the
/// development VM, 256 MB at a time).
/// A forked child drops the ranges its parent kept (writing them would copy every page).
/// malloc keeps freed memory in its heap for the same reason, but maps blocks above 32 MiB
/// afresh every time and hands reused blocks out on whatever pages they had.
void release(void* range, std::size_t bytes);

inline constexpr std::size_t kRetainedBytes = std::size_t{1} << 30;

/// Returns every kept range to the kernel.
void release_retained();

}  // namespace huge_pages

/// Allocates arrays of at least kPageBytes through huge_pages, smaller ones with operator new.
template <class T>
struct HugePageAllocator {
  using value_type = T;

  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) {}  // NOLINT: allocators convert implicitly

  T* allocate(std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < huge_pages::kPageBytes)
      return static_cast<T*>(::operator new (bytes, std::align_val_t{alignof(T)}));
    return static_cast<T*>(huge_pages::acquire(round_up(bytes)));
  }
  void deallocate(T* p, std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < huge_pages::kPageBytes) {
      ::operator delete (p, std::align_val_t{alignof(T)});
      return;
    }
    huge_pages::release(p, round_up(bytes));
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

}  // namespace petersen
