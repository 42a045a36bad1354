#pragma once
// The input's triangles bucketed by their smallest corner (a counting sort), to find the one with
// a given vertex set: a triangle of K that no flip made is one of them. The buckets hold a few
// triangles each, stored with their other two corners so that a probe reads its bucket and not the
// input's corners (one random read per candidate fewer). O(V + F) to build, O(bucket) a probe.

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>

#include "petersen/graph/memory.hpp"
#include "petersen/lrs/lrs.hpp"
#include "petersen/mesh/mesh.hpp"

namespace petersen::lrs {

class TrianglesByCorner {
 public:
  /// Triangle t is corners[3t], corners[3t + 1], corners[3t + 2], each below vertex_count.
  TrianglesByCorner(std::span<const VertexId> corners, std::size_t vertex_count)
      : start_(vertex_count + 1, 0), entry_(corners.size() / 3) {
    const auto faces = static_cast<FaceId>(corners.size() / 3);
    const auto triangle = [&](FaceId t) { return corners.subspan(3 * std::size_t{t}, 3); };
    for (FaceId t = 0; t < faces; ++t) ++start_[smallest(triangle(t)) + 1];
    for (std::size_t v = 0; v + 1 < start_.size(); ++v) start_[v + 1] += start_[v];
    for (FaceId t = 0; t < faces; ++t) {
      const auto c = triangle(t);
      const VertexId low = smallest(c);
      const VertexId u = c[0] == low ? c[1] : c[0];
      const VertexId w = c[2] == low ? c[1] : c[2];
      entry_[start_[low]++] = {t, u, w};
    }
    // Each start moved to the next bucket's: shifted back by one bucket.
    for (std::size_t v = start_.size() - 1; v > 0; --v) start_[v] = start_[v - 1];
    start_[0] = 0;
  }

  /// Hints the caches at the buckets a later find(a, b, c) reads: first the bucket's start, then,
  /// once that is in cache, the bucket itself.
  void prefetch_start(VertexId low) const { __builtin_prefetch(&start_[low]); }
  void prefetch_bucket(VertexId low) const { __builtin_prefetch(entry_.data() + start_[low]); }

  /// The input triangle with corners {a, b, c} (distinct), or kNoFace.
  FaceId find(VertexId a, VertexId b, VertexId c) const {
    const VertexId low = std::min({a, b, c});
    const VertexId x = a == low ? b : a, y = c == low ? b : c;
    for (std::uint32_t j = start_[low]; j < start_[low + 1]; ++j) {
      const Entry& t = entry_[j];
      if ((t.u == x && t.w == y) || (t.u == y && t.w == x)) return t.face;
    }
    return kNoFace;
  }

 private:
  struct Entry {
    FaceId face;
    VertexId u, w;  // the corners other than the smallest
  };

  static VertexId smallest(std::span<const VertexId> t) { return std::min({t[0], t[1], t[2]}); }

  std::pmr::vector<std::uint32_t> start_;
  std::pmr::vector<Entry> entry_;
};

}  // namespace petersen::lrs
