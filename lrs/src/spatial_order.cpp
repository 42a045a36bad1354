#include "spatial_order.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace petersen::lrs {

namespace {

// The grid: 2^bits cells per axis, so that a cell holds a few hundred faces, whose halfedges fit
// in the L2 cache; within a cell the order is the input's and barely matters (measured on
// armadillo-sub2: 3, 4 and 6 bits alike; on the A3 plate, whose input order is already local, 6
// bits cost 5-10 % more than 4). At most 7 bits: the counting sort's 2^21 buckets.
int bits_per_axis(std::size_t faces) {
  constexpr double kFacesPerCell = 384;
  const double cells = std::max(1.0, static_cast<double>(faces) / kFacesPerCell);
  return std::clamp(static_cast<int>(std::lround(std::log2(cells) / 3)), 1, 7);
}

// The low `bits` bits of x, spread to every third position.
std::uint32_t spread(std::uint32_t x, int bits) {
  std::uint32_t out = 0;
  for (int b = 0; b < bits; ++b) out |= ((x >> b) & 1u) << (3 * b);
  return out;
}

// Per vertex, its cell's index along the Morton curve.
std::pmr::vector<std::uint32_t> vertex_cells(const Positions& positions, int bits) {
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
    scale[a] =
        extent > 0 && extent < std::numeric_limits<double>::infinity() ? (1u << bits) / extent : 0;
  }
  const double last = (1u << bits) - 1;
  std::pmr::vector<std::uint32_t> cell(positions.size());
  for (std::size_t v = 0; v < positions.size(); ++v) {
    std::uint32_t code = 0;
    for (int a = 0; a < 3; ++a) {
      // NaN fails q >= 0: such a vertex goes to the first cell (the order is only a hint).
      const double q = (positions[v][a] - low[a]) * scale[a];
      code |= spread(static_cast<std::uint32_t>(q >= 0 ? std::min(q, last) : 0), bits) << a;
    }
    cell[v] = code;
  }
  return cell;
}

// A stable counting sort of the items 0..key.size()-1 by key < cells: the items in order.
std::pmr::vector<std::uint32_t> sorted_by_cell(const std::pmr::vector<std::uint32_t>& key,
                                               std::uint32_t cells) {
  std::vector<std::uint32_t> start(cells + 1, 0);
  for (std::uint32_t k : key) ++start[k + 1];
  for (std::uint32_t c = 0; c < cells; ++c) start[c + 1] += start[c];
  std::pmr::vector<std::uint32_t> order(key.size());
  for (std::uint32_t i = 0; i < key.size(); ++i) order[start[key[i]]++] = i;
  return order;
}

}  // namespace

std::pmr::vector<VertexId> spatial_vertex_order(const Positions& positions,
                                                std::size_t face_count) {
  const int bits = bits_per_axis(face_count);
  return sorted_by_cell(vertex_cells(positions, bits), 1u << (3 * bits));
}

SpatialMesh spatially_ordered(const PolygonMesh& mesh) {
  SpatialMesh out;
  const std::size_t triangles = mesh.face_count();
  const int bits = bits_per_axis(triangles);
  const std::uint32_t cells = 1u << (3 * bits);
  const std::pmr::vector<std::uint32_t> cell = vertex_cells(mesh.positions, bits);
  out.input_vertex = sorted_by_cell(cell, cells);
  std::vector<VertexId> new_id(mesh.positions.size());
  out.mesh.positions.resize(mesh.positions.size());
  for (VertexId v = 0; v < out.input_vertex.size(); ++v) {
    new_id[out.input_vertex[v]] = v;
    out.mesh.positions[v] = mesh.positions[out.input_vertex[v]];
  }
  std::pmr::vector<std::uint32_t> face_cell(triangles);
  for (std::size_t t = 0; t < triangles; ++t) face_cell[t] = cell[mesh.corners[3 * t]];
  const std::pmr::vector<std::uint32_t> faces = sorted_by_cell(face_cell, cells);
  out.mesh.corners.resize(3 * triangles);
  for (std::size_t t = 0; t < faces.size(); ++t) {
    for (std::size_t k = 0; k < 3; ++k) {
      out.mesh.corners[3 * t + k] = new_id[mesh.corners[3 * std::size_t{faces[t]} + k]];
    }
  }
  return out;
}

}  // namespace petersen::lrs
