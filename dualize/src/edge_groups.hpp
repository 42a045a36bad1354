#pragma once
// Halfedges grouped by the undirected edge they lie on, without hashing: the core shared by the
// dual builder and the surface inspection.

#include <array>
#include <cstdint>
#include <vector>

#include "petersen/dualize/mesh.hpp"
#include "petersen/graph/huge_pages.hpp"

namespace petersen {

/// Halfedge h = 3t + k runs from corner k of triangle t to corner (k+1)%3. `entries` holds
/// {larger vertex, halfedge} bucketed by the smaller vertex (bucket v is entries[start[v]] up to
/// entries[start[v+1]]) and sorted within each bucket, so the copies of an edge are adjacent and
/// in halfedge order. O(F log d) for maximum vertex degree d.
struct EdgeGroups {
  HugeVector<std::uint32_t> start;
  HugeVector<std::array<std::uint32_t, 2>> entries;
};

/// Groups the halfedges of the triangles whose `usable` flag is set (all when `usable` is empty).
/// The corners of usable triangles must be in range.
EdgeGroups group_halfedges(const TriangleMesh& mesh, const std::vector<std::uint8_t>& usable);

inline VertexId halfedge_from(const TriangleMesh& mesh, std::uint32_t h) {
  return mesh.triangles[h / 3][h % 3];
}
inline VertexId halfedge_to(const TriangleMesh& mesh, std::uint32_t h) {
  return mesh.triangles[h / 3][(h % 3 + 1) % 3];
}

}  // namespace petersen
