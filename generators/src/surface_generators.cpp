#include "petersen/generators/surface_generators.hpp"

#include <algorithm>
#include <array>
#include <unordered_map>
#include <vector>

#include "petersen/graph/seeded_random.hpp"
#include "petersen/mesh/edge_groups.hpp"

namespace petersen {

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

PolygonMesh plate_mesh(const PlateShape& shape) {
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

  PolygonMesh mesh;
  mesh.corners.reserve(3 * shape.triangle_count());
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
                const int order[2][6] = {{0, 2, 1, 0, 3, 2}, {0, 1, 2, 0, 2, 3}};
                for (int k : order[side]) mesh.corners.push_back(quad[k]);
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

PolygonMesh voxel_plate(const PlateSpec& spec) {
  return plate_mesh(uniform_plate(spec.holes_x, spec.holes_y, spec.dents, spec.subdivision));
}

namespace {

// 1-to-3 splits of random triangles, the new vertex at the centroid: triangle t = (a, b, c)
// becomes (a, b, m) and (b, c, m), (c, a, m) are appended.
void split_triangles(PolygonMesh& mesh, std::uint32_t splits, SeededRandom& rng) {
  auto& corners = mesh.corners;
  corners.reserve(corners.size() + 6 * std::size_t{splits});
  mesh.positions.reserve(mesh.positions.size() + splits);
  for (std::uint32_t k = 0; k < splits; ++k) {
    const FaceId t = static_cast<FaceId>(rng.below64(mesh.face_count()));
    const VertexId a = corners[3 * t], b = corners[3 * t + 1], c = corners[3 * t + 2];
    std::array<double, 3> centroid{};
    for (int d = 0; d < 3; ++d) {
      centroid[d] = (mesh.positions[a][d] + mesh.positions[b][d] + mesh.positions[c][d]) / 3;
    }
    const VertexId m = static_cast<VertexId>(mesh.positions.size());
    mesh.positions.push_back(centroid);
    corners[3 * t + 2] = m;
    for (VertexId v : {b, c, m, c, a, m}) corners.push_back(v);
  }
}

// twin[h]: the halfedge running back along halfedge h's edge (halfedge 3t + k runs from corner k
// of triangle t to corner k + 1). 4 bytes per halfedge, where a map of directed edges costs ten
// times that and a hash per step. Throws MeshError unless every edge has two halfedges.
std::pmr::vector<std::uint32_t> twins(const PolygonMesh& mesh) {
  std::pmr::vector<std::uint32_t> twin(mesh.corners.size());
  const EdgeGroups groups = PolygonHalfedges(mesh).group();
  for_each_edge_group(groups, [&](std::uint32_t first, std::uint32_t end) {
    if (end - first != 2) throw MeshError("randomize_triangulation: the mesh is not closed");
    twin[groups.entries[first][1]] = groups.entries[first + 1][1];
    twin[groups.entries[first + 1][1]] = groups.entries[first][1];
  });
  return twin;
}

// About `flips` random edge flips on the halfedges of a closed triangulation, each kept only when
// the triangulation stays simplicial.
void flip_edges(PolygonMesh& mesh, std::uint32_t flips, SeededRandom& rng) {
  auto& corners = mesh.corners;
  std::pmr::vector<std::uint32_t> twin = twins(mesh);
  auto from = [&](std::uint32_t h) { return corners[h]; };
  auto to = [&](std::uint32_t h) { return corners[h - h % 3 + (h % 3 + 1) % 3]; };
  auto next = [](std::uint32_t h) { return h - h % 3 + (h % 3 + 1) % 3; };
  auto prev = [](std::uint32_t h) { return h - h % 3 + (h % 3 + 2) % 3; };
  // Whether the halfedge w -> z exists: a walk around w, from its halfedge `start`.
  auto has_halfedge = [&](std::uint32_t start, VertexId z) {
    std::uint32_t h = start;
    do {
      if (to(h) == z) return true;
      h = twin[prev(h)];
    } while (h != start);
    return false;
  };
  std::vector<std::uint32_t> degree(mesh.positions.size(), 0);
  for (VertexId v : corners) ++degree[v];
  const std::size_t face_count = mesh.face_count();
  for (std::uint32_t k = 0; k < flips; ++k) {
    const FaceId t = static_cast<FaceId>(rng.below64(face_count));
    const int corner = static_cast<int>(rng.below64(3));
    const std::uint32_t h = 3 * t + corner, g = twin[h];
    const FaceId t2 = g / 3;
    const VertexId u = from(h), v = to(h), w = from(prev(h)), z = from(prev(g));
    // Flip (u,v) to (w,z) only if (w,z) is not an edge already and u, v keep degree >= 3.
    if (w == z || degree[u] <= 3 || degree[v] <= 3 || has_halfedge(prev(h), z)) continue;
    // t = (u, v, w) and t2 = (v, u, z) bound the quad u, z, v, w (counter-clockwise); its other
    // diagonal gives (u, z, w) and (z, v, w), with the same orientation. The outer sides keep
    // their twins, which are told their new halfedges.
    const std::uint32_t vw = twin[next(h)], wu = twin[prev(h)], uz = twin[next(g)],
                        zv = twin[prev(g)];
    const std::uint32_t a = 3 * t, b = 3 * t2;
    corners[a] = u, corners[a + 1] = z, corners[a + 2] = w;
    corners[b] = z, corners[b + 1] = v, corners[b + 2] = w;
    auto join = [&](std::uint32_t x, std::uint32_t y) {
      twin[x] = y;
      twin[y] = x;
    };
    join(a, uz);
    join(a + 1, b + 2);
    join(a + 2, wu);
    join(b, zv);
    join(b + 1, vw);
    --degree[u];
    --degree[v];
    ++degree[w];
    ++degree[z];
  }
}

}  // namespace

PolygonMesh randomize_triangulation(PolygonMesh mesh, std::uint32_t splits, std::uint32_t flips,
                                    std::uint64_t seed) {
  if (!mesh.all_triangles()) {
    throw MeshError("randomize_triangulation: every face must be a triangle");
  }
  // SeededRandom's draws are fixed by its code, so a seed gives the same mesh on every platform
  // and library (the example's regeneration command in README.md relies on it).
  SeededRandom rng(seed);
  split_triangles(mesh, splits, rng);
  flip_edges(mesh, flips, rng);
  return mesh;
}

PolygonMesh random_closed_surface(std::uint32_t genus, std::uint32_t splits, std::uint32_t flips,
                                  std::uint64_t seed) {
  return randomize_triangulation(voxel_plate({genus, genus == 0 ? 0u : 1u, 1, false}), splits,
                                 flips, seed);
}

PolygonMesh spatially_ordered(const PolygonMesh& mesh) {
  if (!mesh.all_triangles()) throw MeshError("spatially_ordered: every face must be a triangle");
  std::array<double, 3> low{}, high{};
  for (int d = 0; d < 3; ++d) {
    low[d] = mesh.positions.empty() ? 0 : mesh.positions[0][d];
    high[d] = low[d];
  }
  for (const auto& p : mesh.positions) {
    for (int d = 0; d < 3; ++d) {
      low[d] = std::min(low[d], p[d]);
      high[d] = std::max(high[d], p[d]);
    }
  }
  // 21 bits per axis, interleaved: the key of a centroid.
  auto spread = [](std::uint64_t x) {
    x &= 0x1FFFFF;
    x = (x | x << 32) & 0x1F00000000FFFFull;
    x = (x | x << 16) & 0x1F0000FF0000FFull;
    x = (x | x << 8) & 0x100F00F00F00F00Full;
    x = (x | x << 4) & 0x10C30C30C30C30C3ull;
    x = (x | x << 2) & 0x1249249249249249ull;
    return x;
  };
  const std::size_t face_count = mesh.face_count();
  std::pmr::vector<std::array<std::uint64_t, 2>> order(face_count);
  for (std::size_t t = 0; t < face_count; ++t) {
    std::uint64_t key = 0;
    for (int d = 0; d < 3; ++d) {
      double c = 0;
      for (int k = 0; k < 3; ++k) c += mesh.positions[mesh.corners[3 * t + k]][d];
      const double extent = high[d] - low[d];
      const double unit = extent > 0 ? (c / 3 - low[d]) / extent : 0;
      key |= spread(static_cast<std::uint64_t>(std::clamp(unit, 0.0, 1.0) * 0x1FFFFF)) << d;
    }
    order[t] = {key, t};
  }
  std::sort(order.begin(), order.end());
  PolygonMesh out;
  out.corners.resize(mesh.corners.size());
  std::pmr::vector<VertexId> renamed(mesh.positions.size(), 0xFFFFFFFFu);
  out.positions.reserve(mesh.positions.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    const std::size_t t = order[i][1];
    for (int k = 0; k < 3; ++k) {
      const VertexId v = mesh.corners[3 * t + k];
      VertexId& id = renamed[v];
      if (id == 0xFFFFFFFFu) {
        id = static_cast<VertexId>(out.positions.size());
        out.positions.push_back(mesh.positions[v]);
      }
      out.corners[3 * i + k] = id;
    }
  }
  // Vertices no triangle uses keep their place at the end, in their order.
  for (VertexId v = 0; v < mesh.positions.size(); ++v) {
    if (renamed[v] == 0xFFFFFFFFu) out.positions.push_back(mesh.positions[v]);
  }
  return out;
}

}  // namespace petersen
