// The generators' claimed topology, checked by counting on their output with plain containers
// (petersen/testing/mesh_census.hpp), independently of the library's own edge grouping and
// surface check.

#include "petersen/generators/polygon_generators.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <queue>
#include <set>
#include <vector>

#include "petersen/generators/surface_generators.hpp"
#include "petersen/mesh/mesh_report.hpp"
#include "petersen/testing/mesh_census.hpp"

namespace petersen {
namespace {

std::vector<std::vector<VertexId>> faces_of(const PolygonMesh& mesh) {
  std::vector<std::vector<VertexId>> faces;
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    const auto corners = mesh.face(f);
    faces.emplace_back(corners.begin(), corners.end());
  }
  return faces;
}

using petersen::testing::census;
using Census = petersen::testing::MeshCensus;
using Edge = std::pair<VertexId, VertexId>;

// What is wrong with the arrays, or "": corners in range, at least three per face and none
// repeated, face_start empty exactly when all faces are triangles (and then consistent),
// positions finite.
std::string malformation(const PolygonMesh& mesh) {
  if (mesh.face_start.empty()) {
    if (mesh.corners.size() % 3 != 0) return "corners not a multiple of 3 without face_start";
  } else {
    if (mesh.face_start.front() != 0 || mesh.face_start.back() != mesh.corners.size()) {
      return "face_start does not span the corners";
    }
    bool all_triangles = true;
    for (std::size_t f = 0; f + 1 < mesh.face_start.size(); ++f) {
      if (mesh.face_start[f] > mesh.face_start[f + 1]) return "face_start decreases";
      all_triangles &= mesh.face_start[f + 1] - mesh.face_start[f] == 3;
    }
    if (all_triangles) return "face_start set although all faces are triangles";
  }
  for (const auto& face : faces_of(mesh)) {
    if (face.size() < 3) return "a face with fewer than three corners";
    for (VertexId v : face) {
      if (v >= mesh.positions.size()) return "a corner out of range";
    }
    if (std::set<VertexId>(face.begin(), face.end()).size() != face.size()) {
      return "a face repeats a corner";
    }
  }
  for (const auto& p : mesh.positions) {
    for (double x : p) {
      if (!std::isfinite(x)) return "a position not finite";
    }
  }
  return "";
}

std::size_t repeated_faces(const PolygonMesh& mesh) {
  std::set<std::vector<VertexId>> seen;
  std::size_t repeats = 0;
  for (auto face : faces_of(mesh)) {
    std::sort(face.begin(), face.end());
    repeats += !seen.insert(face).second;
  }
  return repeats;
}

std::size_t coinciding_positions(const PolygonMesh& mesh) {
  std::set<VertexId> referenced(mesh.corners.begin(), mesh.corners.end());
  std::set<std::array<double, 3>> seen;
  std::size_t coinciding = 0;
  for (VertexId v : referenced) coinciding += !seen.insert(mesh.positions[v]).second;
  return coinciding;
}

// Every vertex's link (the edges opposite it in its triangles) is one cycle.
bool links_are_cycles(const PolygonMesh& mesh) {
  std::map<VertexId, std::map<VertexId, std::vector<VertexId>>> link;
  for (const auto& face : faces_of(mesh)) {
    if (face.size() != 3) return false;
    for (int k = 0; k < 3; ++k) {
      const VertexId v = face[k], a = face[(k + 1) % 3], b = face[(k + 2) % 3];
      link[v][a].push_back(b);
      link[v][b].push_back(a);
    }
  }
  for (const auto& [v, graph] : link) {
    for (const auto& [x, next] : graph) {
      if (next.size() != 2 || next[0] == next[1]) return false;
    }
    // Walk the cycle from any link vertex; it must visit the whole link.
    const VertexId first = graph.begin()->first;
    VertexId previous = first, at = graph.begin()->second[0];
    std::size_t steps = 1;
    while (at != first && steps <= graph.size()) {
      const auto& next = graph.at(at);
      const VertexId after = next[0] == previous ? next[1] : next[0];
      previous = at;
      at = after;
      ++steps;
    }
    if (at != first || steps != graph.size()) return false;
  }
  return true;
}

// What keeps the mesh from being a closed simplicial non-orientable connected surface of Euler
// characteristic `euler` with distinct positions, or "": each edge in exactly two triangles,
// links cycles, no repeated triangle, no consistent orientation.
std::string closed_non_orientable_problem(const PolygonMesh& mesh, std::int64_t euler) {
  if (const std::string problem = malformation(mesh); !problem.empty()) return problem;
  if (!mesh.all_triangles()) return "not all triangles";
  const Census c = census(mesh);
  if (c.boundary_edges != 0 || c.non_manifold_edges != 0 || 2 * c.edges != 3 * c.faces) {
    return "an edge not in exactly two triangles";
  }
  if (c.euler() != euler) return "Euler characteristic " + std::to_string(c.euler());
  if (c.components != 1) return std::to_string(c.components) + " components";
  if (c.pinched_vertices != 0) return "a pinched vertex";
  if (c.orientable) return "orientable";
  if (!links_are_cycles(mesh)) return "a vertex link that is not one cycle";
  if (repeated_faces(mesh) != 0) return "a repeated triangle";
  if (coinciding_positions(mesh) != 0) return "two vertices at one position";
  return "";
}

bool same_arrays(const PolygonMesh& a, const PolygonMesh& b) {
  return std::equal(a.positions.begin(), a.positions.end(), b.positions.begin(),
                    b.positions.end()) &&
         std::equal(a.corners.begin(), a.corners.end(), b.corners.begin(), b.corners.end()) &&
         std::equal(a.face_start.begin(), a.face_start.end(), b.face_start.begin(),
                    b.face_start.end());
}

PolygonMesh closed_surface(std::uint32_t genus, std::uint64_t seed) {
  return random_closed_surface(genus, 60, 60, seed);
}

TEST(KleinBottle, IsAClosedNonOrientableSimplicialSurfaceOfEulerCharacteristic0) {
  for (std::uint32_t u = 3; u <= 7; ++u) {
    for (std::uint32_t v = 3; v <= 7; ++v) {
      SCOPED_TRACE(::testing::Message() << u << " x " << v);
      const PolygonMesh mesh = klein_bottle(u, v);
      EXPECT_EQ(closed_non_orientable_problem(mesh, 0), "");
      EXPECT_EQ(census(mesh).vertices, std::size_t{u} * v);
      EXPECT_EQ(mesh.face_count(), 2 * std::size_t{u} * v);
    }
  }
  EXPECT_EQ(closed_non_orientable_problem(klein_bottle(40, 25), 0), "");
}

RC_GTEST_PROP(KleinBottle, AnyGridOfThreeOrMoreASide, ()) {
  const auto u = *rc::gen::inRange<std::uint32_t>(3, 50);
  const auto v = *rc::gen::inRange<std::uint32_t>(3, 50);
  RC_ASSERT(closed_non_orientable_problem(klein_bottle(u, v), 0) == "");
}

TEST(KleinBottle, RefusesGridsThatRepeatEdges) {
  EXPECT_THROW(klein_bottle(2, 5), std::invalid_argument);
  EXPECT_THROW(klein_bottle(5, 2), std::invalid_argument);
  EXPECT_THROW(klein_bottle(0, 0), std::invalid_argument);
  EXPECT_THROW(klein_bottle(1u << 20, 1u << 20), std::invalid_argument);
}

TEST(ProjectivePlane, IsAClosedNonOrientableSimplicialSurfaceOfEulerCharacteristic1) {
  for (std::uint32_t s = 0; s <= 4; ++s) {
    SCOPED_TRACE(s);
    const PolygonMesh mesh = projective_plane(s);
    EXPECT_EQ(closed_non_orientable_problem(mesh, 1), "");
    EXPECT_EQ(mesh.face_count(), std::size_t{10} << (2 * s));
  }
  const Census minimal = census(projective_plane(0));
  EXPECT_EQ(minimal.vertices, 6u);
  EXPECT_EQ(minimal.edges, 15u);
  EXPECT_EQ(minimal.faces, 10u);
  EXPECT_THROW(projective_plane(13), std::invalid_argument);
}

TEST(OpenGrid, IsAnOrientedDiskWithOneBoundaryLoop) {
  for (std::uint32_t nx = 1; nx <= 5; ++nx) {
    for (std::uint32_t ny = 1; ny <= 5; ++ny) {
      SCOPED_TRACE(::testing::Message() << nx << " x " << ny);
      const PolygonMesh mesh = open_grid(nx, ny);
      EXPECT_EQ(malformation(mesh), "");
      const Census c = census(mesh);
      EXPECT_EQ(c.vertices, std::size_t{nx + 1} * (ny + 1));
      EXPECT_EQ(c.faces, 2 * std::size_t{nx} * ny);
      EXPECT_EQ(c.euler(), 1);
      EXPECT_EQ(c.boundary_edges, 2 * std::size_t{nx + ny});
      EXPECT_EQ(c.boundary_loops, 1u);
      EXPECT_EQ(c.non_manifold_edges, 0u);
      EXPECT_EQ(c.inconsistent_edges, 0u);
      EXPECT_EQ(c.components, 1u);
      EXPECT_TRUE(c.orientable);
      EXPECT_EQ(repeated_faces(mesh), 0u);
      // Counter-clockwise seen from +z: positive signed area.
      for (const auto& f : faces_of(mesh)) {
        const auto &p = mesh.positions[f[0]], &q = mesh.positions[f[1]], &r = mesh.positions[f[2]];
        EXPECT_GT((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]), 0);
      }
    }
  }
  EXPECT_THROW(open_grid(0, 3), std::invalid_argument);
}

TEST(JitteredGrid, IsTheGridMovedAndRecutWithinItsSquares) {
  const std::uint32_t nx = 7, ny = 5;
  const double jitter = 0.1;
  const PolygonMesh mesh = jittered_grid({.nx = nx, .ny = ny, .jitter = jitter, .seed = 3});
  EXPECT_EQ(malformation(mesh), "");
  const Census c = census(mesh);
  EXPECT_EQ(c.faces, 2 * std::size_t{nx} * ny);
  EXPECT_EQ(c.euler(), 1);
  EXPECT_EQ(c.boundary_loops, 1u);
  EXPECT_EQ(c.inconsistent_edges, 0u);
  EXPECT_EQ(repeated_faces(mesh), 0u);
  const PolygonMesh lattice = open_grid(nx, ny);
  ASSERT_EQ(mesh.positions.size(), lattice.positions.size());
  bool moved = false;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    EXPECT_LE(std::abs(mesh.positions[v][0] - lattice.positions[v][0]), jitter);
    EXPECT_LE(std::abs(mesh.positions[v][1] - lattice.positions[v][1]), jitter);
    moved |= mesh.positions[v] != lattice.positions[v];
  }
  EXPECT_TRUE(moved);
  std::size_t along_p00_p11 = 0;
  for (std::uint32_t q = 0; q < nx * ny; ++q) {
    // Faces 2q and 2q + 1 cover square q exactly, one diagonal shared.
    const VertexId p00 = q / nx * (nx + 1) + q % nx;
    const std::set<VertexId> square{p00, p00 + 1, p00 + nx + 1, p00 + nx + 2};
    std::set<VertexId> both;
    std::multiset<VertexId> corners;
    for (FaceId f : {2 * q, 2 * q + 1}) {
      for (VertexId v : mesh.face(f)) {
        both.insert(v);
        corners.insert(v);
      }
      const auto t = mesh.face(f);
      const auto &p = mesh.positions[t[0]], &r = mesh.positions[t[1]], &u = mesh.positions[t[2]];
      EXPECT_GT((r[0] - p[0]) * (u[1] - p[1]) - (r[1] - p[1]) * (u[0] - p[0]), 0);
    }
    EXPECT_EQ(both, square);
    along_p00_p11 += corners.count(p00) == 2;
  }
  // Both diagonals occur.
  EXPECT_GT(along_p00_p11, 0u);
  EXPECT_LT(along_p00_p11, std::size_t{nx} * ny);
  EXPECT_THROW(jittered_grid({.nx = 3, .ny = 3, .jitter = 0.3}), std::invalid_argument);
  EXPECT_THROW(jittered_grid({.nx = 0, .ny = 3}), std::invalid_argument);
}

TEST(JitteredGrid, TorusIsAClosedOrientedSurfaceOfGenus1) {
  const PolygonMesh mesh = jittered_grid({.nx = 30, .ny = 10, .jitter = 0.1, .torus = true});
  EXPECT_EQ(malformation(mesh), "");
  const Census c = census(mesh);
  EXPECT_EQ(c.vertices, 300u);
  EXPECT_EQ(c.faces, 600u);
  EXPECT_EQ(c.euler(), 0);
  EXPECT_EQ(c.boundary_edges, 0u);
  EXPECT_EQ(c.non_manifold_edges, 0u);
  EXPECT_EQ(c.inconsistent_edges, 0u);
  EXPECT_EQ(c.components, 1u);
  EXPECT_TRUE(c.orientable);
  EXPECT_EQ(repeated_faces(mesh), 0u);
  // Facing outwards: each face's normal points away from the tube's centre circle.
  for (const auto& f : faces_of(mesh)) {
    const auto &p = mesh.positions[f[0]], &q = mesh.positions[f[1]], &r = mesh.positions[f[2]];
    const double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
    const double w[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
    const double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                         u[0] * w[1] - u[1] * w[0]};
    const double radial = std::hypot(p[0], p[1]), major = 3.0;
    const double out[3] = {p[0] - major * p[0] / radial, p[1] - major * p[1] / radial, p[2]};
    EXPECT_GT(n[0] * out[0] + n[1] * out[1] + n[2] * out[2], 0);
  }
  EXPECT_THROW(jittered_grid({.nx = 20, .ny = 10, .torus = true}), std::invalid_argument);
}

TEST(Census, FindsClosedOrientableSurfacesOrientable) {
  // The control for the non-orientability checks above: the same count succeeds on surfaces
  // that have an orientation, whatever their genus.
  for (std::uint32_t genus = 0; genus <= 3; ++genus) {
    const Census c = census(closed_surface(genus, genus));
    EXPECT_TRUE(c.orientable);
    EXPECT_EQ(c.boundary_edges, 0u);
    EXPECT_EQ(c.euler(), 2 - 2 * std::int64_t{genus});
  }
}

TEST(PunchHoles, OneDiskRemovedFromAFineSurfaceOpensOneBoundaryLoop) {
  // On a fine plate (every feature 4 units wide) a patch is a disk: χ drops by one and one
  // boundary loop appears.
  const PolygonMesh plate = voxel_plate({1, 1, 4, false});
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    SCOPED_TRACE(seed);
    const PolygonMesh holed = punch_holes(plate, 1, seed);
    EXPECT_EQ(malformation(holed), "");
    const Census c = census(holed);
    EXPECT_LT(c.faces, plate.face_count());
    EXPECT_EQ(c.euler(), census(plate).euler() - 1);
    EXPECT_EQ(c.boundary_loops, 1u);
    EXPECT_EQ(c.non_manifold_edges, 0u);
    EXPECT_TRUE(c.orientable);
  }
}

// The output's faces are input faces, in input order; the positions are unchanged.
bool is_subsequence_of(const PolygonMesh& part, const PolygonMesh& whole) {
  const auto kept = faces_of(part), all = faces_of(whole);
  std::size_t at = 0;
  for (const auto& face : kept) {
    while (at < all.size() && all[at] != face) ++at;
    if (at == all.size()) return false;
    ++at;
  }
  return std::equal(part.positions.begin(), part.positions.end(), whole.positions.begin(),
                    whole.positions.end());
}

RC_GTEST_PROP(PunchHoles, KeepsInputFacesAndOpensBoundaries, ()) {
  const auto genus = *rc::gen::inRange<std::uint32_t>(0, 4);
  const auto holes = *rc::gen::inRange<std::uint32_t>(1, 6);
  const auto seed = *rc::gen::arbitrary<std::uint64_t>();
  const PolygonMesh closed = closed_surface(genus, seed);
  const PolygonMesh holed = punch_holes(closed, holes, seed);
  RC_ASSERT(malformation(holed).empty());
  RC_ASSERT(is_subsequence_of(holed, closed));
  const Census c = census(holed);
  RC_ASSERT(c.faces >= 1u);
  RC_ASSERT(c.faces < closed.face_count());
  RC_ASSERT(c.boundary_edges >= 3u);
  RC_ASSERT(c.boundary_loops >= 1u);
  RC_ASSERT(c.non_manifold_edges == 0u);
  RC_ASSERT(c.orientable);
}

TEST(PunchHoles, AlwaysKeepsAFace) {
  for (std::uint64_t seed = 0; seed < 10; ++seed) {
    EXPECT_GE(punch_holes(open_grid(1, 1), 5, seed).face_count(), 1u);
    const PolygonMesh small = punch_holes(projective_plane(0), 100, seed);
    EXPECT_GE(small.face_count(), 1u);
    EXPECT_LT(small.face_count(), 10u);
  }
}

// What merging may change: faces and edges drop by one per absorbed triangle, nothing else.
void check_merge(const PolygonMesh& triangles, std::uint32_t count, std::uint64_t seed) {
  const PolygonMesh merged = merge_into_polygons(triangles, count, seed);
  RC_ASSERT(malformation(merged).empty());
  const Census before = census(triangles), after = census(merged);
  std::size_t triangles_covered = 0, polygons = 0;
  for (const auto& face : faces_of(merged)) {
    RC_ASSERT(face.size() <= 5u);
    triangles_covered += face.size() - 2;
    polygons += face.size() > 3;
  }
  RC_ASSERT(triangles_covered == triangles.face_count());
  RC_ASSERT(polygons <= std::size_t{count});
  RC_ASSERT(after.euler() == before.euler());
  RC_ASSERT(before.faces - after.faces == before.edges - after.edges);
  RC_ASSERT(after.boundary_edges == before.boundary_edges);
  RC_ASSERT(after.boundary_loops == before.boundary_loops);
  RC_ASSERT(after.components == before.components);
  RC_ASSERT(after.orientable == before.orientable);
  RC_ASSERT(after.inconsistent_edges == before.inconsistent_edges);
  // Orientation kept: every side of a polygon runs as it did in an input triangle.
  std::set<Edge> directed;
  for (const auto& face : faces_of(triangles)) {
    for (std::size_t k = 0; k < face.size(); ++k) {
      directed.insert({face[k], face[(k + 1) % face.size()]});
    }
  }
  for (const auto& face : faces_of(merged)) {
    for (std::size_t k = 0; k < face.size(); ++k) {
      RC_ASSERT(directed.count({face[k], face[(k + 1) % face.size()]}) == 1u);
    }
  }
}

RC_GTEST_PROP(MergeIntoPolygons, KeepsTheSurfaceAndItsOrientation, ()) {
  const auto seed = *rc::gen::arbitrary<std::uint64_t>();
  const auto count = *rc::gen::inRange<std::uint32_t>(0, 200);
  const PolygonMesh bases[] = {closed_surface(seed % 4, seed), klein_bottle(5, 7),
                               projective_plane(1), punch_holes(open_grid(9, 7), 3, seed)};
  for (const PolygonMesh& base : bases) check_merge(base, count, seed);
}

TEST(MergeIntoPolygons, MakesQuadsAndPentagons) {
  const PolygonMesh merged = merge_into_polygons(open_grid(20, 20), 100, 7);
  std::map<std::size_t, std::size_t> by_arity;
  for (const auto& face : faces_of(merged)) ++by_arity[face.size()];
  EXPECT_GT(by_arity[4], 0u);
  EXPECT_GT(by_arity[5], 0u);
  EXPECT_GT(by_arity[3], 0u);
  EXPECT_LE(by_arity[4] + by_arity[5], 100u);
}

RC_GTEST_PROP(AddFins, MakesNonManifoldEdges, ()) {
  const auto seed = *rc::gen::arbitrary<std::uint64_t>();
  const auto count = *rc::gen::inRange<std::uint32_t>(1, 10);
  const PolygonMesh base = closed_surface(seed % 3, seed);
  const PolygonMesh finned = add_fins(base, count, seed);
  RC_ASSERT(malformation(finned).empty());
  const Census before = census(base), after = census(finned);
  RC_ASSERT(after.faces == before.faces + count);
  RC_ASSERT(after.vertices == before.vertices + count);
  RC_ASSERT(after.edges == before.edges + 2 * count);
  RC_ASSERT(after.euler() == before.euler());
  RC_ASSERT(after.non_manifold_edges >= 1u);
  RC_ASSERT(after.non_manifold_edges <= std::size_t{count});
  RC_ASSERT(after.boundary_edges == 2 * std::size_t{count});
  RC_ASSERT(coinciding_positions(finned) == 0u);
  RC_ASSERT(repeated_faces(finned) == 0u);
}

TEST(AddFins, OnAMeshOfBoundaryEdgesOnlyClosesOneOfThem) {
  PolygonMesh triangle;
  triangle.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  triangle.add_face(std::array<VertexId, 3>{0, 1, 2});
  const Census c = census(add_fins(triangle, 1, 3));
  EXPECT_EQ(c.faces, 2u);
  EXPECT_EQ(c.non_manifold_edges, 0u);
  EXPECT_EQ(c.boundary_edges, 4u);
  EXPECT_EQ(c.inconsistent_edges, 0u);  // the fin runs against the face it leans on
}

RC_GTEST_PROP(PinchVertices, EachPinchMergesTwoVerticesIntoAPinchedOne, ()) {
  const auto seed = *rc::gen::arbitrary<std::uint64_t>();
  const auto count = *rc::gen::inRange<std::uint32_t>(1, 4);
  const PolygonMesh base = closed_surface(seed % 3, seed);
  const PolygonMesh pinched = pinch_vertices(base, count, seed);
  RC_ASSERT(malformation(pinched).empty());
  const Census before = census(base), after = census(pinched);
  const std::size_t pinches = before.vertices - after.vertices;
  RC_ASSERT(pinches >= 1u);
  RC_ASSERT(pinches <= std::size_t{count});
  RC_ASSERT(after.pinched_vertices == pinches);
  RC_ASSERT(after.euler() == before.euler() - std::int64_t(pinches));
  RC_ASSERT(after.edges == before.edges);
  RC_ASSERT(after.faces == before.faces);
  RC_ASSERT(after.boundary_edges == 0u);
  RC_ASSERT(after.non_manifold_edges == 0u);
  RC_ASSERT(repeated_faces(pinched) == 0u);
}

TEST(PinchVertices, CanJoinTwoComponentsAtOneVertex) {
  const PolygonMesh two[] = {projective_plane(1), projective_plane(1)};
  const PolygonMesh both = concatenate(two);
  bool joined = false;
  for (std::uint64_t seed = 0; seed < 20 && !joined; ++seed) {
    const Census c = census(pinch_vertices(both, 1, seed));
    EXPECT_EQ(c.pinched_vertices, 1u);
    joined = c.components == 1;
  }
  EXPECT_TRUE(joined);
}

RC_GTEST_PROP(FlipFaces, ReversesExactlyTheAskedNumberOfFaces, ()) {
  const auto seed = *rc::gen::arbitrary<std::uint64_t>();
  const auto count = *rc::gen::inRange<std::uint32_t>(0, 300);
  const PolygonMesh base = merge_into_polygons(closed_surface(seed % 3, seed), 20, seed);
  const PolygonMesh flipped = flip_faces(base, count, seed);
  RC_ASSERT(malformation(flipped).empty());
  const auto before = faces_of(base), after = faces_of(flipped);
  RC_ASSERT(before.size() == after.size());
  std::size_t reversed = 0;
  for (std::size_t f = 0; f < before.size(); ++f) {
    if (before[f] == after[f]) continue;
    RC_ASSERT(std::equal(before[f].rbegin(), before[f].rend(), after[f].begin()));
    ++reversed;
  }
  RC_ASSERT(reversed == std::min<std::size_t>(count, before.size()));
  const Census c = census(flipped);
  RC_ASSERT(c.orientable);  // a re-orientation still exists
  RC_ASSERT((c.inconsistent_edges > 0) == (reversed > 0 && reversed < before.size()));
}

TEST(Concatenate, AddsUpComponentsAndCounts) {
  const PolygonMesh parts[] = {klein_bottle(3, 4), merge_into_polygons(open_grid(4, 4), 5, 1),
                               projective_plane(0)};
  const PolygonMesh all = concatenate(parts);
  EXPECT_EQ(malformation(all), "");
  Census sum;
  for (const PolygonMesh& part : parts) {
    const Census c = census(part);
    sum.vertices += c.vertices;
    sum.edges += c.edges;
    sum.faces += c.faces;
    sum.boundary_edges += c.boundary_edges;
    sum.components += c.components;
  }
  const Census c = census(all);
  EXPECT_EQ(c.vertices, sum.vertices);
  EXPECT_EQ(c.edges, sum.edges);
  EXPECT_EQ(c.faces, sum.faces);
  EXPECT_EQ(c.boundary_edges, sum.boundary_edges);
  EXPECT_EQ(c.components, 3u);
  EXPECT_FALSE(c.orientable);
  EXPECT_EQ(all.positions.size(),
            parts[0].positions.size() + parts[1].positions.size() + parts[2].positions.size());
  EXPECT_EQ(concatenate({}).face_count(), 0u);
  const PolygonMesh triangles[] = {open_grid(2, 1), klein_bottle(3, 3)};
  EXPECT_TRUE(concatenate(triangles).all_triangles());
}

TEST(Generators, SameSeedSameArrays) {
  for (std::uint64_t seed : {0ull, 1ull, 12345ull}) {
    const PolygonMesh base = closed_surface(2, seed);
    EXPECT_TRUE(same_arrays(punch_holes(base, 4, seed), punch_holes(base, 4, seed)));
    EXPECT_TRUE(
        same_arrays(merge_into_polygons(base, 30, seed), merge_into_polygons(base, 30, seed)));
    EXPECT_TRUE(same_arrays(add_fins(base, 3, seed), add_fins(base, 3, seed)));
    EXPECT_TRUE(same_arrays(pinch_vertices(base, 2, seed), pinch_vertices(base, 2, seed)));
    EXPECT_TRUE(same_arrays(flip_faces(base, 9, seed), flip_faces(base, 9, seed)));
    EXPECT_TRUE(same_arrays(random_mixed_mesh(seed, 800), random_mixed_mesh(seed, 800)));
  }
  // And the seed matters.
  std::set<std::vector<VertexId>> distinct;
  for (std::uint64_t seed = 0; seed < 10; ++seed) {
    const PolygonMesh mesh = random_mixed_mesh(seed, 300);
    distinct.insert(std::vector<VertexId>(mesh.corners.begin(), mesh.corners.end()));
  }
  EXPECT_GE(distinct.size(), 5u);
}

RC_GTEST_PROP(RandomMixedMesh, IsWellFormedAndDeterministic, ()) {
  const auto seed = *rc::gen::arbitrary<std::uint64_t>();
  const auto size = *rc::gen::inRange<std::uint32_t>(1, 3000);
  const PolygonMesh mesh = random_mixed_mesh(seed, size);
  RC_ASSERT(malformation(mesh).empty());
  RC_ASSERT(mesh.face_count() >= 1u);
  RC_ASSERT(repeated_faces(mesh) == 0u);
  RC_ASSERT(same_arrays(mesh, random_mixed_mesh(seed, size)));
}

// Two independent countings agree: this file's census and the library's inspection, on the mixed
// meshes that are all triangles: fans, vertex components, duplicates.
RC_GTEST_PROP(RandomMixedMesh, CensusAgreesWithInspectMeshOnTriangles, ()) {
  const auto seed = *rc::gen::arbitrary<std::uint64_t>();
  const PolygonMesh mesh = random_mixed_mesh(seed, *rc::gen::inRange<std::uint32_t>(1, 1500));
  RC_PRE(mesh.all_triangles());
  const Census c = census(mesh);
  const MeshReport r = inspect_mesh(mesh);
  RC_ASSERT(r.referenced_vertices == c.vertices);
  RC_ASSERT(r.edges == c.edges);
  RC_ASSERT(r.faces == c.faces);
  RC_ASSERT(r.euler_characteristic == c.euler());
  RC_ASSERT(r.boundary_edges.count == c.boundary_edges);
  RC_ASSERT(r.non_manifold_edges.count == c.non_manifold_edges);
  RC_ASSERT(r.inconsistent_edges.count == c.inconsistent_edges);
  RC_ASSERT(r.pinched_vertices.count == c.pinched_vertices);
  RC_ASSERT(r.vertex_components == c.components);
  RC_ASSERT(r.duplicate_faces.empty());
  RC_ASSERT(r.degenerate_faces.empty());
}

// And with inspect_mesh, on every mixed mesh, polygons included.
RC_GTEST_PROP(RandomMixedMesh, CensusAgreesWithInspectMesh, ()) {
  const auto seed = *rc::gen::arbitrary<std::uint64_t>();
  const PolygonMesh mesh = random_mixed_mesh(seed, *rc::gen::inRange<std::uint32_t>(1, 1500));
  const Census c = census(mesh);
  const MeshReport r = inspect_mesh(mesh);
  RC_ASSERT(r.referenced_vertices == c.vertices);
  RC_ASSERT(r.edges == c.edges);
  RC_ASSERT(r.faces == c.faces);
  RC_ASSERT(r.euler_characteristic == c.euler());
  const auto triangles = r.faces_by_arity.find(3);
  RC_ASSERT(r.faces - (triangles == r.faces_by_arity.end() ? 0 : triangles->second) ==
            c.non_triangles);
  RC_ASSERT(r.boundary_edges.count == c.boundary_edges);
  RC_ASSERT(r.boundary_loops == c.boundary_loops);
  RC_ASSERT(r.non_manifold_edges.count == c.non_manifold_edges);
  RC_ASSERT(r.inconsistent_edges.count == c.inconsistent_edges);
  RC_ASSERT(r.degenerate_faces.empty());
  RC_ASSERT(r.components == c.edge_components);
  RC_ASSERT(r.orientable == c.orientable);
}

TEST(RandomMixedMesh, DrawsEveryKindOfMesh) {
  std::size_t polygons = 0, boundaries = 0, non_manifold = 0, non_orientable = 0, several = 0,
              pinched = 0, inconsistent = 0, closed_orientable = 0;
  std::size_t smallest = SIZE_MAX, largest = 0;
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    const std::uint32_t size = seed % 2 ? 2000 : 30;
    const PolygonMesh mesh = random_mixed_mesh(seed, size);
    const Census c = census(mesh);
    polygons += c.non_triangles > 0;
    boundaries += c.boundary_edges > 0;
    non_manifold += c.non_manifold_edges > 0;
    non_orientable += c.non_manifold_edges == 0 && !c.orientable;
    several += c.components > 1;
    pinched += c.pinched_vertices > 0;
    inconsistent += c.inconsistent_edges > 0;
    closed_orientable += c.boundary_edges == 0 && c.non_manifold_edges == 0 && c.orientable;
    smallest = std::min(smallest, c.faces);
    largest = std::max(largest, c.faces);
  }
  EXPECT_GT(polygons, 0u);
  EXPECT_GT(boundaries, 0u);
  EXPECT_GT(non_manifold, 0u);
  EXPECT_GT(non_orientable, 0u);
  EXPECT_GT(several, 0u);
  EXPECT_GT(pinched, 0u);
  EXPECT_GT(inconsistent, 0u);
  EXPECT_GT(closed_orientable, 0u);
  EXPECT_LT(smallest, 60u);
  EXPECT_GT(largest, 1000u);
}

}  // namespace
}  // namespace petersen
