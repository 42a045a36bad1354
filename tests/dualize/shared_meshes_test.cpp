// The real meshes in ../shared/meshes: each closed one loads with the V, F and genus SOURCES.md
// lists and converts through LEMON; each invalid one fails the way SOURCES.md says.

#include "shared_meshes.hpp"

#include <gtest/gtest.h>

#include "peers.hpp"
#include "petersen/dualize/dual.hpp"
#include "petersen/graph/connectivity.hpp"
#include "petersen/io/read_mesh.hpp"
#include "petersen/mesh/mesh_report.hpp"
#include "quad_mesh_check.hpp"

namespace petersen {
namespace {

// The >1M-triangle meshes take seconds under sanitizers; they are loaded in the plain build only.
// LEMON's matching is the slow peer: the conversion test keeps to the smaller meshes.
#ifdef PETERSEN_SANITIZE
constexpr std::uint32_t kMaxTriangles = 200000;
constexpr std::uint32_t kMaxLemonTriangles = 20000;
#else
constexpr std::uint32_t kMaxTriangles = 0xFFFFFFFFu;
constexpr std::uint32_t kMaxLemonTriangles = 100000;
#endif

TEST(SharedMeshes, ClosedOnesHaveTheListedCountsAndGenus) {
  const auto dir = testing::shared_mesh_dir();
  if (!dir) GTEST_SKIP() << "no ../shared/meshes (set PETERSEN_SHARED_MESHES)";
  for (const auto& expected : testing::shared_meshes_up_to(kMaxTriangles)) {
    SCOPED_TRACE(expected.file);
    const PolygonMesh mesh = read_mesh(*dir + "/" + expected.file);
    const MeshReport r = inspect_mesh(mesh);
    EXPECT_EQ(r.referenced_vertices, expected.vertices);
    EXPECT_EQ(r.faces, expected.triangles);
    EXPECT_EQ(r.faces_by_arity.at(3), expected.triangles);
    EXPECT_EQ(r.genus, expected.genus);
    EXPECT_TRUE(r.closed());
    EXPECT_EQ(r.components, 1u);
    EXPECT_EQ(r.vertex_components, 1u);
    EXPECT_TRUE(r.pinched_vertices.empty());
    EXPECT_NO_THROW(require_closed_surface(mesh, {false, false}));
  }
}

TEST(SharedMeshes, ClosedOnesConvertThroughLemon) {
  const auto dir = testing::shared_mesh_dir();
  if (!dir) GTEST_SKIP() << "no ../shared/meshes (set PETERSEN_SHARED_MESHES)";
  for (const auto& expected : testing::shared_meshes_up_to(kMaxLemonTriangles)) {
    SCOPED_TRACE(expected.file);
    const PolygonMesh mesh = read_mesh(*dir + "/" + expected.file);
    const CubicGraph dual = dual_graph(mesh);
    EXPECT_NO_THROW(validate_connected_bridgeless(dual));
    const Matching matching = testing::lemon_matching(dual);
    ASSERT_TRUE(verify_perfect_matching(dual, matching).ok());
    EXPECT_EQ(testing::quad_mesh_problem(mesh, testing::quads_of_matching(mesh, dual, matching)),
              "");
  }
}

TEST(SharedMeshes, InvalidOnesFailAsDescribed) {
  const auto dir = testing::shared_mesh_dir();
  if (!dir) GTEST_SKIP() << "no ../shared/meshes (set PETERSEN_SHARED_MESHES)";
  auto report = [&](const char* file) {
    return inspect_mesh(read_mesh(*dir + "/invalid/" + file));
  };

  const MeshReport bunny = report("stanford-bunny.obj.gz");
  EXPECT_EQ(bunny.boundary_edges.count, 223u);
  EXPECT_EQ(bunny.unreferenced_vertices.count, 1113u);
  EXPECT_FALSE(bunny.closed());

  const MeshReport teapot = report("teapot.obj.gz");
  EXPECT_EQ(teapot.boundary_edges.count, 1036u);
  EXPECT_EQ(teapot.vertex_components, 4u);
  EXPECT_EQ(teapot.components, 19u);

  const MeshReport beetle = report("beetle.obj.gz");
  EXPECT_EQ(beetle.non_manifold_edges.count, 47u);
  EXPECT_EQ(beetle.boundary_edges.count, 296u);
  EXPECT_EQ(beetle.vertex_components, 2u);

  for (const char* file : {"stanford-bunny.obj.gz", "teapot.obj.gz", "beetle.obj.gz"}) {
    const PolygonMesh mesh = read_mesh(*dir + "/invalid/" + file);
    EXPECT_THROW(require_closed_surface(mesh), MeshError) << file;
    EXPECT_THROW(dual_graph(mesh), MeshError) << file;
  }

  // cow: closed and edge-manifold, vertex 253 pinched; accepted and converted.
  const PolygonMesh cow = read_mesh(*dir + "/invalid/cow.obj.gz");
  const MeshReport r = inspect_mesh(cow);
  EXPECT_TRUE(r.closed());
  EXPECT_EQ(r.pinched_vertices.first, std::vector<VertexId>{253});
  EXPECT_EQ(r.euler_characteristic, 1);
  EXPECT_NO_THROW(require_closed_surface(cow));
  try {
    require_closed_surface(cow, {.allow_pinched_vertices = false});
    ADD_FAILURE() << "pinched vertex accepted";
  } catch (const MeshError& e) {
    EXPECT_NE(std::string(e.what()).find("pinched vertex 253"), std::string::npos) << e.what();
  }
  const CubicGraph dual = dual_graph(cow);
  EXPECT_NO_THROW(validate_connected_bridgeless(dual));
  EXPECT_EQ(testing::quad_mesh_problem(
                cow, testing::quads_of_matching(cow, dual, testing::lemon_matching(dual))),
            "");
}

}  // namespace
}  // namespace petersen
