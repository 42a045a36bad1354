#pragma once
// Test files of triangle strips: a PLY `tristrips` element written from strips given by hand, in
// any encoding, byte order and index type, and the strips of a grid with the triangles they stand
// for worked out by hand (not by the reader's rule), so that a test can compare the two.

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "petersen/mesh/mesh.hpp"

namespace petersen::testing {

enum class PlyEncoding { ascii, little, big };

/// A PLY of `positions` (float x y z) and one tristrips record per entry of `records` (each a
/// vertex_indices list, -1 between strips), the list counted by `count_type` and its items of
/// `index_type` ("int", "uint", "short", "ushort", "char" or "uchar"; -1 is written as the
/// type's all-ones value in an unsigned type, as strip writers do).
inline std::string tristrip_ply(const Positions& positions,
                                const std::vector<std::vector<std::int64_t>>& records,
                                PlyEncoding encoding, const std::string& count_type = "int",
                                const std::string& index_type = "int") {
  const char* format = encoding == PlyEncoding::ascii    ? "ascii"
                       : encoding == PlyEncoding::little ? "binary_little_endian"
                                                         : "binary_big_endian";
  std::string out = std::string("ply\nformat ") + format + " 1.0\nelement vertex " +
                    std::to_string(positions.size()) +
                    "\nproperty float x\nproperty float y\nproperty float z\nelement tristrips " +
                    std::to_string(records.size()) + "\nproperty list " + count_type + " " +
                    index_type + " vertex_indices\nend_header\n";
  const auto size_of = [](const std::string& type) -> std::size_t {
    return type == "char" || type == "uchar" ? 1 : type == "short" || type == "ushort" ? 2 : 4;
  };
  auto put = [&](std::uint64_t bits, std::size_t size) {
    for (std::size_t k = 0; k < size; ++k) {
      const std::size_t byte = encoding == PlyEncoding::big ? size - 1 - k : k;
      out += static_cast<char>((bits >> (8 * byte)) & 0xFF);
    }
  };
  for (const auto& p : positions) {
    if (encoding == PlyEncoding::ascii) {
      out += std::to_string(float(p[0])) + " " + std::to_string(float(p[1])) + " " +
             std::to_string(float(p[2])) + "\n";
      continue;
    }
    for (double x : p) {
      const float f = static_cast<float>(x);
      std::uint32_t bits;
      std::memcpy(&bits, &f, 4);
      put(bits, 4);
    }
  }
  const bool is_unsigned = index_type[0] == 'u';
  for (const auto& record : records) {
    if (encoding == PlyEncoding::ascii) {
      out += std::to_string(record.size());
      for (std::int64_t v : record) {
        const std::int64_t written =
            v == -1 && is_unsigned ? std::int64_t((1ull << (8 * size_of(index_type))) - 1) : v;
        out += " " + std::to_string(written);
      }
      out += "\n";
      continue;
    }
    put(record.size(), size_of(count_type));
    for (std::int64_t v : record) put(static_cast<std::uint64_t>(v), size_of(index_type));
  }
  return out;
}

/// A grid of nx by ny cells on (nx + 1)(ny + 1) vertices (vertex i + (nx + 1) j at column i, row
/// j, moved and lifted a little so that quads differ in shape): `faces` its two triangles per cell,
/// row by row, written out by hand, and `records` the same triangles as strips, one per row,
/// alternately ended by -1 and joined to the next by repeated vertices (four triangles repeating a
/// vertex each), over two records.
struct StripGrid {
  PolygonMesh faces;
  std::vector<std::vector<std::int64_t>> records;
  std::uint64_t joins = 0;  ///< triangles repeating a vertex in the strips
};

inline StripGrid strip_grid(std::uint32_t nx, std::uint32_t ny) {
  StripGrid grid;
  const auto v = [&](std::uint32_t i, std::uint32_t j) { return VertexId(i + (nx + 1) * j); };
  for (std::uint32_t j = 0; j <= ny; ++j) {
    for (std::uint32_t i = 0; i <= nx; ++i) {
      // Multiples of 1/64: exact as floats and in the six decimals an ascii file is written with.
      const auto exact = [](double x) { return std::round(64 * x) / 64; };
      grid.faces.positions.push_back({exact(i + 0.1 * std::sin(3.0 * j)), double(j),
                                      exact(0.3 * std::sin(double(i)) * std::cos(0.7 * j))});
    }
  }
  // The strip of row j runs v(0, j+1), v(0, j), v(1, j+1), v(1, j), ...: its triangles are, per
  // cell i, (v(i, j+1), v(i, j), v(i+1, j+1)) and then, the second of the pair turned back to the
  // same orientation, (v(i+1, j+1), v(i, j), v(i+1, j)).
  grid.records.resize(2);
  for (std::uint32_t j = 0; j < ny; ++j) {
    for (std::uint32_t i = 0; i < nx; ++i) {
      const std::array<VertexId, 3> t1{v(i, j + 1), v(i, j), v(i + 1, j + 1)};
      const std::array<VertexId, 3> t2{v(i + 1, j + 1), v(i, j), v(i + 1, j)};
      grid.faces.add_face(t1);
      grid.faces.add_face(t2);
    }
    std::vector<std::int64_t>& record = grid.records[j < ny / 2 ? 0 : 1];
    if (!record.empty() && record.back() != -1) {
      // The last vertex again, then the first of this row: with the row's own first vertex, an
      // even number of items before it, so that its first triangle is an even one of the strip.
      const std::int64_t last = record.back();
      record.insert(record.end(), {last, std::int64_t(v(0, j + 1))});
      grid.joins += 4;
    }
    for (std::uint32_t i = 0; i <= nx; ++i) {
      record.push_back(v(i, j + 1));
      record.push_back(v(i, j));
    }
    if (j % 2 == 0) record.push_back(-1);  // odd rows are joined to the next in their record
  }
  return grid;
}

}  // namespace petersen::testing
