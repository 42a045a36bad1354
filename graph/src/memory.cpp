#include "petersen/graph/memory.hpp"

namespace petersen {

std::size_t release_tail(std::pmr::memory_resource* memory, void* block, std::size_t bytes,
                         std::size_t keep_bytes) {
  if (auto* pool = dynamic_cast<TailReleasingResource*>(memory))
    return pool->shrink(block, bytes, keep_bytes);
  return bytes;
}

}  // namespace petersen
