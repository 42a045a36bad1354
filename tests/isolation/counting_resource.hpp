#pragma once
// A memory resource that counts what it hands out, over new and delete: the isolation tests' proof
// that a call allocated from the resource its options named, and gave everything back.

#include <atomic>
#include <cstddef>
#include <memory_resource>

namespace petersen::testing {

class CountingResource final : public std::pmr::memory_resource {
 public:
  std::size_t allocated_bytes() const { return allocated_; }
  std::size_t live_bytes() const { return live_; }
  void reset() { allocated_ = 0; }

 private:
  void* do_allocate(std::size_t bytes, std::size_t alignment) override {
    allocated_ += bytes;
    live_ += bytes;
    return std::pmr::new_delete_resource()->allocate(bytes, alignment);
  }
  void do_deallocate(void* p, std::size_t bytes, std::size_t alignment) override {
    live_ -= bytes;
    std::pmr::new_delete_resource()->deallocate(p, bytes, alignment);
  }
  bool do_is_equal(const std::pmr::memory_resource& other) const noexcept override {
    return this == &other;
  }

  std::atomic<std::size_t> allocated_{0}, live_{0};
};

}  // namespace petersen::testing
