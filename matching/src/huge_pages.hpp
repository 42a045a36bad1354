#pragma once
// Large scratch arrays on transparent huge pages: a fresh array of n bytes costs n / 4 KiB page
// faults otherwise, and on a virtual machine a fault costs microseconds (about a third of the gw
// set-up on armadillo-sub2's dual). Linux only honours the advice with transparent huge pages in
// "always" or "madvise" mode; elsewhere these are plain allocations.

#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace petersen {

template <class T>
struct HugePageAllocator {
  using value_type = T;
  static constexpr std::size_t kHugePage = std::size_t{2} << 20;

  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) {}  // NOLINT: allocators convert implicitly

  T* allocate(std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < kHugePage) return static_cast<T*>(::operator new(bytes));
    const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
    void* p = std::aligned_alloc(kHugePage, rounded);
    if (p == nullptr) throw std::bad_alloc();
#if defined(MADV_HUGEPAGE)
    madvise(p, rounded, MADV_HUGEPAGE);  // advice only: a refusal leaves ordinary pages
#endif
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t n) {
    if (n * sizeof(T) < kHugePage)
      ::operator delete(p);
    else
      std::free(p);
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
