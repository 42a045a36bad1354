#include "spatial_order.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>

namespace petersen::lrs {

namespace {

constexpr int kBitsPerAxis = 6;
constexpr std::uint32_t kCells = 1u << (3 * kBitsPerAxis);

// The low kBitsPerAxis bits of x, spread to every third position.
std::uint32_t spread(std::uint32_t x) {
  std::uint32_t out = 0;
  for (int b = 0; b < kBitsPerAxis; ++b) out |= ((x >> b) & 1u) << (3 * b);
  return out;
}

// Per vertex, its cell's index along the Morton curve.
std::vector<std::uint32_t> vertex_cells(const std::vector<std::array<double, 3>>& positions) {
  std::array<double, 3> low, high;
  low.fill(std::numeric_limits<double>::max());
  high.fill(std::numeric_limits<double>::lowest());
  for (const auto& p : positions) {
    for (int a = 0; a < 3; ++a) {
      low[a] = std::min(low[a], p[a]);
      high[a] = std::max(high[a], p[a]);
    }
  }
  std::array<double, 3> scale;
  for (int a = 0; a < 3; ++a) {
    const double extent = high[a] - low[a];
    // A flat or non-finite extent puts every vertex in the first cell along that axis.
    scale[a] = extent > 0 && extent < std::numeric_limits<double>::infinity()
                   ? (1u << kBitsPerAxis) / extent
                   : 0;
  }
  constexpr double kLast = (1u << kBitsPerAxis) - 1;
  std::vector<std::uint32_t> cell(positions.size());
  for (std::size_t v = 0; v < positions.size(); ++v) {
    std::uint32_t code = 0;
    for (int a = 0; a < 3; ++a) {
      // NaN fails q >= 0: such a vertex goes to the first cell (the order is only a hint).
      const double q = (positions[v][a] - low[a]) * scale[a];
      code |= spread(static_cast<std::uint32_t>(q >= 0 ? std::min(q, kLast) : 0)) << a;
    }
    cell[v] = code;
  }
  return cell;
}

// A stable counting sort of the items 0..key.size()-1 by key < kCells: the items in order.
std::vector<std::uint32_t> sorted_by_cell(const std::vector<std::uint32_t>& key) {
  std::vector<std::uint32_t> start(kCells + 1, 0);
  for (std::uint32_t k : key) ++start[k + 1];
  for (std::uint32_t c = 0; c < kCells; ++c) start[c + 1] += start[c];
  std::vector<std::uint32_t> order(key.size());
  for (std::uint32_t i = 0; i < key.size(); ++i) order[start[key[i]]++] = i;
  return order;
}

}  // namespace

SpatialMesh spatially_ordered(const TriangleMesh& mesh) {
  SpatialMesh out;
  const std::vector<std::uint32_t> cell = vertex_cells(mesh.positions);
  out.input_vertex = sorted_by_cell(cell);
  std::vector<VertexId> new_id(mesh.positions.size());
  out.mesh.positions.resize(mesh.positions.size());
  for (VertexId v = 0; v < out.input_vertex.size(); ++v) {
    new_id[out.input_vertex[v]] = v;
    out.mesh.positions[v] = mesh.positions[out.input_vertex[v]];
  }
  std::vector<std::uint32_t> face_cell(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) face_cell[t] = cell[mesh.triangles[t][0]];
  const std::vector<std::uint32_t> faces = sorted_by_cell(face_cell);
  out.mesh.triangles.resize(mesh.triangles.size());
  for (std::size_t t = 0; t < faces.size(); ++t) {
    const auto& corners = mesh.triangles[faces[t]];
    out.mesh.triangles[t] = {new_id[corners[0]], new_id[corners[1]], new_id[corners[2]]};
  }
  return out;
}

}  // namespace petersen::lrs
