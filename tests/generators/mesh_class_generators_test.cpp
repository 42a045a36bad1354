// The mesh classes' claimed topology and attributes, counted by the plain-container census
// (petersen/testing/mesh_census.hpp).

#include "petersen/generators/mesh_class_generators.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "petersen/generators/surface_generators.hpp"
#include "petersen/testing/mesh_census.hpp"
#include "petersen/testing/mesh_classes.hpp"

namespace petersen {
namespace {

using petersen::testing::census;
using petersen::testing::MeshCensus;

TEST(MobiusBand, IsAnOpenNonOrientableStripWithOneBoundaryLoop) {
  for (std::uint32_t u = 3; u <= 8; ++u) {
    for (std::uint32_t v = 1; v <= 4; ++v) {
      SCOPED_TRACE(::testing::Message() << u << " x " << v);
      const PolygonMesh mesh = mobius_band(u, v);
      const MeshCensus c = census(mesh);
      EXPECT_EQ(c.vertices, std::size_t{u} * (v + 1));
      EXPECT_EQ(c.faces, 2 * std::size_t{u} * v);
      EXPECT_EQ(c.euler(), 0);
      EXPECT_EQ(c.boundary_edges, 2 * std::size_t{u});
      EXPECT_EQ(c.boundary_loops, 1u);
      EXPECT_EQ(c.non_manifold_edges, 0u);
      EXPECT_EQ(c.pinched_vertices, 0u);
      EXPECT_EQ(c.components, 1u);
      EXPECT_FALSE(c.orientable);
      std::set<std::array<double, 3>> points(mesh.positions.begin(), mesh.positions.end());
      EXPECT_EQ(points.size(), mesh.positions.size());
    }
  }
  EXPECT_THROW(mobius_band(2, 3), std::invalid_argument);
  EXPECT_THROW(mobius_band(5, 0), std::invalid_argument);
}

TEST(QuadDominantGrid, MixesQuadsWithOddFacesAndKeepsTheGridsTopology) {
  for (bool torus : {false, true}) {
    const QuadDominantGrid spec{.nx = torus ? 12u : 8u,
                                .ny = torus ? 4u : 8u,
                                .torus = torus,
                                .triangle_squares = 2,
                                .pentagons = 3,
                                .hexagons = 2,
                                .seed = 7};
    const PolygonMesh mesh = quad_dominant_grid(spec);
    const MeshCensus c = census(mesh);
    std::size_t by_arity[7] = {};
    for (FaceId f = 0; f < mesh.face_count(); ++f) ++by_arity[std::min(mesh.arity(f), 6u)];
    EXPECT_GT(by_arity[4], by_arity[3] + by_arity[5] + by_arity[6]);
    EXPECT_GT(by_arity[3], 0u);
    EXPECT_EQ(by_arity[5], 3u);
    EXPECT_EQ(by_arity[6], 2u);
    EXPECT_EQ(c.euler(), torus ? 0 : 1);
    EXPECT_EQ(c.boundary_loops, torus ? 0u : 1u);
    EXPECT_TRUE(c.orientable);
    EXPECT_EQ(c.inconsistent_edges, 0u);
    EXPECT_EQ(c.non_manifold_edges, 0u);
    EXPECT_EQ(c.components, 1u);
  }
}

TEST(ChamferedCube, IsAClosedConsistentCubeOfSquaresBevelsAndCorners) {
  const PolygonMesh cube = chamfered_cube();
  const MeshCensus c = census(cube);
  EXPECT_EQ(c.vertices, 24u);
  EXPECT_EQ(c.faces, 26u);
  EXPECT_EQ(c.euler(), 2);
  EXPECT_EQ(c.boundary_edges, 0u);
  EXPECT_EQ(c.inconsistent_edges, 0u);
  EXPECT_TRUE(c.orientable);
  std::size_t by_arity[5] = {};
  for (FaceId f = 0; f < cube.face_count(); ++f) ++by_arity[std::min(cube.arity(f), 4u)];
  EXPECT_EQ(by_arity[3], 8u);
  EXPECT_EQ(by_arity[4], 18u);
  // Outward: each face's corners turn counter-clockwise about its centre's direction.
  for (FaceId f = 0; f < cube.face_count(); ++f) {
    const auto k = cube.face(f);
    const auto& a = cube.positions[k[0]];
    const auto& b = cube.positions[k[1]];
    const auto& d = cube.positions[k[2]];
    const std::array<double, 3> u = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const std::array<double, 3> v = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
    const std::array<double, 3> n = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                                     u[0] * v[1] - u[1] * v[0]};
    EXPECT_GT(n[0] * a[0] + n[1] * a[1] + n[2] * a[2], 0) << "face " << f;
  }
  // Split along either diagonal: every quad two triangles on its corners, the corners kept.
  for (bool first : {true, false}) {
    const PolygonMesh split = split_quads(cube, first);
    const MeshCensus t = census(split);
    EXPECT_EQ(t.faces, 8u + 2 * 18u);
    EXPECT_EQ(t.non_triangles, 0u);
    EXPECT_EQ(t.euler(), 2);
    EXPECT_EQ(t.inconsistent_edges, 0u);
  }
}

TEST(FlatShaded, GivesFaceNormalsTextureSeamsAndMaterials) {
  const PolygonMesh mesh =
      flat_shaded(random_closed_surface(0, 20, 20, 3), {.materials = 3, .seed = 5});
  EXPECT_NO_THROW(check_attributes(mesh));
  const MeshAttributes& a = mesh.attributes;
  ASSERT_EQ(a.normals.size(), mesh.face_count());
  std::set<std::array<double, 3>> texcoords_of_vertex0;
  std::size_t corner = 0;
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    const auto& n = a.normals[f];
    EXPECT_NEAR(std::hypot(n[0], n[1], n[2]), 1.0, 1e-12);
    for (VertexId v : mesh.face(f)) {
      EXPECT_EQ(a.corner_normal[corner], f);
      if (v == 0) texcoords_of_vertex0.insert(a.texcoords[a.corner_texcoord[corner]]);
      ++corner;
    }
  }
  // A cube's corner is on three faces of different axes: three charts meet there.
  EXPECT_GE(texcoords_of_vertex0.size(), 2u);
  EXPECT_EQ(a.material_names.size(), 3u);
  std::set<std::uint32_t> used(a.face_material.begin(), a.face_material.end());
  EXPECT_GE(used.size(), 1u);
}

TEST(ComponentCensus, CountsEachComponentApart) {
  const PolygonMesh parts[] = {mobius_band(5, 2), random_closed_surface(1, 10, 10, 2),
                               open_grid(3, 2), klein_bottle(4, 4)};
  const auto components = testing::component_census(concatenate(parts));
  using C = testing::ComponentCensus;
  const std::vector<C> expected = {{.euler = 0, .boundary_loops = 0, .orientable = false},
                                   {.euler = 0, .boundary_loops = 0, .orientable = true},
                                   {.euler = 0, .boundary_loops = 1, .orientable = false},
                                   {.euler = 1, .boundary_loops = 1, .orientable = true}};
  EXPECT_EQ(components, expected);
}

// Every class makes well-formed meshes of its kind, the same for the same seed.
RC_GTEST_PROP(MeshClasses, AreOfTheirClassAndDeterministic, ()) {
  for (testing::MeshClass c : testing::kMeshClasses) {
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    const auto faces = *rc::gen::inRange<std::uint32_t>(12, 120);
    const PolygonMesh mesh = testing::mesh_of_class(c, seed, faces);
    const PolygonMesh again = testing::mesh_of_class(c, seed, faces);
    RC_ASSERT(mesh.corners == again.corners);
    RC_ASSERT(mesh.face_count() > 0u);
    for (VertexId v : mesh.corners) RC_ASSERT(v < mesh.positions.size());
    const MeshCensus census_of = census(mesh);
    switch (c) {
      case testing::MeshClass::closed:
        RC_ASSERT(census_of.boundary_edges == 0u);
        RC_ASSERT(census_of.orientable);
        break;
      case testing::MeshClass::open_with_holes:
        RC_ASSERT(census_of.boundary_loops >= 1u);
        break;
      case testing::MeshClass::quad_dominant:
        RC_ASSERT(census_of.non_triangles >= 1u);
        break;
      case testing::MeshClass::non_manifold:
        RC_ASSERT(census_of.non_manifold_edges + census_of.pinched_vertices >= 1u);
        break;
      case testing::MeshClass::non_orientable:
        RC_ASSERT(!census_of.orientable);
        break;
      case testing::MeshClass::components:
        RC_ASSERT(census_of.edge_components >= 2u);
        break;
      case testing::MeshClass::textured:
        RC_ASSERT(!mesh.attributes.corner_texcoord.empty());
        RC_ASSERT(!mesh.attributes.face_material.empty());
        check_attributes(mesh);
        break;
    }
  }
}

}  // namespace
}  // namespace petersen
