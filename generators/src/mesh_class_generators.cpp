#include "petersen/generators/mesh_class_generators.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "petersen/generators/polygon_generators.hpp"
#include "petersen/graph/seeded_random.hpp"
#include "petersen/mesh/vec3.hpp"

namespace petersen {

namespace {

using Point = std::array<double, 3>;

// A uniform double in [0, 1) from the top 53 bits, the same on every standard library.
double unit(SeededRandom& rng) {
  return double(rng.next() >> 11) * 0x1p-53;
}

// The face's unit normal by Newell's method (any simple polygon, planar or not); +z when the
// face has no area.
Point face_normal(const PolygonMesh& mesh, FaceId f) {
  const Point n = vec3::newell_normal(mesh.positions, mesh.face(f));
  const double length = std::hypot(n[0], n[1], n[2]);
  if (!(length > 0) || !std::isfinite(length)) return {0, 0, 1};
  return {n[0] / length, n[1] / length, n[2] / length};
}

Point centroid(const PolygonMesh& mesh, FaceId f) {
  Point sum{0, 0, 0};
  for (VertexId v : mesh.face(f))
    for (int d = 0; d < 3; ++d) sum[d] += mesh.positions[v][d];
  for (double& x : sum) x /= double(mesh.arity(f));
  return sum;
}

// The coordinate axis the normal is closest to.
int dominant_axis(const Point& n) {
  int axis = 0;
  for (int d = 1; d < 3; ++d)
    if (std::abs(n[d]) > std::abs(n[axis])) axis = d;
  return axis;
}

// The lowest and highest value of coordinate d over the positions.
std::pair<double, double> extent(const PolygonMesh& mesh, int d) {
  double low = 0, high = 0;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const double x = mesh.positions[v][d];
    low = v == 0 ? x : std::min(low, x);
    high = v == 0 ? x : std::max(high, x);
  }
  return {low, high};
}

}  // namespace

PolygonMesh mobius_band(std::uint32_t u, std::uint32_t v) {
  if (u < 3 || v < 1) {
    throw std::invalid_argument("mobius_band: a " + std::to_string(u) + " x " + std::to_string(v) +
                                " strip repeats edges; it needs u >= 3 and v >= 1");
  }
  if (6 * std::uint64_t{u} * v > 0xFFFFFFFFull) {
    throw std::invalid_argument("mobius_band: more than 2^32 - 1 corners");
  }
  PolygonMesh mesh;
  mesh.positions.resize(std::size_t{u} * (v + 1));
  for (std::uint32_t j = 0; j <= v; ++j) {
    for (std::uint32_t i = 0; i < u; ++i) {
      // The classic embedding: at angle 2π the half twist maps width s to -s, the glue's j -> v -
      // j.
      const double theta = 2 * std::numbers::pi * i / u, s = double(j) / v - 0.5;
      const double radius = 1 + s * std::cos(theta / 2);
      mesh.positions[std::size_t{j} * u + i] = {radius * std::cos(theta), radius * std::sin(theta),
                                                s * std::sin(theta / 2)};
    }
  }
  auto id = [&](std::uint32_t i, std::uint32_t j) {
    return static_cast<VertexId>(i < u ? j * u + i : (v - j) * u);
  };
  mesh.corners.reserve(6 * std::size_t{u} * v);
  for (std::uint32_t j = 0; j < v; ++j) {
    for (std::uint32_t i = 0; i < u; ++i) {
      const VertexId p00 = id(i, j), p10 = id(i + 1, j), p01 = id(i, j + 1), p11 = id(i + 1, j + 1);
      mesh.corners.insert(mesh.corners.end(), {p00, p10, p11, p00, p11, p01});
    }
  }
  return mesh;
}

PolygonMesh quad_dominant_grid(const QuadDominantGrid& spec) {
  const PolygonMesh grid = jittered_grid({.nx = spec.nx,
                                          .ny = spec.ny,
                                          .jitter = spec.jitter,
                                          .torus = spec.torus,
                                          .seed = spec.seed});
  const std::uint32_t nx = spec.nx, ny = spec.ny, squares = nx * ny;
  const std::uint32_t columns = spec.torus ? nx : nx + 1, rows = spec.torus ? ny : ny + 1;
  auto vertex = [&](std::uint32_t x, std::uint32_t y) {
    return static_cast<VertexId>((y % rows) * columns + x % columns);
  };
  auto square_corners = [&](std::uint32_t q) {
    const std::uint32_t x = q % nx, y = q / nx;
    return std::array<VertexId, 4>{vertex(x, y), vertex(x + 1, y), vertex(x + 1, y + 1),
                                   vertex(x, y + 1)};
  };
  // The square right of q, or none at the open grid's right side.
  auto right_of = [&](std::uint32_t q) -> std::optional<std::uint32_t> {
    const std::uint32_t x = q % nx;
    if (x + 1 < nx) return q + 1;
    if (spec.torus) return q + 1 - nx;
    return std::nullopt;
  };
  SeededRandom rng(spec.seed ^ 0x5157ull);
  enum class Kind : std::uint8_t { quad, triangles, merged, absorbed, leftover_triangle };
  std::vector<Kind> kind(squares);
  for (Kind& k : kind) k = rng.below(16) < spec.triangle_squares ? Kind::triangles : Kind::quad;
  std::vector<std::vector<VertexId>> merged(squares);
  std::vector<FaceId> leftover(squares, kNoFace);  // the triangle a pentagon left in its square
  auto merge = [&](std::uint32_t count, Kind right_kind, auto make) {
    for (std::uint32_t tries = 0, made = 0; made < count && tries < 16 * count + 16; ++tries) {
      const std::uint32_t q = rng.below(squares);
      const auto r = right_of(q);
      if (!r || *r == q || kind[q] != Kind::quad || kind[*r] != right_kind) continue;
      merged[q] = make(q, *r);
      kind[q] = Kind::merged;
      kind[*r] = right_kind == Kind::quad ? Kind::absorbed : Kind::leftover_triangle;
      ++made;
    }
  };
  merge(spec.hexagons, Kind::quad, [&](std::uint32_t q, std::uint32_t r) {
    const auto p = square_corners(q), s = square_corners(r);
    return std::vector<VertexId>{p[0], p[1], s[1], s[2], p[2], p[3]};
  });
  merge(spec.pentagons, Kind::triangles, [&](std::uint32_t q, std::uint32_t r) {
    // The triangle of r on its left side (q's right side p1-p2) joins q; the other stays.
    const auto p = square_corners(q);
    for (FaceId t : {2 * r, 2 * r + 1}) {
      const auto c = grid.face(t);
      const bool on_side = std::find(c.begin(), c.end(), p[1]) != c.end() &&
                           std::find(c.begin(), c.end(), p[2]) != c.end();
      if (!on_side) continue;
      const VertexId apex =
          *std::find_if(c.begin(), c.end(), [&](VertexId w) { return w != p[1] && w != p[2]; });
      leftover[r] = t == 2 * r ? 2 * r + 1 : 2 * r;
      return std::vector<VertexId>{p[0], p[1], apex, p[2], p[3]};
    }
    throw std::logic_error("quad_dominant_grid: no triangle on a square's side");
  });
  PolygonMesh mesh;
  mesh.positions = grid.positions;
  for (std::uint32_t q = 0; q < squares; ++q) {
    switch (kind[q]) {
      case Kind::quad:
        mesh.add_face(square_corners(q));
        break;
      case Kind::triangles:
        mesh.add_face(grid.face(2 * q));
        mesh.add_face(grid.face(2 * q + 1));
        break;
      case Kind::merged:
        mesh.add_face(merged[q]);
        break;
      case Kind::leftover_triangle:
        mesh.add_face(grid.face(leftover[q]));
        break;
      case Kind::absorbed:
        break;
    }
  }
  return mesh;
}

PolygonMesh flat_shaded(PolygonMesh mesh, const FlatShading& spec) {
  SeededRandom rng(spec.seed);
  MeshAttributes& a = mesh.attributes;
  a = {};
  const auto [low_x, high_x] = extent(mesh, 0);
  const auto [low_y, high_y] = extent(mesh, 1);
  std::vector<double> slab_ends;
  for (std::uint32_t m = 1; m < std::max<std::uint32_t>(spec.materials, 1); ++m)
    slab_ends.push_back(low_x + (high_x - low_x) * unit(rng));
  std::sort(slab_ends.begin(), slab_ends.end());
  // Charts: the projection axis, and which side of a random height the face's centre is on.
  const double chart_split = low_y + (high_y - low_y) * unit(rng);
  for (std::size_t m = 0; m < std::max<std::size_t>(slab_ends.size() + 1, 1); ++m)
    a.material_names.push_back("m" + std::to_string(m));
  std::map<std::pair<std::uint32_t, VertexId>, std::uint32_t> texcoord_of;
  a.corner_texcoord.resize(mesh.corners.size());
  a.corner_normal.resize(mesh.corners.size());
  a.face_material.resize(mesh.face_count());
  std::size_t corner = 0;
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    const Point n = face_normal(mesh, f), centre = centroid(mesh, f);
    a.normals.push_back(n);
    const int axis = dominant_axis(n);
    const std::uint32_t chart = 2 * axis + (centre[1] > chart_split);
    a.face_material[f] = static_cast<std::uint32_t>(
        std::upper_bound(slab_ends.begin(), slab_ends.end(), centre[0]) - slab_ends.begin());
    for (VertexId v : mesh.face(f)) {
      const auto [it, added] = texcoord_of.insert({{chart, v}, std::uint32_t(a.texcoords.size())});
      if (added) {
        const Point& p = mesh.positions[v];
        // Each chart its own strip of the texture, so that charts meet at seams.
        a.texcoords.push_back({p[(axis + 1) % 3] * spec.uv_scale + 1.5 * chart,
                               p[(axis + 2) % 3] * spec.uv_scale, 0});
      }
      a.corner_texcoord[corner] = it->second;
      a.corner_normal[corner] = f;
      ++corner;
    }
  }
  return mesh;
}

PolygonMesh chamfered_cube() {
  PolygonMesh mesh;
  for (int axis = 0; axis < 3; ++axis) {
    for (int corner = 0; corner < 8; ++corner) {
      if (corner & (1 << axis)) continue;  // the other two signs vary; the axis' own below
      for (double sign : {-1.0, 1.0}) {
        std::array<double, 3> p{};
        for (int k = 0; k < 3; ++k) p[k] = (corner & (1 << k) ? 0.6 : -0.6);
        p[axis] = sign;
        mesh.positions.push_back(p);
      }
    }
  }
  // Each face: the points that go furthest along one of the 26 directions (±1, 0)^3 \ 0 (a
  // square's, a bevel's or a corner's normal), ordered by angle about it.
  for (int x = -1; x <= 1; ++x) {
    for (int y = -1; y <= 1; ++y) {
      for (int z = -1; z <= 1; ++z) {
        if (!x && !y && !z) continue;
        const Point n{double(x), double(y), double(z)};
        double most = -1e9;
        for (const Point& p : mesh.positions) most = std::max(most, vec3::dot(p, n));
        std::vector<VertexId> face;
        Point centre{};
        for (VertexId v = 0; v < mesh.positions.size(); ++v) {
          if (vec3::dot(mesh.positions[v], n) < most - 1e-9) continue;
          face.push_back(v);
          for (int k = 0; k < 3; ++k) centre[k] += mesh.positions[v][k];
        }
        for (double& c : centre) c /= double(face.size());
        const Point u = vec3::sub(mesh.positions[face[0]], centre), w = vec3::cross(n, u);
        auto angle = [&](VertexId v) {
          const Point d = vec3::sub(mesh.positions[v], centre);
          return std::atan2(vec3::dot(d, w), vec3::dot(d, u));
        };
        std::sort(face.begin(), face.end(),
                  [&](VertexId a, VertexId b) { return angle(a) < angle(b); });
        mesh.add_face(face);
      }
    }
  }
  return mesh;
}

PolygonMesh split_quads(const PolygonMesh& mesh, bool first_diagonal) {
  PolygonMesh out;
  out.positions.assign(mesh.positions.begin(), mesh.positions.end());
  const int k = first_diagonal ? 0 : 1;
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    const std::span<const VertexId> c = mesh.face(f);
    if (c.size() != 4) {
      out.add_face(c);
      continue;
    }
    out.add_face(std::array<VertexId, 3>{c[k], c[k + 1], c[(k + 2) % 4]});
    out.add_face(std::array<VertexId, 3>{c[k], c[(k + 2) % 4], c[(k + 3) % 4]});
  }
  return out;
}

}  // namespace petersen
