#pragma once
// The bench's huge-page pool (petersen/memory_pool/huge_page_pool.hpp): made once by the program
// and set as its default memory resource, so that every array of every contestant, at every level
// the bench calls the library, is served as the CLI's are. PETERSEN_HUGE_PAGE_POOL=off leaves the
// standard resource, so that the same binaries measure what the pool buys.

#include <cstdlib>
#include <memory_resource>
#include <string_view>

#include "petersen/memory_pool/huge_page_pool.hpp"

namespace petersen::bench {

/// Makes the pool and sets it as the default resource unless PETERSEN_HUGE_PAGE_POOL is "off";
/// returns it, or nullptr. The pool is never destroyed: arrays with static storage may be given
/// back to it at exit. Call it first thing in main(), before any array is made.
inline HugePagePool* install_memory_pool() {
  const char* setting = std::getenv("PETERSEN_HUGE_PAGE_POOL");
  if (setting != nullptr && std::string_view(setting) == "off") return nullptr;
  static HugePagePool* const pool = new HugePagePool;  // NOLINT: outlives every array
  std::pmr::set_default_resource(pool);
  return pool;
}

/// In a forked child: the ranges the parent's pool keeps are shared with it copy on write, and
/// writing them would copy every page; they are dropped, as fresh memory is cheaper.
inline void drop_inherited_pool() {
  if (auto* pool = dynamic_cast<HugePagePool*>(std::pmr::get_default_resource()))
    pool->release_retained();
}

}  // namespace petersen::bench
