#include "petersen/mesh/surface_check.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "petersen/generators/surface_generators.hpp"

namespace petersen {
namespace {

TriangleMesh tetrahedron(VertexId offset = 0) {
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  for (auto& t : mesh.triangles)
    for (auto& v : t) v += offset;
  return mesh;
}

TriangleMesh two_tetrahedra_sharing_vertex_0() {
  TriangleMesh mesh = tetrahedron();
  TriangleMesh other = tetrahedron(4);  // corners 4..7; rename 4 -> 0 to pinch
  mesh.positions.resize(8, {2, 2, 2});
  for (auto t : other.triangles) {
    for (auto& v : t) v = v == 4 ? 0 : v;
    mesh.triangles.push_back(t);
  }
  return mesh;
}

std::string requirement_error(const TriangleMesh& mesh, SurfaceRequirements req = {}) {
  try {
    require_closed_surface(mesh, req);
  } catch (const MeshError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SurfaceCheck, TetrahedronIsAClosedSphere) {
  const SurfaceReport r = inspect_surface(tetrahedron());
  EXPECT_TRUE(r.closed());
  EXPECT_EQ(r.vertices, 4u);
  EXPECT_EQ(r.edges, 6u);
  EXPECT_EQ(r.faces, 4u);
  EXPECT_EQ(r.components, 1u);
  EXPECT_EQ(r.euler_characteristic, 2);
  EXPECT_EQ(r.genus, 0u);
  EXPECT_EQ(requirement_error(tetrahedron()), "no error");
}

TEST(SurfaceCheck, PlatesHaveTheirGenus) {
  for (std::uint32_t holes : {1u, 2u, 3u}) {
    const SurfaceReport r = inspect_surface(voxel_plate({holes, 2, 1, false}));
    EXPECT_TRUE(r.closed());
    EXPECT_EQ(r.genus, 2 * holes);
    EXPECT_EQ(r.euler_characteristic, 2 - 4 * std::int64_t{holes});
  }
}

TEST(SurfaceCheck, PinchedVertexIsReportedAndAcceptedUnlessRefused) {
  const TriangleMesh mesh = two_tetrahedra_sharing_vertex_0();
  const SurfaceReport r = inspect_surface(mesh);
  EXPECT_TRUE(r.closed());
  EXPECT_EQ(r.pinched_vertices.count, 1u);
  EXPECT_EQ(r.pinched_vertices.first, std::vector<VertexId>{0});
  EXPECT_EQ(r.components, 1u);
  EXPECT_EQ(r.edge_components, 2u);
  EXPECT_EQ(r.euler_characteristic, 3);  // 7 - 12 + 8: one vertex shared
  EXPECT_EQ(r.genus, 0u);                // two spheres once the vertex is split
  EXPECT_EQ(r.unreferenced_vertices.first, std::vector<VertexId>{4});
  EXPECT_EQ(requirement_error(mesh), "no error");
  EXPECT_EQ(requirement_error(mesh, {.allow_pinched_vertices = false}),
            "not a closed surface: pinched vertex 0 (1 in all)");
  EXPECT_EQ(requirement_error(mesh, {.allow_several_components = false}),
            "not a closed surface: 2 components (triangles joined through edges)");
}

TEST(SurfaceCheck, EachProblemNamesItsFirstElement) {
  TriangleMesh open = tetrahedron();
  open.triangles.pop_back();
  const SurfaceReport r = inspect_surface(open);
  EXPECT_FALSE(r.closed());
  EXPECT_FALSE(r.genus);
  EXPECT_EQ(r.boundary_edges.count, 3u);
  EXPECT_EQ(requirement_error(open), "not a closed surface: boundary edge (0, 2) (3 such edges)");

  // Two tetrahedra sharing the edge 0-1: it lies in four triangles.
  TriangleMesh fin = tetrahedron();
  fin.positions.resize(6, {1, 1, 1});
  for (auto t : tetrahedron().triangles) {
    for (auto& v : t) v = v == 2 ? 4 : v == 3 ? 5 : v;
    fin.triangles.push_back(t);
  }
  EXPECT_EQ(inspect_surface(fin).non_manifold_edges.first, (std::vector<EdgeRef>{{1, 0}}));
  EXPECT_EQ(requirement_error(fin),
            "not a closed surface: non-manifold edge (1, 0) (1 such edges)");

  TriangleMesh flipped = tetrahedron();
  flipped.triangles[3] = {0, 2, 3};
  EXPECT_EQ(inspect_surface(flipped).inconsistent_edges.count, 3u);
  EXPECT_NE(requirement_error(flipped).find("inconsistently oriented edge"), std::string::npos);

  TriangleMesh degenerate = tetrahedron();
  degenerate.triangles.push_back({1, 1, 2});
  EXPECT_EQ(requirement_error(degenerate),
            "not a closed surface: degenerate triangle 4 (1 in all)");

  TriangleMesh out_of_range = tetrahedron();
  out_of_range.triangles[2][1] = 99;
  EXPECT_EQ(inspect_surface(out_of_range).out_of_range_triangles.first, std::vector<FaceId>{2});
  EXPECT_EQ(requirement_error(out_of_range),
            "not a closed surface: corner out of range in triangle 2 (1 in all)");

  // A two-triangle "pillow": closed edge by edge, but a duplicate.
  TriangleMesh pillow;
  pillow.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  pillow.triangles = {{0, 1, 2}, {0, 2, 1}};
  EXPECT_EQ(inspect_surface(pillow).duplicate_triangles.first, std::vector<FaceId>{1});
  EXPECT_EQ(requirement_error(pillow), "not a closed surface: duplicate triangle 1 (1 in all)");
  EXPECT_EQ(requirement_error(TriangleMesh{}), "not a closed surface: no triangles");
}

TEST(SurfaceCheck, DescribeListsCountsAndFirstElements) {
  TriangleMesh open = tetrahedron();
  open.triangles.pop_back();
  const std::string text = describe(inspect_surface(open));
  EXPECT_NE(text.find("V 4, E 6, F 3, components 1 (1 through edges), V - E + F 1, genus -"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("boundary edges: 3 ((0, 2), "), std::string::npos) << text;
}

// The scale series' layout: the same surface (every triangle, by its corners' positions, in the
// same orientation), closed with the same genus, its triangles now in Morton order.
TEST(SurfaceCheck, SpatialOrderKeepsTheSurface) {
  const TriangleMesh mesh = randomize_triangulation(voxel_plate({2, 1, 6, false}), 500, 1500, 3);
  const TriangleMesh ordered = spatially_ordered(mesh);
  ASSERT_EQ(ordered.triangles.size(), mesh.triangles.size());
  ASSERT_EQ(ordered.positions.size(), mesh.positions.size());
  const SurfaceReport before = inspect_surface(mesh), after = inspect_surface(ordered);
  EXPECT_TRUE(after.closed());
  EXPECT_EQ(after.genus, before.genus);
  EXPECT_EQ(after.genus, 2u);
  // Each triangle as its corners' positions, rotated to start at the smallest: the same multiset.
  auto as_positions = [](const TriangleMesh& m) {
    std::vector<std::array<std::array<double, 3>, 3>> out;
    for (const auto& t : m.triangles) {
      std::array<std::array<double, 3>, 3> p = {m.positions[t[0]], m.positions[t[1]],
                                                m.positions[t[2]]};
      std::rotate(p.begin(), std::min_element(p.begin(), p.end()), p.end());
      out.push_back(p);
    }
    std::sort(out.begin(), out.end());
    return out;
  };
  EXPECT_EQ(as_positions(ordered), as_positions(mesh));
  // Vertices in order of first use.
  VertexId next = 0;
  for (const auto& t : ordered.triangles)
    for (VertexId v : t) {
      ASSERT_LE(v, next);
      next = std::max(next, v + 1);
    }
}

}  // namespace
}  // namespace petersen
