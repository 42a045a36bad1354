#pragma once
// Halfedges grouped by the undirected edge they lie on, without hashing: the core shared by the
// dual builder, the surface inspection and the pairable graph.

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "petersen/dualize/mesh.hpp"
#include "petersen/graph/huge_pages.hpp"

namespace petersen {

/// `entries` holds {larger vertex, halfedge} bucketed by the smaller vertex (bucket v is
/// entries[start[v]] up to entries[start[v+1]]) and sorted within each bucket, so the copies of
/// an edge are adjacent and in halfedge order.
struct EdgeGroups {
  HugeVector<std::uint32_t> start;
  HugeVector<std::array<std::uint32_t, 2>> entries;
};

/// Groups halfedges 0..halfedge_count-1, halfedge h running from from(h) to to(h) (vertices below
/// vertex_count), skipping those for which used(h) is false. A counting sort by smaller vertex,
/// then a sort within each bucket: O(H log d) for maximum vertex degree d.
template <class From, class To, class Used>
EdgeGroups group_halfedges(std::size_t vertex_count, std::uint32_t halfedge_count, From from, To to,
                           Used used) {
  // After the placement loop start[v] has moved to the end of bucket v; the shift restores it.
  EdgeGroups groups;
  auto& start = groups.start;
  start.assign(vertex_count + 1, 0);
  std::uint32_t total = 0;
  for (std::uint32_t h = 0; h < halfedge_count; ++h) {
    if (!used(h)) continue;
    ++start[std::min(from(h), to(h)) + 1];
    ++total;
  }
  for (std::size_t v = 0; v < vertex_count; ++v) start[v + 1] += start[v];
  groups.entries.resize(total);
  for (std::uint32_t h = 0; h < halfedge_count; ++h) {
    if (!used(h)) continue;
    const VertexId a = from(h), b = to(h);
    groups.entries[start[std::min(a, b)]++] = {std::max(a, b), h};
  }
  for (std::size_t v = vertex_count; v > 0; --v) start[v] = start[v - 1];
  start[0] = 0;
  for (std::size_t v = 0; v < vertex_count; ++v) {
    std::sort(groups.entries.begin() + start[v], groups.entries.begin() + start[v + 1]);
  }
  return groups;
}

/// Halfedge h = 3t + k runs from corner k of triangle t to corner (k+1)%3.
inline VertexId halfedge_from(const TriangleMesh& mesh, std::uint32_t h) {
  return mesh.triangles[h / 3][h % 3];
}
inline VertexId halfedge_to(const TriangleMesh& mesh, std::uint32_t h) {
  return mesh.triangles[h / 3][(h % 3 + 1) % 3];
}

/// Groups the halfedges of the triangles whose `usable` flag is set (all when `usable` is empty).
/// The corners of usable triangles must be in range.
inline EdgeGroups group_halfedges(const TriangleMesh& mesh,
                                  const std::vector<std::uint8_t>& usable) {
  return group_halfedges(
      mesh.positions.size(), static_cast<std::uint32_t>(3 * mesh.triangles.size()),
      [&](std::uint32_t h) { return halfedge_from(mesh, h); },
      [&](std::uint32_t h) { return halfedge_to(mesh, h); },
      [&](std::uint32_t h) { return usable.empty() || usable[h / 3]; });
}

}  // namespace petersen
