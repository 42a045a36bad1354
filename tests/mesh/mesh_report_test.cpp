#include "petersen/mesh/mesh_report.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "petersen/generators/polygon_generators.hpp"
#include "petersen/generators/surface_generators.hpp"

namespace petersen {
namespace {

PolygonMesh tetrahedron(VertexId offset = 0) {
  PolygonMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  mesh.corners = {0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2};
  for (auto& v : mesh.corners) v += offset;
  return mesh;
}

void add_triangle(PolygonMesh& mesh, std::array<VertexId, 3> corners) {
  mesh.add_face(corners);
}

PolygonMesh two_tetrahedra_sharing_vertex_0() {
  PolygonMesh mesh = tetrahedron();
  const PolygonMesh other = tetrahedron(4);  // corners 4..7; rename 4 -> 0 to pinch
  mesh.positions.resize(8, {2, 2, 2});
  for (VertexId v : other.corners) mesh.corners.push_back(v == 4 ? 0 : v);
  return mesh;
}

std::string requirement_error(const PolygonMesh& mesh, SurfaceRequirements req = {}) {
  try {
    require_closed_surface(mesh, req);
  } catch (const MeshError& e) {
    return e.what();
  }
  return "no error";
}

TEST(MeshReport, TetrahedronIsAClosedSphere) {
  const MeshReport r = inspect_mesh(tetrahedron());
  EXPECT_TRUE(r.closed());
  EXPECT_EQ(r.referenced_vertices, 4u);
  EXPECT_EQ(r.edges, 6u);
  EXPECT_EQ(r.faces, 4u);
  EXPECT_EQ(r.components, 1u);
  EXPECT_EQ(r.vertex_components, 1u);
  EXPECT_EQ(r.euler_characteristic, 2);
  EXPECT_EQ(r.genus, 0);
  EXPECT_EQ(requirement_error(tetrahedron()), "no error");
}

TEST(MeshReport, PlatesHaveTheirGenus) {
  for (std::uint32_t holes : {1u, 2u, 3u}) {
    const MeshReport r = inspect_mesh(voxel_plate({holes, 2, 1, false}));
    EXPECT_TRUE(r.closed());
    EXPECT_EQ(r.genus, 2 * holes);
    EXPECT_EQ(r.euler_characteristic, 2 - 4 * std::int64_t{holes});
  }
}

TEST(MeshReport, PinchedVertexIsReportedAndAcceptedUnlessRefused) {
  const PolygonMesh mesh = two_tetrahedra_sharing_vertex_0();
  const MeshReport r = inspect_mesh(mesh);
  EXPECT_TRUE(r.closed());
  EXPECT_EQ(r.pinched_vertices.count, 1u);
  EXPECT_EQ(r.pinched_vertices.first, std::vector<VertexId>{0});
  EXPECT_EQ(r.components, 2u);
  EXPECT_EQ(r.vertex_components, 1u);
  EXPECT_EQ(r.euler_characteristic, 3);  // 7 - 12 + 8: one vertex shared
  EXPECT_EQ(r.genus, 0);                 // two spheres once the vertex is split
  EXPECT_EQ(r.unreferenced_vertices.first, std::vector<VertexId>{4});
  EXPECT_EQ(requirement_error(mesh), "no error");
  EXPECT_EQ(requirement_error(mesh, {.allow_pinched_vertices = false}),
            "not a closed surface: pinched vertex 0 (1 in all)");
  EXPECT_EQ(requirement_error(mesh, {.allow_several_components = false}),
            "not a closed surface: 2 components (triangles joined through edges)");
}

// Two pinches of one sphere (two pairs of its vertices merged): χ drops by two, the genus stays 0,
// as it does once each pinched vertex is split into its fans.
TEST(MeshReport, GenusCountsEachPinchedVertexAsSplit) {
  const PolygonMesh mesh = pinch_vertices(random_closed_surface(0, 300, 300, 1), 2, 5);
  const MeshReport r = inspect_mesh(mesh);
  ASSERT_EQ(r.pinched_vertices.count, 2u);
  EXPECT_EQ(r.euler_characteristic, 0);
  EXPECT_EQ(r.genus, 0);
}

TEST(MeshReport, EachProblemNamesItsFirstElement) {
  PolygonMesh open = tetrahedron();
  open.corners.resize(9);
  const MeshReport r = inspect_mesh(open);
  EXPECT_FALSE(r.closed());
  EXPECT_FALSE(r.genus);
  EXPECT_EQ(r.boundary_edges.count, 3u);
  EXPECT_EQ(requirement_error(open), "not a closed surface: boundary edge (0, 2) (3 such edges)");

  // Two tetrahedra sharing the edge 0-1: it lies in four triangles.
  PolygonMesh fin = tetrahedron();
  fin.positions.resize(6, {1, 1, 1});
  for (VertexId v : tetrahedron().corners) fin.corners.push_back(v == 2 ? 4 : v == 3 ? 5 : v);
  EXPECT_EQ(inspect_mesh(fin).non_manifold_edges.first, (std::vector<EdgeRef>{{1, 0}}));
  EXPECT_EQ(requirement_error(fin),
            "not a closed surface: non-manifold edge (1, 0) (1 such edges)");

  PolygonMesh flipped = tetrahedron();
  std::swap(flipped.corners[10], flipped.corners[11]);  // triangle 3 becomes (0, 2, 3)
  EXPECT_EQ(inspect_mesh(flipped).inconsistent_edges.count, 3u);
  EXPECT_NE(requirement_error(flipped).find("inconsistently oriented edge"), std::string::npos);

  PolygonMesh degenerate = tetrahedron();
  add_triangle(degenerate, {1, 1, 2});
  EXPECT_EQ(requirement_error(degenerate),
            "not a closed surface: degenerate triangle 4 (1 in all)");

  PolygonMesh out_of_range = tetrahedron();
  out_of_range.corners[7] = 99;  // corner 1 of triangle 2
  EXPECT_EQ(inspect_mesh(out_of_range).out_of_range_faces.first, std::vector<FaceId>{2});
  EXPECT_EQ(requirement_error(out_of_range),
            "not a closed surface: corner out of range in triangle 2 (1 in all)");

  // A two-triangle "pillow": closed edge by edge, but a duplicate.
  PolygonMesh pillow;
  pillow.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  pillow.corners = {0, 1, 2, 0, 2, 1};
  EXPECT_EQ(inspect_mesh(pillow).duplicate_faces.first, std::vector<FaceId>{1});
  EXPECT_EQ(requirement_error(pillow), "not a closed surface: duplicate triangle 1 (1 in all)");
  EXPECT_EQ(requirement_error(PolygonMesh{}), "not a closed surface: no triangles");
}

// Faces that are not triangles are named as faces.
TEST(MeshReport, PolygonsAreNamedAsFaces) {
  PolygonMesh cube = voxel_plate({0, 0, 1, false});
  PolygonMesh quads;
  quads.positions = cube.positions;
  const std::array<VertexId, 4> square{0, 1, 2, 3};
  quads.add_face(square);
  quads.add_face(std::array<VertexId, 4>{0, 1, 1, 3});
  EXPECT_EQ(requirement_error(quads), "not a closed surface: degenerate face 1 (1 in all)");
  quads.corners[0] = 99;
  EXPECT_EQ(requirement_error(quads),
            "not a closed surface: corner out of range in face 0 (1 in all)");
}

// The scale series' layout: the same surface (every triangle, by its corners' positions, in the
// same orientation), closed with the same genus, its triangles now in Morton order.
TEST(MeshReport, SpatialOrderKeepsTheSurface) {
  const PolygonMesh mesh = randomize_triangulation(voxel_plate({2, 1, 6, false}), 500, 1500, 3);
  const PolygonMesh ordered = spatially_ordered(mesh);
  ASSERT_EQ(ordered.face_count(), mesh.face_count());
  ASSERT_EQ(ordered.positions.size(), mesh.positions.size());
  ASSERT_TRUE(ordered.all_triangles());
  const MeshReport before = inspect_mesh(mesh), after = inspect_mesh(ordered);
  EXPECT_TRUE(after.closed());
  EXPECT_EQ(after.genus, before.genus);
  EXPECT_EQ(after.genus, 2);
  // Each triangle as its corners' positions, rotated to start at the smallest: the same multiset.
  auto as_positions = [](const PolygonMesh& m) {
    std::vector<std::array<std::array<double, 3>, 3>> out;
    for (FaceId t = 0; t < m.face_count(); ++t) {
      const auto c = m.face(t);
      std::array<std::array<double, 3>, 3> p = {m.positions[c[0]], m.positions[c[1]],
                                                m.positions[c[2]]};
      std::rotate(p.begin(), std::min_element(p.begin(), p.end()), p.end());
      out.push_back(p);
    }
    std::sort(out.begin(), out.end());
    return out;
  };
  EXPECT_EQ(as_positions(ordered), as_positions(mesh));
  // Vertices in order of first use.
  VertexId next = 0;
  for (VertexId v : ordered.corners) {
    ASSERT_LE(v, next);
    next = std::max(next, v + 1);
  }
}

}  // namespace
}  // namespace petersen
