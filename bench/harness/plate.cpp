#include "plate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>
#include <vector>

namespace petersen::bench {

namespace {

// Lattice offsets of the cell boundaries along one axis: cells alternate wall, hole, ..., wall.
std::vector<std::uint32_t> cell_offsets(std::uint32_t holes, std::uint32_t wall,
                                        std::uint32_t hole) {
  std::vector<std::uint32_t> offsets{0};
  for (std::uint32_t i = 0; i < 2 * holes + 1; ++i)
    offsets.push_back(offsets.back() + (i % 2 ? hole : wall));
  return offsets;
}

}  // namespace

std::uint64_t PlateShape::triangle_count() const {
  const std::uint64_t x = std::uint64_t{holes_x + 1} * wall_x + std::uint64_t{holes_x} * hole_x;
  const std::uint64_t y = std::uint64_t{holes_y + 1} * wall_y + std::uint64_t{holes_y} * hole_y;
  const std::uint64_t holes = std::uint64_t{holes_x} * holes_y;
  const std::uint64_t hole_perimeter = 2 * std::uint64_t{hole_x + hole_y};
  // Unit squares: bottom and top (less the holes' openings, or plus the dents' floors), the
  // outer walls, and the walls of every hole or dent; two triangles each.
  const std::uint64_t squares =
      dents
          ? 2 * x * y + 2 * (x + y) * (thickness + dent_depth) + hole_perimeter * dent_depth * holes
          : 2 * (x * y - holes * hole_x * hole_y) + 2 * (x + y) * thickness +
                hole_perimeter * thickness * holes;
  return 2 * squares;
}

std::uint64_t PlateShape::genus() const {
  return dents ? 0 : std::uint64_t{holes_x} * holes_y;
}

TriangleMesh plate_mesh(const PlateShape& shape) {
  const std::array<std::vector<std::uint32_t>, 3> offsets = {
      cell_offsets(shape.holes_x, shape.wall_x, shape.hole_x),
      cell_offsets(shape.holes_y, shape.wall_y, shape.hole_y),
      shape.dents
          ? std::vector<std::uint32_t>{0, shape.thickness, shape.thickness + shape.dent_depth}
          : std::vector<std::uint32_t>{0, shape.thickness}};
  const std::int64_t cells[3] = {std::int64_t(offsets[0].size()) - 1,
                                 std::int64_t(offsets[1].size()) - 1,
                                 std::int64_t(offsets[2].size()) - 1};
  auto filled = [&](const std::int64_t c[3]) {
    for (int axis = 0; axis < 3; ++axis)
      if (c[axis] < 0 || c[axis] >= cells[axis]) return false;
    const bool hole_column = c[0] % 2 == 1 && c[1] % 2 == 1;
    return !(hole_column && (!shape.dents || c[2] == 1));
  };

  TriangleMesh mesh;
  mesh.triangles.reserve(shape.triangle_count());
  mesh.positions.reserve(shape.triangle_count() / 2 + 2);
  std::unordered_map<std::uint64_t, VertexId> vertex_at;
  vertex_at.reserve(shape.triangle_count() / 2 + 2);
  auto vertex = [&](const std::uint32_t p[3]) {
    const std::uint64_t key = (std::uint64_t{p[0]} << 42) | (std::uint64_t{p[1]} << 21) | p[2];
    auto [it, inserted] = vertex_at.try_emplace(key, static_cast<VertexId>(mesh.positions.size()));
    if (inserted) mesh.positions.push_back({double(p[0]), double(p[1]), double(p[2])});
    return it->second;
  };

  std::int64_t c[3];
  for (c[2] = 0; c[2] < cells[2]; ++c[2]) {
    for (c[1] = 0; c[1] < cells[1]; ++c[1]) {
      for (c[0] = 0; c[0] < cells[0]; ++c[0]) {
        if (!filled(c)) continue;
        for (int axis = 0; axis < 3; ++axis) {
          for (int side : {0, 1}) {
            std::int64_t n[3] = {c[0], c[1], c[2]};
            n[axis] += side ? 1 : -1;
            if (filled(n)) continue;
            // The face lies at the cell's lower or upper boundary along `axis`; (b, c, axis) is
            // right-handed, so corners in (b, c) order run counter-clockwise seen along +axis.
            const int b = (axis + 1) % 3, d = (axis + 2) % 3;
            const std::uint32_t b0 = offsets[b][c[b]], b1 = offsets[b][c[b] + 1];
            const std::uint32_t d0 = offsets[d][c[d]], d1 = offsets[d][c[d] + 1];
            for (std::uint32_t i = b0; i < b1; ++i) {
              for (std::uint32_t j = d0; j < d1; ++j) {
                VertexId quad[4];
                const std::uint32_t di[4] = {0, 1, 1, 0}, dj[4] = {0, 0, 1, 1};
                for (int k = 0; k < 4; ++k) {
                  std::uint32_t p[3];
                  p[axis] = offsets[axis][c[axis] + side];
                  p[b] = i + di[k];
                  p[d] = j + dj[k];
                  quad[k] = vertex(p);
                }
                if (side) {
                  mesh.triangles.push_back({quad[0], quad[1], quad[2]});
                  mesh.triangles.push_back({quad[0], quad[2], quad[3]});
                } else {
                  mesh.triangles.push_back({quad[0], quad[2], quad[1]});
                  mesh.triangles.push_back({quad[0], quad[3], quad[2]});
                }
              }
            }
          }
        }
      }
    }
  }
  return mesh;
}

PlateShape uniform_plate(std::uint32_t holes_x, std::uint32_t holes_y, bool dents,
                         std::uint32_t units) {
  return {holes_x, holes_y, units, units, units, units, units, dents ? units : 0, dents};
}

PlateShape fit_plate(std::uint32_t holes_x, std::uint32_t holes_y, bool dents, std::uint64_t target,
                     double tolerance, std::uint32_t max_units) {
  // The isotropic width nearest the target bounds the in-plane widths searched (±2 around it).
  std::uint32_t s = 1;
  while (s < max_units && uniform_plate(holes_x, holes_y, dents, s + 1).triangle_count() <= target)
    ++s;
  const std::uint32_t lo = s > 2 ? s - 2 : 1, hi = std::min(s + 2, max_units);
  const std::uint32_t depth_hi = std::min(max_units, std::max<std::uint32_t>(10, 2 * hi));

  PlateShape best = uniform_plate(holes_x, holes_y, dents, s);
  auto error = [&](const PlateShape& p) {
    return std::abs(double(p.triangle_count()) - double(target)) / double(target);
  };
  auto spread = [](const PlateShape& p) {
    const auto [mn, mx] = std::minmax({p.wall_x, p.hole_x, p.wall_y, p.hole_y});
    return mx - mn;
  };
  // Within tolerance: fewer distinct widths first, then nearer; outside it: nearer.
  auto better = [&](const PlateShape& p, const PlateShape& q) {
    const bool p_in = error(p) <= tolerance, q_in = error(q) <= tolerance;
    if (p_in != q_in) return p_in;
    if (p_in && spread(p) != spread(q)) return spread(p) < spread(q);
    return error(p) < error(q);
  };
  PlateShape p{holes_x, holes_y, 0, 0, 0, 0, 0, 0, dents};
  for (p.wall_x = lo; p.wall_x <= hi; ++p.wall_x)
    for (p.hole_x = lo; p.hole_x <= hi; ++p.hole_x)
      for (p.wall_y = lo; p.wall_y <= hi; ++p.wall_y)
        for (p.hole_y = lo; p.hole_y <= hi; ++p.hole_y) {
          const auto [mn, mx] = std::minmax({p.wall_x, p.hole_x, p.wall_y, p.hole_y});
          if (mx > 2 * mn) continue;
          for (p.thickness = 1; p.thickness <= depth_hi; ++p.thickness)
            for (p.dent_depth = dents ? 1 : 0; p.dent_depth <= (dents ? depth_hi : 0);
                 ++p.dent_depth)
              if (better(p, best)) best = p;
        }
  return best;
}

}  // namespace petersen::bench
