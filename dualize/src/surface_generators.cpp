#include "petersen/dualize/surface_generators.hpp"

#include <random>
#include <unordered_map>

namespace petersen {

namespace {

struct Lattice {
  std::uint32_t nx, ny, nz;  // lattice points per axis
  std::vector<VertexId> index;
  TriangleMesh* mesh;
  std::uint32_t scale;

  VertexId vertex(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
    VertexId& id = index[(std::size_t{z} * ny + y) * nx + x];
    if (id == 0xFFFFFFFFu) {
      id = static_cast<VertexId>(mesh->positions.size());
      mesh->positions.push_back({double(x) / scale, double(y) / scale, double(z) / scale});
    }
    return id;
  }
};

}  // namespace

TriangleMesh voxel_plate(const PlateSpec& spec) {
  const std::uint32_t cx = 2 * spec.holes_x + 1, cy = 2 * spec.holes_y + 1, cz = spec.dents ? 2 : 1;
  const std::uint32_t s = std::max<std::uint32_t>(spec.subdivision, 1);
  auto filled = [&](std::int64_t x, std::int64_t y, std::int64_t z) {
    if (x < 0 || y < 0 || z < 0 || x >= cx || y >= cy || z >= cz) return false;
    bool hole_column = x % 2 == 1 && y % 2 == 1;
    return !(hole_column && (!spec.dents || z == 1));
  };
  TriangleMesh mesh;
  Lattice lattice{cx * s + 1, cy * s + 1, cz * s + 1, {}, &mesh, s};
  lattice.index.assign(std::size_t{lattice.nx} * lattice.ny * lattice.nz, 0xFFFFFFFFu);
  for (std::int64_t z = 0; z < cz; ++z) {
    for (std::int64_t y = 0; y < cy; ++y) {
      for (std::int64_t x = 0; x < cx; ++x) {
        if (!filled(x, y, z)) continue;
        const std::int64_t cell[3] = {x, y, z};
        for (int axis = 0; axis < 3; ++axis) {
          for (int side : {-1, 1}) {
            std::int64_t n[3] = {x, y, z};
            n[axis] += side;
            if (filled(n[0], n[1], n[2])) continue;
            // The face lies at cell[axis] (+1 for side +1); (b, c, axis) is right-handed, so
            // corners in (b, c) order are counter-clockwise seen along +axis.
            const int b = (axis + 1) % 3, c = (axis + 2) % 3;
            for (std::uint32_t i = 0; i < s; ++i) {
              for (std::uint32_t j = 0; j < s; ++j) {
                VertexId quad[4];
                const std::uint32_t du[4] = {0, 1, 1, 0}, dv[4] = {0, 0, 1, 1};
                for (int k = 0; k < 4; ++k) {
                  std::uint32_t p[3];
                  p[axis] = static_cast<std::uint32_t>((cell[axis] + (side > 0)) * s);
                  p[b] = static_cast<std::uint32_t>(cell[b] * s + i + du[k]);
                  p[c] = static_cast<std::uint32_t>(cell[c] * s + j + dv[k]);
                  quad[k] = lattice.vertex(p[0], p[1], p[2]);
                }
                if (side > 0) {
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

TriangleMesh randomize_triangulation(TriangleMesh mesh, std::uint32_t splits, std::uint32_t flips,
                                     std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  auto& tris = mesh.triangles;
  for (std::uint32_t k = 0; k < splits; ++k) {
    FaceId t = static_cast<FaceId>(rng() % tris.size());
    auto [a, b, c] = tris[t];
    std::array<double, 3> centroid{};
    for (int d = 0; d < 3; ++d) {
      centroid[d] = (mesh.positions[a][d] + mesh.positions[b][d] + mesh.positions[c][d]) / 3;
    }
    VertexId m = static_cast<VertexId>(mesh.positions.size());
    mesh.positions.push_back(centroid);
    tris[t] = {a, b, m};
    tris.push_back({b, c, m});
    tris.push_back({c, a, m});
  }
  // Edge flips: the directed edge (u, v) of one triangle meets (v, u) of the other.
  auto key = [](VertexId u, VertexId v) { return (std::uint64_t{u} << 32) | v; };
  std::unordered_map<std::uint64_t, FaceId> face_of;  // directed edge -> triangle holding it
  std::vector<std::uint32_t> degree(mesh.positions.size(), 0);
  for (FaceId t = 0; t < tris.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      face_of[key(tris[t][k], tris[t][(k + 1) % 3])] = t;
      ++degree[tris[t][k]];
    }
  }
  auto corner_after = [&](FaceId t, VertexId u, VertexId v) {
    for (int k = 0; k < 3; ++k)
      if (tris[t][k] == u && tris[t][(k + 1) % 3] == v) return tris[t][(k + 2) % 3];
    return VertexId{0xFFFFFFFFu};
  };
  for (std::uint32_t k = 0; k < flips; ++k) {
    FaceId t = static_cast<FaceId>(rng() % tris.size());
    int corner = static_cast<int>(rng() % 3);
    VertexId u = tris[t][corner], v = tris[t][(corner + 1) % 3];
    VertexId w = tris[t][(corner + 2) % 3];
    FaceId t2 = face_of.at(key(v, u));
    VertexId z = corner_after(t2, v, u);
    // Flip (u,v) to (w,z) only if (w,z) is not an edge already and u, v keep degree >= 3.
    if (w == z || degree[u] <= 3 || degree[v] <= 3 || face_of.count(key(w, z))) continue;
    // t = (u, v, w) and t2 = (v, u, z) bound the quad u, z, v, w (counter-clockwise); its other
    // diagonal gives (u, z, w) and (z, v, w), with the same orientation.
    for (int j = 0; j < 3; ++j) {
      face_of.erase(key(tris[t][j], tris[t][(j + 1) % 3]));
      face_of.erase(key(tris[t2][j], tris[t2][(j + 1) % 3]));
    }
    tris[t] = {u, z, w};
    tris[t2] = {z, v, w};
    for (FaceId f : {t, t2})
      for (int j = 0; j < 3; ++j) face_of[key(tris[f][j], tris[f][(j + 1) % 3])] = f;
    --degree[u];
    --degree[v];
    ++degree[w];
    ++degree[z];
  }
  return mesh;
}

TriangleMesh random_closed_surface(std::uint32_t genus, std::uint32_t splits, std::uint32_t flips,
                                   std::uint64_t seed) {
  return randomize_triangulation(voxel_plate({genus, genus == 0 ? 0u : 1u, 1, false}), splits,
                                 flips, seed);
}

}  // namespace petersen
