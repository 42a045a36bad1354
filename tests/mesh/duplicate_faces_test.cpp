// duplicate_faces and drop_duplicate_faces: the same corners in any order or orientation are one
// face, the first kept; attributes stay with the faces kept.

#include "petersen/mesh/duplicate_faces.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

#include "petersen/mesh/mesh_report.hpp"
#include "petersen/testing/arbitrary.hpp"

namespace petersen {
namespace {

void add(PolygonMesh& mesh, std::vector<VertexId> corners) {
  mesh.add_face(corners);
}

TEST(DuplicateFaces, SameCornersInAnyOrderAreOneFace) {
  PolygonMesh mesh;
  mesh.positions.assign(6, {0, 0, 0});
  add(mesh, {0, 1, 2});     // 0
  add(mesh, {2, 1, 0});     // 1: reversed
  add(mesh, {1, 2, 0});     // 2: rotated
  add(mesh, {0, 1, 3});     // 3
  add(mesh, {0, 1, 2, 3});  // 4: a quad on the same vertices as 0 and 3 together
  add(mesh, {3, 2, 1, 0});  // 5
  add(mesh, {0, 0, 1});     // 6: degenerate
  add(mesh, {0, 1, 1});     // 7: other corners as a multiset
  add(mesh, {1, 0, 0});     // 8: the same as 6
  EXPECT_EQ(duplicate_faces(mesh), (std::vector<FaceId>{1, 2, 5, 8}));
  const MeshReport report = inspect_mesh(mesh);
  EXPECT_EQ(report.duplicate_faces.count, 4u);
  EXPECT_NE(describe(report).find("duplicate faces 4"), std::string::npos);
}

TEST(DuplicateFaces, DropKeepsTheFirstWithItsAttributes) {
  PolygonMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  add(mesh, {0, 1, 2});
  add(mesh, {2, 1, 0});
  add(mesh, {1, 3, 2});
  MeshAttributes& a = mesh.attributes;
  a.texcoords = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  a.corner_texcoord = {0, 1, 2, 2, 1, 0, 1, 3, 2};
  a.material_names = {"a", "b"};
  a.face_material = {0, 1, 1};
  a.face_properties.push_back({"quality", ScalarType::float32, {0.5, 0.25, 0.125}});
  const DroppedFaces result = drop_duplicate_faces(mesh);
  EXPECT_EQ(result.dropped, std::vector<FaceId>{1});
  const PolygonMesh& out = result.mesh;
  EXPECT_EQ(std::vector<VertexId>(out.corners.begin(), out.corners.end()),
            (std::vector<VertexId>{0, 1, 2, 1, 3, 2}));
  EXPECT_EQ(std::vector<std::uint32_t>(out.attributes.corner_texcoord.begin(),
                                       out.attributes.corner_texcoord.end()),
            (std::vector<std::uint32_t>{0, 1, 2, 1, 3, 2}));
  EXPECT_EQ(std::vector<std::uint32_t>(out.attributes.face_material.begin(),
                                       out.attributes.face_material.end()),
            (std::vector<std::uint32_t>{0, 1}));
  EXPECT_EQ(std::vector<double>(out.attributes.face_properties[0].values.begin(),
                                out.attributes.face_properties[0].values.end()),
            (std::vector<double>{0.5, 0.125}));
  EXPECT_EQ(out.attributes.texcoords.size(), 4u);
  check_attributes(out);
}

// Against a brute force over sorted corners: each face is a copy iff an earlier face has its
// sorted corners; dropping leaves no copies and every kind of face once, in input order.
RC_GTEST_PROP(DuplicateFaces, AgreeWithSortedCorners, ()) {
  PolygonMesh mesh = *testing::mixed_meshes();
  const auto faces = static_cast<FaceId>(mesh.face_count());
  for (std::uint32_t k = *rc::gen::inRange<std::uint32_t>(0, 6); k > 0; --k) {
    const auto c = mesh.face(*rc::gen::inRange<FaceId>(0, faces));
    std::vector<VertexId> copy(c.begin(), c.end());
    std::rotate(copy.begin(), copy.begin() + *rc::gen::inRange<std::size_t>(0, copy.size()),
                copy.end());
    if (*rc::gen::arbitrary<bool>()) std::reverse(copy.begin(), copy.end());
    mesh.add_face(copy);
  }
  std::set<std::vector<VertexId>> seen;
  std::vector<FaceId> expected;
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    const auto c = mesh.face(f);
    std::vector<VertexId> sorted(c.begin(), c.end());
    std::sort(sorted.begin(), sorted.end());
    if (!seen.insert(sorted).second) expected.push_back(f);
  }
  RC_ASSERT(duplicate_faces(mesh) == expected);
  std::vector<FaceId> backwards(mesh.face_count());
  for (FaceId f = 0; f < backwards.size(); ++f) backwards[f] = FaceId(backwards.size() - 1 - f);
  RC_ASSERT(duplicate_faces(mesh, backwards) == expected);
  const DroppedFaces dropped = drop_duplicate_faces(mesh);
  RC_ASSERT(dropped.mesh.face_count() == seen.size());
  RC_ASSERT(duplicate_faces(dropped.mesh).empty());
  RC_ASSERT(inspect_mesh(mesh).duplicate_faces.count == expected.size());
}

}  // namespace
}  // namespace petersen
