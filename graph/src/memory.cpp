#include "petersen/graph/memory.hpp"

#include "petersen/graph/huge_page_pool.hpp"

namespace petersen {

std::size_t release_tail(std::pmr::memory_resource* memory, void* block, std::size_t bytes,
                         std::size_t keep_bytes) {
  if (auto* pool = dynamic_cast<HugePagePool*>(memory))
    return pool->shrink(block, bytes, keep_bytes);
  return bytes;
}

}  // namespace petersen
