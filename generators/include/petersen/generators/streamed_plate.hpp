#pragma once
// A closed plate of any size, produced vertex by vertex and triangle by triangle without holding
// it: the input of the out-of-core tests and benchmarks (10^9 triangles).

#include <cmath>
#include <cstdint>

#include "petersen/mesh/mesh.hpp"

namespace petersen {

/// A flat tube closed at both ends: `rows` rows of `around` unit squares (each cut into two
/// triangles) wrapped around a flattened ellipse, and a fan of `around` triangles closing each
/// end. Closed, consistently oriented, genus 0; squares are cut along either diagonal by a fixed
/// hash (plate_diagonal_flipped). Triangles are stored row after row, so that a range of them is a
/// band of rows, as a scanner's order is spatially coherent.
struct StreamedPlate {
  std::uint32_t around = 3;
  std::uint32_t rows = 1;

  std::uint64_t triangles() const { return 2 * std::uint64_t{around} * (std::uint64_t{rows} + 1); }
  std::uint64_t vertices() const { return std::uint64_t{around} * (std::uint64_t{rows} + 1) + 2; }
};

/// The plate with about `triangles` triangles (at least 12), its rows 16 times as many as its
/// squares around, as a long plate. Throws std::invalid_argument past 2^32 - 2 triangles.
StreamedPlate streamed_plate_of_size(std::uint64_t triangles);

/// Calls vertex(x, y, z) for each vertex in id order: the first fan's centre, the rows' rings of
/// `around` vertices, the last fan's centre. O(1) memory.
template <class VertexSink>
void for_each_plate_vertex(const StreamedPlate& plate, VertexSink&& vertex) {
  const double width = plate.around / 4.0, thickness = width / 16.0;
  vertex(-1.0f, 0.0f, 0.0f);
  for (std::uint64_t r = 0; r <= plate.rows; ++r) {
    for (std::uint32_t j = 0; j < plate.around; ++j) {
      const double angle = 2 * 3.14159265358979323846 * j / plate.around;
      vertex(float(r), float(width * std::cos(angle)), float(thickness * std::sin(angle)));
    }
  }
  vertex(float(plate.rows) + 1.0f, 0.0f, 0.0f);
}

/// Whether square `square` (row · around + column) is cut along its other diagonal: a fixed hash,
/// so that vertex degrees vary and the pairable graph has odd cycles, as a scanner's
/// triangulation has (a grid cut along one diagonal everywhere has a bipartite pairable graph,
/// whose parts leave unpaired triangles of one colour at every cut).
inline bool plate_diagonal_flipped(std::uint64_t square) {
  square = (square ^ (square >> 30)) * 0xbf58476d1ce4e5b9ull;
  square = (square ^ (square >> 27)) * 0x94d049bb133111ebull;
  return ((square ^ (square >> 31)) & 1u) != 0;
}

/// Calls triangle(a, b, c) for each triangle in face order: the first fan, the rows, the last fan,
/// all running the same way around the surface. O(1) memory.
template <class TriangleSink>
void for_each_plate_triangle(const StreamedPlate& plate, TriangleSink&& triangle) {
  const std::uint32_t n = plate.around;
  auto ring = [&](std::uint64_t r, std::uint32_t j) {
    return static_cast<VertexId>(1 + r * n + (j == n ? 0 : j));
  };
  for (std::uint32_t j = 0; j < n; ++j) triangle(VertexId{0}, ring(0, j + 1), ring(0, j));
  for (std::uint64_t r = 0; r < plate.rows; ++r) {
    for (std::uint32_t j = 0; j < n; ++j) {
      if (plate_diagonal_flipped(r * n + j)) {
        triangle(ring(r, j), ring(r, j + 1), ring(r + 1, j));
        triangle(ring(r, j + 1), ring(r + 1, j + 1), ring(r + 1, j));
      } else {
        triangle(ring(r, j), ring(r + 1, j + 1), ring(r + 1, j));
        triangle(ring(r, j), ring(r, j + 1), ring(r + 1, j + 1));
      }
    }
  }
  const VertexId last = static_cast<VertexId>(plate.vertices() - 1);
  for (std::uint32_t j = 0; j < n; ++j)
    triangle(last, ring(plate.rows, j), ring(plate.rows, j + 1));
}

}  // namespace petersen
