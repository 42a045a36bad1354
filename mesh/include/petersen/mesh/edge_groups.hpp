#pragma once
// Halfedges grouped by the undirected edge they lie on, without hashing: the core shared by the
// dual builder, the surface inspection and the pairable graph.

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "petersen/graph/memory.hpp"
#include "petersen/mesh/mesh.hpp"

namespace petersen {

/// `entries` holds {larger vertex, halfedge} bucketed by the smaller vertex (bucket v is
/// entries[start[v]] up to entries[start[v+1]]) and sorted within each bucket, so the copies of
/// an edge are adjacent and in halfedge order.
struct EdgeGroups {
  std::pmr::vector<std::uint32_t> start;
  std::pmr::vector<std::array<std::uint32_t, 2>> entries;
};

/// Sorts one bucket by (larger vertex, halfedge), its entries being in ascending halfedge order
/// already (as group_halfedges_in fills them): a vertex has a handful of edges, where an
/// insertion sort beats std::sort's call and set-up, and, being stable, it need only compare the
/// larger vertex.
inline void sort_bucket(std::array<std::uint32_t, 2>* first, std::array<std::uint32_t, 2>* last) {
  if (last - first > 16) return std::sort(first, last);
  // Nothing to sort; and an empty range may be two null pointers (a slice without halfedges),
  // where first + 1 below would be undefined.
  if (last - first < 2) return;
  for (auto* i = first + 1; i < last; ++i) {
    const std::array<std::uint32_t, 2> entry = *i;
    auto* j = i;
    for (; j != first && (j - 1)->front() > entry[0]; --j) *j = *(j - 1);
    *j = entry;
  }
}

/// The bucket offsets of every vertex: start[v] is the number of halfedges whose smaller end lies
/// below v (size vertex_count + 1). `for_each_halfedge(visit)` calls visit(h, from, to) for every
/// halfedge to group, in ascending h. One pass over the halfedges.
template <class ForEachHalfedge>
std::pmr::vector<std::uint32_t> bucket_starts(std::size_t vertex_count,
                                              ForEachHalfedge for_each_halfedge) {
  std::pmr::vector<std::uint32_t> start(vertex_count + 1, 0);
  for_each_halfedge([&](std::uint32_t, VertexId a, VertexId b) { ++start[std::min(a, b) + 1]; });
  for (std::size_t v = 0; v < vertex_count; ++v) start[v + 1] += start[v];
  return start;
}

/// The groups of the halfedges whose smaller end lies in [first_vertex, last_vertex), from the
/// offsets of bucket_starts: start and entries are those of the range alone (start[0] is
/// first_vertex's bucket, at entry 0). One pass over all halfedges, then a sort within each
/// bucket: O(H + R log d) for R halfedges in the range and maximum vertex degree d. Ranges that
/// split the vertices let callers group a large mesh a slice at a time, or slices in parallel.
template <class ForEachHalfedge>
EdgeGroups group_halfedges_in(std::span<const std::uint32_t> all_starts, std::size_t first_vertex,
                              std::size_t last_vertex, ForEachHalfedge for_each_halfedge) {
  EdgeGroups groups;
  const std::uint32_t base = all_starts[first_vertex];
  const std::size_t vertices = last_vertex - first_vertex;
  groups.start.resize(vertices + 1);
  groups.entries.resize(all_starts[last_vertex] - base);
  // Bucket v's next free entry is kept in start[v + 1], which the bucket's last entry moves to
  // its end, the next bucket's start: no separate array of cursors, whose fresh pages
  // per slice would dominate the grouping's page faults.
  groups.start[0] = 0;
  for (std::size_t i = 0; i < vertices; ++i) {
    groups.start[i + 1] = all_starts[first_vertex + i] - base;
  }
  for_each_halfedge([&](std::uint32_t h, VertexId a, VertexId b) {
    const std::size_t low = std::min(a, b);
    if (low < first_vertex || low >= last_vertex) return;
    groups.entries[groups.start[low - first_vertex + 1]++] = {std::max(a, b), h};
  });
  for (std::size_t v = 0; v + 1 < groups.start.size(); ++v) {
    sort_bucket(groups.entries.data() + groups.start[v],
                groups.entries.data() + groups.start[v + 1]);
  }
  return groups;
}

/// Visits halfedges 0..halfedge_count-1, halfedge h running from from(h) to to(h), skipping those
/// for which used(h) is false: a `for_each_halfedge` for the functions above.
template <class From, class To, class Used>
auto halfedges_by(std::uint32_t halfedge_count, From from, To to, Used used) {
  return [=](auto visit) {
    for (std::uint32_t h = 0; h < halfedge_count; ++h) {
      if (used(h)) visit(h, from(h), to(h));
    }
  };
}

/// Groups halfedges 0..halfedge_count-1, halfedge h running from from(h) to to(h) (vertices below
/// vertex_count), skipping those for which used(h) is false. A counting sort by smaller vertex,
/// then a sort within each bucket: O(H log d) for maximum vertex degree d.
template <class From, class To, class Used>
EdgeGroups group_halfedges(std::size_t vertex_count, std::uint32_t halfedge_count, From from, To to,
                           Used used) {
  const auto halfedges = halfedges_by(halfedge_count, from, to, used);
  const std::pmr::vector<std::uint32_t> start = bucket_starts(vertex_count, halfedges);
  return group_halfedges_in(start, 0, vertex_count, halfedges);
}

/// The halfedges of a polygon mesh: halfedge h is corner h of the flat corner array, running to
/// the next corner of its face. The face of each corner is kept only when some face is not a
/// triangle (otherwise it is h / 3).
class PolygonHalfedges {
 public:
  explicit PolygonHalfedges(const PolygonMesh& mesh) : mesh_(mesh) {
    if (mesh.all_triangles()) return;
    corner_face_.resize(mesh.corners.size());
    for (FaceId f = 0; f < mesh.face_count(); ++f)
      for (std::uint32_t c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c)
        corner_face_[c] = f;
  }
  std::uint32_t count() const { return static_cast<std::uint32_t>(mesh_.corners.size()); }
  FaceId face(std::uint32_t h) const { return corner_face_.empty() ? h / 3 : corner_face_[h]; }
  std::uint32_t first(FaceId f) const {
    return mesh_.all_triangles() ? 3 * f : mesh_.face_start[f];
  }
  std::uint32_t next(std::uint32_t h) const {
    const FaceId f = face(h);
    return h + 1 == first(f) + mesh_.arity(f) ? first(f) : h + 1;
  }
  VertexId from(std::uint32_t h) const { return mesh_.corners[h]; }
  VertexId to(std::uint32_t h) const { return mesh_.corners[next(h)]; }

  /// Calls visit(h, from(h), to(h)) for each halfedge in ascending h, but those from a vertex to
  /// itself (inside a face that repeats a vertex), which lie on no edge: a `for_each_halfedge` for
  /// bucket_starts and group_halfedges_in. On a triangle mesh a triangle's three corners are read
  /// once, with no face lookup per halfedge: the pairable graph's slices each take a pass, and
  /// on armadillo-sub2 (4.15M halfedges, 2 threads, 8 slices) the generic lookups made the
  /// passes most of its grouping.
  template <class Visit>
  void for_each(Visit visit) const {
    if (mesh_.all_triangles()) {
      const VertexId* c = mesh_.corners.data();
      const std::uint32_t halfedges = count();
      for (std::uint32_t h = 0; h < halfedges; h += 3) {
        const VertexId a = c[h], b = c[h + 1], d = c[h + 2];
        if (a != b) visit(h, a, b);
        if (b != d) visit(h + 1, b, d);
        if (d != a) visit(h + 2, d, a);
      }
      return;
    }
    for (std::uint32_t h = 0; h < count(); ++h) {
      const VertexId a = from(h), b = to(h);
      if (a != b) visit(h, a, b);
    }
  }

  /// The halfedges grouped by edge (those from a vertex to itself left out).
  EdgeGroups group() const {
    const auto halfedges = [&](auto visit) { for_each(visit); };
    const std::pmr::vector<std::uint32_t> start = bucket_starts(mesh_.positions.size(), halfedges);
    return group_halfedges_in(start, 0, mesh_.positions.size(), halfedges);
  }

 private:
  const PolygonMesh& mesh_;
  std::pmr::vector<FaceId> corner_face_;
};

/// Calls visit(first, end) for each edge's group of entries [first, end) in `groups`.
template <class Visit>
void for_each_edge_group(const EdgeGroups& groups, Visit visit) {
  for (std::size_t v = 0; v + 1 < groups.start.size(); ++v) {
    const std::uint32_t last = groups.start[v + 1];
    for (std::uint32_t first = groups.start[v]; first != last;) {
      std::uint32_t end = first + 1;
      while (end != last && groups.entries[end][0] == groups.entries[first][0]) ++end;
      visit(first, end);
      first = end;
    }
  }
}

}  // namespace petersen
