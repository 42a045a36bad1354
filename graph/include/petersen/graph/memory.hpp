#pragma once
// Memory the caller owns. Every large array the library makes, in its results and in its
// scratch, is a std::pmr::vector or a RawArray on the std::pmr::memory_resource the caller's
// options name (`memory`, std::pmr::get_default_resource() unless set): a program that converts
// meshes of millions of faces hands in a resource that keeps and reuses large blocks (the huge-page
// pool of the CLI, the bench and the Python module, which is theirs and not the library's), one
// that does not leaves the default. The library keeps no memory and no state of its own between
// calls, and never changes the default resource.
//
// The invariant, which makes the resource flow: an array is made on the resource it was given
// (std::pmr::vector<T>(n, value, memory)), and only moved (never copied, never move-assigned or
// swapped with an array on another resource) after that. A pmr vector copied takes the default
// resource, not its source's; one move-assigned across resources copies its elements; swapping
// two across resources is undefined.

#include <cstddef>
#include <memory>
#include <memory_resource>
#include <vector>

namespace petersen {

/// Frees `v`'s storage, leaving it empty on its own resource. (Assigning it an empty vector made
/// on another resource would move nothing and keep the storage.)
template <class T>
void free_storage(std::pmr::vector<T>& v) {
  v = std::pmr::vector<T>(v.get_allocator());
}

/// Gives a RawArray's block back to the resource it came from.
template <class T>
struct RawArrayRelease {
  std::pmr::memory_resource* memory = nullptr;
  std::size_t size = 0;  ///< elements
  void operator()(T* p) const { memory->deallocate(p, size * sizeof(T), alignof(T)); }
};

/// A fixed-size array on a memory resource whose elements the owner writes before reading (no
/// initialising pass, unlike a vector's): for trivially constructible T (a file's bytes, a
/// search's slots). Its size is get_deleter().size.
template <class T>
using RawArray = std::unique_ptr<T[], RawArrayRelease<T>>;

/// A RawArray of `size` elements from `memory`. Throws std::bad_alloc.
template <class T>
RawArray<T> make_raw_array(std::size_t size,
                           std::pmr::memory_resource* memory = std::pmr::get_default_resource()) {
  return RawArray<T>(static_cast<T*>(memory->allocate(size * sizeof(T), alignof(T))),
                     RawArrayRelease<T>{memory, size});
}

/// A memory resource that can give back the tail of a block while its head lives on (a resource
/// of whole pages can unmap the pages past the head); what release_tail asks of a resource.
class TailReleasingResource : public std::pmr::memory_resource {
 public:
  /// Shrinks a block of `bytes` from this resource to its first `keep_bytes` where it can, giving
  /// back the rest. Returns the size the block must be deallocated with from now on:
  /// `keep_bytes` when the tail was given back, else `bytes`.
  virtual std::size_t shrink(void* block, std::size_t bytes, std::size_t keep_bytes) = 0;
};

/// Gives back the tail of a block of `bytes` from `memory` past its first `keep_bytes`, where the
/// resource can (a TailReleasingResource); any other resource keeps the block whole. Returns the
/// size the block must be deallocated with from now on. O(1).
std::size_t release_tail(std::pmr::memory_resource* memory, void* block, std::size_t bytes,
                         std::size_t keep_bytes);

/// Shrinks `array` to its first `size` elements where its resource can give the tail back
/// (release_tail): for an array whose tail is dead while its head lives on.
template <class T>
void shrink_raw_array(RawArray<T>& array, std::size_t size) {
  RawArrayRelease<T>& release = array.get_deleter();
  if (size >= release.size) return;
  const std::size_t bytes =
      release_tail(release.memory, array.get(), release.size * sizeof(T), size * sizeof(T));
  if (bytes == size * sizeof(T)) release.size = size;
}

}  // namespace petersen
