#include "local_vertices.hpp"

#include <algorithm>
#include <string>

namespace petersen::partition_detail {

namespace {

constexpr VertexId kNoVertex = 0xFFFFFFFFu;

LocalCorners by_table(std::span<const VertexId> corners, VertexId low, VertexId high) {
  std::pmr::vector<VertexId> local_of(std::size_t{high} - low + 1, kNoVertex);
  for (VertexId v : corners) local_of[v - low] = 0;
  VertexId next = 0;
  for (VertexId& slot : local_of) {
    if (slot == 0) slot = next++;
  }
  LocalCorners local;
  local.vertex_count = next;
  local.corners.resize(corners.size());
  for (std::size_t i = 0; i < corners.size(); ++i) local.corners[i] = local_of[corners[i] - low];
  return local;
}

LocalCorners by_sorting(std::span<const VertexId> corners) {
  std::pmr::vector<VertexId> ids(corners.begin(), corners.end());
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  LocalCorners local;
  local.vertex_count = static_cast<std::uint32_t>(ids.size());
  local.corners.resize(corners.size());
  for (std::size_t i = 0; i < corners.size(); ++i) {
    local.corners[i] =
        static_cast<VertexId>(std::lower_bound(ids.begin(), ids.end(), corners[i]) - ids.begin());
  }
  return local;
}

}  // namespace

LocalCorners local_corners(std::span<const VertexId> corners, FaceId first_face) {
  if (corners.empty()) return {};
  VertexId low = kNoVertex, high = 0;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    if (corners[i] == kNoVertex) {
      throw MeshError("face " + std::to_string(std::uint64_t{first_face} + i / 3) +
                      " names vertex 4294967295, past the largest vertex id");
    }
    low = std::min(low, corners[i]);
    high = std::max(high, corners[i]);
  }
  if (std::uint64_t{high} - low < 4 * std::uint64_t{corners.size()}) {
    return by_table(corners, low, high);
  }
  return by_sorting(corners);
}

}  // namespace petersen::partition_detail
