#include "petersen/generators/polygon_generators.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "petersen/generators/surface_generators.hpp"
#include "petersen/graph/seeded_random.hpp"
#include "petersen/mesh/vec3.hpp"

namespace petersen {

namespace {

using Point = std::array<double, 3>;

constexpr std::uint64_t kMaxCorners = 0xFFFFFFFFu;
constexpr std::uint32_t kNone = 0xFFFFFFFFu;

std::uint64_t edge_key(VertexId a, VertexId b) {
  return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
}

// The corners of face f are corners[first(f)] up to corners[first(f + 1)].
std::size_t first_corner(const PolygonMesh& mesh, std::size_t f) {
  return mesh.all_triangles() ? 3 * f : mesh.face_start[f];
}

// Corner c's face, for every corner.
std::vector<FaceId> face_of_corners(const PolygonMesh& mesh) {
  std::vector<FaceId> face_of(mesh.corners.size());
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    std::fill(face_of.begin() + first_corner(mesh, f), face_of.begin() + first_corner(mesh, f + 1),
              static_cast<FaceId>(f));
  }
  return face_of;
}

// Halfedge c runs from corner c to the next corner of its face.
std::size_t next_corner(const PolygonMesh& mesh, const std::vector<FaceId>& face_of,
                        std::size_t c) {
  const FaceId f = face_of[c];
  return c + 1 == first_corner(mesh, f + 1) ? first_corner(mesh, f) : c + 1;
}

// Every halfedge as {undirected edge key, corner}, sorted: the halfedges of an edge are adjacent.
// A sort rather than hashing keeps the generators simple and their order independent of any hash.
std::vector<std::pair<std::uint64_t, std::uint32_t>> sorted_halfedges(
    const PolygonMesh& mesh, const std::vector<FaceId>& face_of) {
  std::vector<std::pair<std::uint64_t, std::uint32_t>> halfedges(mesh.corners.size());
  for (std::size_t c = 0; c < mesh.corners.size(); ++c) {
    halfedges[c] = {edge_key(mesh.corners[c], mesh.corners[next_corner(mesh, face_of, c)]),
                    static_cast<std::uint32_t>(c)};
  }
  std::sort(halfedges.begin(), halfedges.end());
  return halfedges;
}

// The halfedges on edge {a, b}.
std::span<const std::pair<std::uint64_t, std::uint32_t>> halfedges_on(
    const std::vector<std::pair<std::uint64_t, std::uint32_t>>& sorted, VertexId a, VertexId b) {
  const std::uint64_t key = edge_key(a, b);
  const auto lo = std::lower_bound(sorted.begin(), sorted.end(),
                                   std::pair<std::uint64_t, std::uint32_t>{key, 0});
  const auto hi =
      std::upper_bound(lo, sorted.end(), std::pair<std::uint64_t, std::uint32_t>{key, kNone});
  return {sorted.data() + (lo - sorted.begin()), static_cast<std::size_t>(hi - lo)};
}

// Draw i (0, 1, 2, ...) of a partial Fisher-Yates pass over `pool`: draws 0..i are distinct
// entries of the pool, each uniform among those left.
std::uint32_t draw_from(std::vector<std::uint32_t>& pool, std::size_t i, SeededRandom& rng) {
  const std::size_t j = i + rng.below64(pool.size() - i);
  std::swap(pool[i], pool[j]);
  return pool[i];
}

std::vector<std::uint32_t> iota_pool(std::size_t n) {
  std::vector<std::uint32_t> pool(n);
  for (std::size_t i = 0; i < n; ++i) pool[i] = static_cast<std::uint32_t>(i);
  return pool;
}

void require_corner_budget(std::uint64_t corners, const char* what) {
  if (corners > kMaxCorners) {
    throw std::invalid_argument(std::string(what) + ": " + std::to_string(corners) +
                                " corners, more than 2^32 - 1");
  }
}

Point normalized(Point p) {
  const double length = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
  return {p[0] / length, p[1] / length, p[2] / length};
}

double dot(const Point& p, const Point& q) {
  return p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
}

// Apéry's parametrization of Boy's surface: even (p and -p give the same point), so it is a map
// of the projective plane.
Point boy_surface(const Point& p) {
  const double x = p[0], y = p[1], z = p[2];
  const double r2 = x * x + y * y + z * z, s = x + y + z;
  return {((2 * x * x - y * y - z * z) * r2 + 2 * y * z * (y * y - z * z) +
           z * x * (x * x - z * z) + x * y * (y * y - x * x)) /
              2,
          std::sqrt(3.0) / 2 *
              ((y * y - z * z) * r2 + z * x * (z * z - x * x) + x * y * (y * y - x * x)),
          s * (s * s * s + 4 * (y - x) * (z - y) * (x - z)) / 8};
}

}  // namespace

PolygonMesh klein_bottle(std::uint32_t u, std::uint32_t v) {
  if (u < 3 || v < 3) {
    throw std::invalid_argument("klein_bottle: a " + std::to_string(u) + " x " + std::to_string(v) +
                                " grid repeats edges; both sides need 3 or more vertices");
  }
  require_corner_budget(6 * std::uint64_t{u} * v, "klein_bottle");
  PolygonMesh mesh;
  mesh.positions.resize(std::size_t{u} * v);
  const double pi = std::numbers::pi;
  for (std::uint32_t j = 0; j < v; ++j) {
    for (std::uint32_t i = 0; i < u; ++i) {
      // Figure-8 immersion: (theta + 2π, -phi) is (theta, phi), the grid's twisted closing. The
      // 0.25 cos(phi) term, invariant under that, separates the circles phi = 0 and phi = π,
      // which the plain immersion maps onto one circle.
      const double theta = 2 * pi * j / v, phi = 2 * pi * i / u;
      const double radius = 2 + std::cos(theta / 2) * std::sin(phi) -
                            std::sin(theta / 2) * std::sin(2 * phi) + 0.25 * std::cos(phi);
      mesh.positions[std::size_t{j} * u + i] = {
          radius * std::cos(theta), radius * std::sin(theta),
          std::sin(theta / 2) * std::sin(phi) + std::cos(theta / 2) * std::sin(2 * phi)};
    }
  }
  // Vertex (i, j) of the grid, rows j = 0..v; row v is row 0 reflected.
  auto id = [&](std::uint32_t i, std::uint32_t j) {
    i %= u;
    return j < v ? j * u + i : (u - i) % u;
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

PolygonMesh projective_plane(std::uint32_t subdivision) {
  if (subdivision > 12) {
    throw std::invalid_argument("projective_plane: subdivision " + std::to_string(subdivision) +
                                " would pass 2^32 - 1 corners (at most 12)");
  }
  // The hemi-icosahedron: one icosahedron vertex of each antipodal pair. Two of them are joined
  // (after negating one if needed) by an icosahedron edge exactly when their dot product is
  // positive; three form a face when they are pairwise joined that way.
  const double g = std::numbers::phi;
  std::vector<Point> sphere = {{0, 1, g}, {0, 1, -g}, {1, g, 0}, {-1, g, 0}, {g, 0, 1}, {g, 0, -1}};
  for (Point& p : sphere) p = normalized(p);
  auto towards = [](const Point& p, const Point& q) {
    return dot(p, q) > 0 ? q : Point{-q[0], -q[1], -q[2]};
  };
  std::vector<std::array<VertexId, 3>> triangles;
  for (VertexId a = 0; a < 6; ++a) {
    for (VertexId b = a + 1; b < 6; ++b) {
      for (VertexId c = b + 1; c < 6; ++c) {
        const Point pb = towards(sphere[a], sphere[b]), pc = towards(sphere[a], sphere[c]);
        if (dot(pb, pc) <= 0) continue;
        const Point& pa = sphere[a];
        const double det = pa[0] * (pb[1] * pc[2] - pb[2] * pc[1]) -
                           pa[1] * (pb[0] * pc[2] - pb[2] * pc[0]) +
                           pa[2] * (pb[0] * pc[1] - pb[1] * pc[0]);
        // Counter-clockwise seen from outside the sphere, in the face's own chart.
        triangles.push_back(det > 0 ? std::array{a, b, c} : std::array{a, c, b});
      }
    }
  }
  for (std::uint32_t round = 0; round < subdivision; ++round) {
    std::unordered_map<std::uint64_t, VertexId> midpoint_of;
    midpoint_of.reserve(triangles.size() * 3 / 2);
    auto midpoint = [&](VertexId a, VertexId b) {
      auto [it, inserted] =
          midpoint_of.try_emplace(edge_key(a, b), static_cast<VertexId>(sphere.size()));
      if (inserted) {
        const Point q = towards(sphere[a], sphere[b]);
        sphere.push_back(
            normalized({sphere[a][0] + q[0], sphere[a][1] + q[1], sphere[a][2] + q[2]}));
      }
      return it->second;
    };
    std::vector<std::array<VertexId, 3>> refined;
    refined.reserve(4 * triangles.size());
    for (const auto& [a, b, c] : triangles) {
      const VertexId ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      refined.push_back({a, ab, ca});
      refined.push_back({ab, b, bc});
      refined.push_back({ca, bc, c});
      refined.push_back({ab, bc, ca});
    }
    triangles = std::move(refined);
  }
  PolygonMesh mesh;
  mesh.positions.resize(sphere.size());
  for (std::size_t i = 0; i < sphere.size(); ++i) mesh.positions[i] = boy_surface(sphere[i]);
  mesh.corners.resize(3 * triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    std::copy(triangles[t].begin(), triangles[t].end(), mesh.corners.begin() + 3 * t);
  }
  return mesh;
}

PolygonMesh open_grid(std::uint32_t nx, std::uint32_t ny) {
  if (nx == 0 || ny == 0) {
    throw std::invalid_argument("open_grid: a " + std::to_string(nx) + " x " + std::to_string(ny) +
                                " grid has no faces");
  }
  require_corner_budget(6 * std::uint64_t{nx} * ny, "open_grid");
  PolygonMesh mesh;
  mesh.positions.resize((std::size_t{nx} + 1) * (ny + 1));
  for (std::uint32_t y = 0; y <= ny; ++y) {
    for (std::uint32_t x = 0; x <= nx; ++x) {
      mesh.positions[std::size_t{y} * (nx + 1) + x] = {double(x), double(y), 0.0};
    }
  }
  mesh.corners.reserve(6 * std::size_t{nx} * ny);
  for (std::uint32_t y = 0; y < ny; ++y) {
    for (std::uint32_t x = 0; x < nx; ++x) {
      const VertexId p00 = y * (nx + 1) + x, p10 = p00 + 1, p01 = p00 + nx + 1, p11 = p01 + 1;
      mesh.corners.insert(mesh.corners.end(), {p00, p10, p11, p00, p11, p01});
    }
  }
  return mesh;
}

PolygonMesh jittered_grid(const JitteredGrid& spec) {
  const std::uint32_t nx = spec.nx, ny = spec.ny;
  if (!(spec.jitter >= 0 && spec.jitter < 0.25)) {
    throw std::invalid_argument("jittered_grid: jitter " + std::to_string(spec.jitter) +
                                " is outside [0, 0.25)");
  }
  if (spec.torus && (ny < 3 || nx < 3 * std::uint64_t{ny})) {
    throw std::invalid_argument("jittered_grid: a torus needs ny >= 3 and nx >= 3 ny, not " +
                                std::to_string(nx) + " x " + std::to_string(ny));
  }
  PolygonMesh mesh = open_grid(nx, ny);  // also checks the sizes
  SeededRandom rng(spec.seed);
  // A uniform double in [-1, 1) from the top 53 bits, the same on every standard library.
  auto unit = [&] { return double(rng.next() >> 11) * 0x1p-52 - 1.0; };
  // Lattice point (x, y), moved, in lattice units.
  const std::uint32_t columns = spec.torus ? nx : nx + 1, rows = spec.torus ? ny : ny + 1;
  std::vector<std::array<double, 2>> lattice(std::size_t{columns} * rows);
  for (std::uint32_t y = 0; y < rows; ++y) {
    for (std::uint32_t x = 0; x < columns; ++x) {
      lattice[std::size_t{y} * columns + x] = {x + spec.jitter * unit(), y + spec.jitter * unit()};
    }
  }
  auto vertex = [&](std::uint32_t x, std::uint32_t y) {
    return static_cast<VertexId>((y % rows) * columns + x % columns);
  };
  mesh.positions.resize(lattice.size());
  for (std::size_t v = 0; v < lattice.size(); ++v) {
    const auto [x, y] = lattice[v];
    if (!spec.torus) {
      mesh.positions[v] = {x, y, 0.0};
      continue;
    }
    // x around the major circle, y around the tube; outward normal (u × v) for increasing x, y.
    const double u = 2 * std::numbers::pi * x / nx, w = 2 * std::numbers::pi * y / ny;
    const double major = double(nx) / ny, ring = major + std::cos(w);
    mesh.positions[v] = {ring * std::cos(u), ring * std::sin(u), std::sin(w)};
  }
  for (std::uint32_t y = 0; y < ny; ++y) {
    for (std::uint32_t x = 0; x < nx; ++x) {
      const VertexId p00 = vertex(x, y), p10 = vertex(x + 1, y), p11 = vertex(x + 1, y + 1),
                     p01 = vertex(x, y + 1);
      VertexId* c = mesh.corners.data() + 6 * (std::size_t{y} * nx + x);
      const bool along_p00_p11 = rng.next() >> 63;
      const std::array<VertexId, 6> faces =
          along_p00_p11 ? std::array<VertexId, 6>{p00, p10, p11, p00, p11, p01}
                        : std::array<VertexId, 6>{p00, p10, p01, p10, p11, p01};
      std::copy(faces.begin(), faces.end(), c);
    }
  }
  return mesh;
}

PolygonMesh punch_holes(const PolygonMesh& mesh, std::uint32_t holes, std::uint64_t seed) {
  SeededRandom rng(seed);
  const std::size_t faces = mesh.face_count(), vertices = mesh.positions.size();
  // Faces around each vertex, as flat arrays.
  std::vector<std::uint32_t> start(vertices + 1, 0), around(mesh.corners.size());
  for (VertexId v : mesh.corners) ++start[v + 1];
  for (std::size_t v = 0; v < vertices; ++v) start[v + 1] += start[v];
  {
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::size_t f = 0; f < faces; ++f) {
      for (VertexId v : mesh.face(static_cast<FaceId>(f)))
        around[fill[v]++] = static_cast<FaceId>(f);
    }
  }
  // Remaining faces, with each one's place in `alive` for O(1) removal.
  std::vector<std::uint32_t> alive = iota_pool(faces), place = iota_pool(faces);
  std::vector<std::uint32_t> stamp(faces, 0);
  std::vector<FaceId> patch;
  for (std::uint32_t hole = 1; hole <= holes && alive.size() > 1; ++hole) {
    const FaceId f = alive[rng.below64(alive.size())];
    patch.assign(1, f);
    stamp[f] = hole;
    if (rng.below64(2)) {
      for (VertexId v : mesh.face(f)) {
        for (std::uint32_t k = start[v]; k < start[v + 1]; ++k) {
          const FaceId g = around[k];
          if (place[g] == kNone || stamp[g] == hole) continue;
          stamp[g] = hole;
          patch.push_back(g);
        }
      }
    }
    if (patch.size() >= alive.size()) continue;
    for (FaceId g : patch) {
      const std::uint32_t i = place[g];
      alive[i] = alive.back();
      place[alive[i]] = i;
      alive.pop_back();
      place[g] = kNone;  // removed
    }
  }
  PolygonMesh out;
  out.positions = mesh.positions;
  for (std::size_t f = 0; f < faces; ++f) {
    if (place[f] != kNone) out.add_face(mesh.face(static_cast<FaceId>(f)));
  }
  return out;
}

PolygonMesh merge_into_polygons(const PolygonMesh& mesh, std::uint32_t count, std::uint64_t seed) {
  SeededRandom rng(seed);
  const std::size_t faces = mesh.face_count();
  const std::vector<FaceId> face_of = face_of_corners(mesh);
  const auto halfedges = sorted_halfedges(mesh, face_of);
  // group[f]: the seed triangle of the polygon that took f in, or f itself.
  std::vector<FaceId> group(faces);
  std::vector<std::uint8_t> taken(faces, 0);
  std::vector<std::vector<VertexId>> polygon_of_seed;  // polygons, in the order they were made
  std::vector<std::uint32_t> polygon_index(faces, kNone);
  std::vector<std::uint32_t> pool;
  for (std::size_t f = 0; f < faces; ++f) {
    group[f] = static_cast<FaceId>(f);
    if (mesh.arity(static_cast<FaceId>(f)) == 3) pool.push_back(static_cast<std::uint32_t>(f));
  }
  std::uint32_t made = 0;
  for (std::size_t i = 0; i < pool.size() && made < count; ++i) {
    const FaceId seed_face = draw_from(pool, i, rng);
    if (taken[seed_face]) continue;
    ++made;
    const std::size_t target = 4 + rng.below64(2);  // a quad or a pentagon
    const auto corners = mesh.face(seed_face);
    std::vector<VertexId> polygon(corners.begin(), corners.end());
    std::vector<FaceId> members{seed_face};
    while (polygon.size() < target) {
      // The first side, from a random one on, across which a free triangle can join.
      const std::size_t offset = rng.below64(polygon.size());
      bool grown = false;
      for (std::size_t s = 0; s < polygon.size() && !grown; ++s) {
        const std::size_t k = (offset + s) % polygon.size();
        const VertexId a = polygon[k], b = polygon[(k + 1) % polygon.size()];
        const auto on_edge = halfedges_on(halfedges, a, b);
        if (on_edge.size() != 2) continue;
        for (const auto& [key, c] : on_edge) {
          const FaceId t = face_of[c];
          if (taken[t] || t == seed_face || mesh.arity(t) != 3) continue;
          // t must run b -> a; its third corner must be new to the polygon.
          if (mesh.corners[c] != b) continue;
          const VertexId apex =
              mesh.corners[next_corner(mesh, face_of, next_corner(mesh, face_of, c))];
          if (std::find(polygon.begin(), polygon.end(), apex) != polygon.end()) continue;
          polygon.insert(polygon.begin() + k + 1, apex);
          members.push_back(t);
          taken[t] = 1;
          grown = true;
          break;
        }
      }
      if (!grown) break;
    }
    taken[seed_face] = 1;
    if (members.size() == 1) continue;
    for (FaceId t : members) group[t] = seed_face;
    polygon_index[seed_face] = static_cast<std::uint32_t>(polygon_of_seed.size());
    polygon_of_seed.push_back(std::move(polygon));
  }
  PolygonMesh out;
  out.positions = mesh.positions;
  for (std::size_t f = 0; f < faces; ++f) {
    if (group[f] != f) continue;
    if (polygon_index[f] != kNone) {
      out.add_face(polygon_of_seed[polygon_index[f]]);
    } else {
      out.add_face(mesh.face(static_cast<FaceId>(f)));
    }
  }
  return out;
}

PolygonMesh add_fins(const PolygonMesh& mesh, std::uint32_t count, std::uint64_t seed) {
  SeededRandom rng(seed);
  PolygonMesh out = mesh;
  if (mesh.face_count() == 0 || count == 0) return out;
  const std::vector<FaceId> face_of = face_of_corners(mesh);
  const auto halfedges = sorted_halfedges(mesh, face_of);
  // Halfedges on edges of two or more faces; all halfedges when there are none.
  std::vector<std::uint32_t> candidates;
  for (std::size_t i = 0; i < halfedges.size(); ++i) {
    const bool shared = (i > 0 && halfedges[i - 1].first == halfedges[i].first) ||
                        (i + 1 < halfedges.size() && halfedges[i + 1].first == halfedges[i].first);
    if (shared) candidates.push_back(halfedges[i].second);
  }
  if (candidates.empty()) candidates = iota_pool(mesh.corners.size());
  for (std::uint32_t k = 0; k < count; ++k) {
    const std::uint32_t c = candidates[rng.below64(candidates.size())];
    const VertexId a = mesh.corners[c], b = mesh.corners[next_corner(mesh, face_of, c)];
    // Newell's normal of the face, then a point beside the edge's midpoint along it.
    Point normal = vec3::newell_normal(mesh.positions, mesh.face(face_of[c]));
    if (!(dot(normal, normal) > 0)) normal = {0, 0, 1};
    normal = normalized(normal);
    const Point& pa = mesh.positions[a];
    const Point& pb = mesh.positions[b];
    const Point d{pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]};
    const double length = dot(d, d) > 0 ? std::sqrt(dot(d, d)) : 1.0;
    // Fins on one edge differ in height, so that no two new vertices coincide.
    const double height = length * (0.5 + double(rng.below64(1024)) / 2048);
    const VertexId apex = static_cast<VertexId>(out.positions.size());
    out.positions.push_back({(pa[0] + pb[0]) / 2 + height * normal[0],
                             (pa[1] + pb[1]) / 2 + height * normal[1],
                             (pa[2] + pb[2]) / 2 + height * normal[2]});
    const std::array<VertexId, 3> fin{b, a, apex};
    out.add_face(fin);
  }
  return out;
}

PolygonMesh pinch_vertices(const PolygonMesh& mesh, std::uint32_t count, std::uint64_t seed) {
  SeededRandom rng(seed);
  PolygonMesh out = mesh;
  const std::size_t faces = mesh.face_count(), vertices = mesh.positions.size();
  if (faces == 0 || count == 0) return out;
  // Corners at each vertex (positions in `corners`), as flat arrays.
  std::vector<std::uint32_t> start(vertices + 1, 0), at(mesh.corners.size());
  for (VertexId v : mesh.corners) ++start[v + 1];
  for (std::size_t v = 0; v < vertices; ++v) start[v + 1] += start[v];
  {
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::size_t c = 0; c < mesh.corners.size(); ++c) {
      at[fill[mesh.corners[c]]++] = static_cast<std::uint32_t>(c);
    }
  }
  const std::vector<FaceId> face_of = face_of_corners(mesh);
  // Closed face neighbourhood of v; valid for any vertex outside earlier pinches' neighbourhoods,
  // whose faces are still those of the input.
  auto neighbourhood = [&](VertexId v, std::vector<VertexId>& into) {
    into.assign(1, v);
    for (std::uint32_t k = start[v]; k < start[v + 1]; ++k) {
      for (VertexId w : mesh.face(face_of[at[k]])) into.push_back(w);
    }
  };
  std::vector<std::uint8_t> touched(vertices, 0);
  std::vector<std::uint64_t> stamp(vertices, 0);
  std::vector<VertexId> around_u, around_w;
  std::uint32_t done = 0;
  const std::uint64_t attempts = 16 * std::uint64_t{count} + 64;
  for (std::uint64_t attempt = 1; attempt <= attempts && done < count; ++attempt) {
    const VertexId u = mesh.corners[rng.below64(mesh.corners.size())];
    const VertexId w = mesh.corners[rng.below64(mesh.corners.size())];
    if (u == w || touched[u] || touched[w]) continue;
    neighbourhood(u, around_u);
    neighbourhood(w, around_w);
    for (VertexId x : around_u) stamp[x] = attempt;
    if (std::any_of(around_w.begin(), around_w.end(),
                    [&](VertexId x) { return stamp[x] == attempt; })) {
      continue;
    }
    for (std::uint32_t k = start[w]; k < start[w + 1]; ++k) out.corners[at[k]] = u;
    for (VertexId x : around_u) touched[x] = 1;
    for (VertexId x : around_w) touched[x] = 1;
    ++done;
  }
  return out;
}

PolygonMesh flip_faces(const PolygonMesh& mesh, std::uint32_t count, std::uint64_t seed) {
  SeededRandom rng(seed);
  PolygonMesh out = mesh;
  std::vector<std::uint32_t> pool = iota_pool(mesh.face_count());
  const std::size_t flips = std::min<std::size_t>(count, pool.size());
  for (std::size_t i = 0; i < flips; ++i) {
    const FaceId f = draw_from(pool, i, rng);
    std::reverse(out.corners.begin() + first_corner(out, f),
                 out.corners.begin() + first_corner(out, f + 1));
  }
  return out;
}

PolygonMesh concatenate(std::span<const PolygonMesh> meshes) {
  PolygonMesh out;
  std::vector<VertexId> shifted;
  for (const PolygonMesh& mesh : meshes) {
    const VertexId offset = static_cast<VertexId>(out.positions.size());
    require_corner_budget(std::uint64_t{out.corners.size()} + mesh.corners.size(), "concatenate");
    out.positions.insert(out.positions.end(), mesh.positions.begin(), mesh.positions.end());
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
      const auto corners = mesh.face(static_cast<FaceId>(f));
      shifted.assign(corners.begin(), corners.end());
      for (VertexId& v : shifted) v += offset;
      out.add_face(shifted);
    }
  }
  return out;
}

PolygonMesh random_mixed_mesh(std::uint64_t seed, std::uint32_t size) {
  SeededRandom rng(seed);
  const std::uint32_t components = rng.below64(4) == 0 ? 2 + rng.below64(2) : 1;
  const std::uint32_t target = std::max<std::uint32_t>(size / components, 1);
  std::vector<PolygonMesh> parts;
  for (std::uint32_t part = 0; part < components; ++part) {
    PolygonMesh mesh;
    switch (rng.below64(4)) {
      case 0: {
        // The genus-g plate has 12 triangles for g = 0 and 64 + 36(g - 1) after; splits add two.
        const std::uint32_t genus = rng.below64(1 + std::min<std::uint32_t>(3, target / 64));
        const std::uint32_t base = genus == 0 ? 12 : 64 + 36 * (genus - 1);
        const std::uint32_t splits = target > base ? (target - base) / 2 : 0;
        mesh = random_closed_surface(genus, splits, splits, rng.next());
        break;
      }
      case 1: {
        const std::uint32_t side = static_cast<std::uint32_t>(std::sqrt(target / 2.0));
        const auto u =
            std::max<std::uint32_t>(3, side + static_cast<std::uint32_t>(rng.below64(3)));
        mesh = klein_bottle(u, std::max<std::uint32_t>(3, target / (2 * u)));
        break;
      }
      case 2: {
        std::uint32_t subdivision = 0;
        while (subdivision < 6 && 40u << (2 * subdivision) <= target) ++subdivision;
        mesh = projective_plane(subdivision);
        break;
      }
      default: {
        const std::uint32_t side = static_cast<std::uint32_t>(std::sqrt(target / 2.0));
        const auto nx =
            std::max<std::uint32_t>(1, side + static_cast<std::uint32_t>(rng.below64(3)));
        mesh = open_grid(nx, std::max<std::uint32_t>(1, target / (2 * nx)));
        break;
      }
    }
    // Each step: whether, how many (at least one), and its seed, drawn in this order (one
    // draw per statement: the order of evaluation of call arguments is unspecified).
    const std::uint32_t faces = static_cast<std::uint32_t>(mesh.face_count());
    auto maybe = [&](std::uint32_t one_in, std::uint32_t most, auto step) {
      if (rng.below64(one_in) != 0) return;
      const auto how_many = static_cast<std::uint32_t>(1 + rng.below64(most));
      const std::uint64_t step_seed = rng.next();
      mesh = step(mesh, how_many, step_seed);
    };
    maybe(2, 1 + faces / 6, merge_into_polygons);
    maybe(2, 1 + faces / 40, punch_holes);
    maybe(3, 3, add_fins);
    maybe(3, 1 + faces / 10, flip_faces);
    parts.push_back(std::move(mesh));
  }
  PolygonMesh mesh = parts.size() == 1 ? std::move(parts[0]) : concatenate(parts);
  // Pinching after the components are put together may join two of them at a vertex.
  if (rng.below64(4) == 0) {
    const auto pinches = static_cast<std::uint32_t>(1 + rng.below64(2));
    mesh = pinch_vertices(mesh, pinches, rng.next());
  }
  return mesh;
}

}  // namespace petersen
