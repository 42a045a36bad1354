#include "edge_groups.hpp"

#include <algorithm>

namespace petersen {

EdgeGroups group_halfedges(const TriangleMesh& mesh, const std::vector<std::uint8_t>& usable) {
  const std::uint32_t halfedge_count = static_cast<std::uint32_t>(3 * mesh.triangles.size());
  auto used = [&](std::uint32_t h) { return usable.empty() || usable[h / 3]; };
  const std::size_t vertex_count = mesh.positions.size();
  // A counting sort by smaller vertex. After the placement loop start[v] has moved to the end of
  // bucket v; the shift restores it.
  EdgeGroups groups;
  auto& start = groups.start;
  start.assign(vertex_count + 1, 0);
  std::uint32_t total = 0;
  for (std::uint32_t h = 0; h < halfedge_count; ++h) {
    if (!used(h)) continue;
    ++start[std::min(halfedge_from(mesh, h), halfedge_to(mesh, h)) + 1];
    ++total;
  }
  for (std::size_t v = 0; v < vertex_count; ++v) start[v + 1] += start[v];
  groups.entries.resize(total);
  for (std::uint32_t h = 0; h < halfedge_count; ++h) {
    if (!used(h)) continue;
    const VertexId a = halfedge_from(mesh, h), b = halfedge_to(mesh, h);
    groups.entries[start[std::min(a, b)]++] = {std::max(a, b), h};
  }
  for (std::size_t v = vertex_count; v > 0; --v) start[v] = start[v - 1];
  start[0] = 0;
  for (std::size_t v = 0; v < vertex_count; ++v) {
    std::sort(groups.entries.begin() + start[v], groups.entries.begin() + start[v + 1]);
  }
  return groups;
}

}  // namespace petersen
