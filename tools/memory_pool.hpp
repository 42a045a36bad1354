#pragma once
// The CLI's huge-page pool (petersen/memory_pool/huge_page_pool.hpp): the program's choice, not the
// library's. A conversion's stages free large arrays that the next stage allocates again; kept in
// the pool, they are not faulted in afresh (fresh pages are the slow ones on a virtual machine).
// PETERSEN_HUGE_PAGE_POOL=off runs without it, so that the same binary measures what it buys.

#include <cstdlib>
#include <memory_resource>
#include <string_view>

#include "petersen/memory_pool/huge_page_pool.hpp"

namespace petersen::cli {

/// True unless the environment variable PETERSEN_HUGE_PAGE_POOL is "off".
inline bool huge_page_pool_wanted() {
  const char* setting = std::getenv("PETERSEN_HUGE_PAGE_POOL");
  return setting == nullptr || std::string_view(setting) != "off";
}

/// The program's pool: made by main() (unless switched off) and set as the process's default
/// resource too, so that arrays the library makes without being handed a resource are served
/// alike and moves between the two never copy. Never destroyed: arrays with static storage may be
/// given back to it at exit.
inline HugePagePool* program_pool = nullptr;

/// What the commands hand the library in its options: the pool, or the standard resource.
inline std::pmr::memory_resource* program_memory() {
  return program_pool != nullptr ? program_pool : std::pmr::get_default_resource();
}

}  // namespace petersen::cli
