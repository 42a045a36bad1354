// Reading and writing meshes with attributes in a program that links petersen::io alone (plain
// GoogleTest, no test support, no matcher): OBJ with vt, vn, usemtl, g, s and vertex colours,
// binary PLY with typed vertex and face properties and per-corner texture coordinates, OFF with
// normals and vertex and face colours. Each is written, read back, and compared value by value.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "petersen/io/read_mesh.hpp"
#include "petersen/io/write_mesh.hpp"

namespace petersen {
namespace {

namespace fs = std::filesystem;

fs::path scratch_dir() {
  const fs::path dir =
      fs::temp_directory_path() / ("petersen-io-alone-" + std::to_string(::getpid()) + "-" +
                                   ::testing::UnitTest::GetInstance()->current_test_info()->name());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Five vertices, a square and two triangles; every value a float exactly, as a float PLY holds.
PolygonMesh base_mesh() {
  PolygonMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0.5}, {0, 1, -0.25}, {2, 0.75, 1.5}};
  mesh.add_face(std::vector<VertexId>{0, 1, 2, 3});
  mesh.add_face(std::vector<VertexId>{1, 4, 2});
  mesh.add_face(std::vector<VertexId>{3, 2, 4});
  return mesh;
}

template <class T>
std::vector<T> vec(const std::pmr::vector<T>& values) {
  return std::vector<T>(values.begin(), values.end());
}

void expect_same_faces(const PolygonMesh& read, const PolygonMesh& written) {
  ASSERT_EQ(read.face_count(), written.face_count());
  EXPECT_EQ(vec(read.positions), vec(written.positions));
  for (FaceId f = 0; f < read.face_count(); ++f) {
    EXPECT_EQ(std::vector<VertexId>(read.face(f).begin(), read.face(f).end()),
              std::vector<VertexId>(written.face(f).begin(), written.face(f).end()))
        << "face " << f;
  }
}

void expect_same_columns(const std::vector<PropertyColumn>& read,
                         const std::vector<PropertyColumn>& written) {
  ASSERT_EQ(read.size(), written.size());
  for (std::size_t c = 0; c < read.size(); ++c) {
    EXPECT_EQ(read[c].name, written[c].name);
    EXPECT_EQ(read[c].type, written[c].type) << read[c].name;
    EXPECT_EQ(std::vector<double>(read[c].values.begin(), read[c].values.end()),
              std::vector<double>(written[c].values.begin(), written[c].values.end()))
        << read[c].name;
  }
}

// The texture coordinate of every corner (u, v, w), or none: how a file's corners compare when
// the reader numbers texture coordinates its own way (PLY: one per corner).
std::vector<std::array<double, 3>> corner_texcoords(const PolygonMesh& mesh) {
  std::vector<std::array<double, 3>> out;
  const MeshAttributes& a = mesh.attributes;
  for (std::size_t k = 0; k < mesh.corners.size(); ++k) {
    const std::uint32_t t = a.corner_texcoord.empty() ? kNoAttribute : a.corner_texcoord[k];
    out.push_back(t == kNoAttribute ? std::array<double, 3>{-9, -9, -9} : a.texcoords[t]);
  }
  return out;
}

PolygonMesh written_and_read(const PolygonMesh& mesh, const fs::path& path) {
  const std::vector<std::string> dropped = write_mesh(path.string(), mesh);
  EXPECT_TRUE(dropped.empty()) << dropped.front();
  std::vector<std::string> read_dropped;
  PolygonMesh read = read_mesh(path.string(), &read_dropped);
  EXPECT_TRUE(read_dropped.empty()) << read_dropped.front();
  return read;
}

TEST(IoAlone, ObjWithTexcoordsNormalsMaterialsGroupsSmoothingAndColours) {
  PolygonMesh mesh = base_mesh();
  MeshAttributes& a = mesh.attributes;
  a.texcoords = {{0, 0, 0}, {1, 0, 0}, {0.5, 0.25, 0}};
  a.normals = {{0, 0, 1}, {0.25, -0.5, 0.75}};
  // The square has texture coordinates and normals, the first triangle normals only, the last
  // neither on one corner.
  a.corner_texcoord = {0, 1, 2, 1, kNoAttribute, kNoAttribute, kNoAttribute, 2, 0, kNoAttribute};
  a.corner_normal = {0, 0, 1, 1, 1, 0, 1, 0, kNoAttribute, 1};
  a.material_names = {"stone", "gold leaf"};
  a.face_material = {0, 0, 1};
  a.group_names = {"left arm"};
  a.face_group = {kNoAttribute, 0, 0};
  a.face_smoothing = {0, 3, 3};
  a.material_libraries = {"scene.mtl"};
  for (const char* name : {"red", "green", "blue"}) {
    a.vertex_properties.push_back({name, ScalarType::float32, {0, 0.25, 0.5, 0.75, 1}});
  }
  const PolygonMesh read = written_and_read(mesh, scratch_dir() / "m.obj");
  expect_same_faces(read, mesh);
  const MeshAttributes& r = read.attributes;
  EXPECT_EQ(vec(r.texcoords), vec(a.texcoords));
  EXPECT_EQ(r.texcoord_components, 2);
  EXPECT_EQ(vec(r.normals), vec(a.normals));
  EXPECT_EQ(vec(r.corner_texcoord), vec(a.corner_texcoord));
  EXPECT_EQ(vec(r.corner_normal), vec(a.corner_normal));
  EXPECT_EQ(r.material_names, a.material_names);
  EXPECT_EQ(vec(r.face_material), vec(a.face_material));
  EXPECT_EQ(r.group_names, a.group_names);
  EXPECT_EQ(vec(r.face_group), vec(a.face_group));
  EXPECT_TRUE(r.object_names.empty());
  EXPECT_TRUE(r.face_object.empty());
  EXPECT_EQ(vec(r.face_smoothing), vec(a.face_smoothing));
  EXPECT_EQ(r.material_libraries, a.material_libraries);
  expect_same_columns(r.vertex_properties, a.vertex_properties);
  EXPECT_TRUE(r.face_properties.empty());
}

TEST(IoAlone, PlyWithTypedVertexAndFacePropertiesAndCornerTexcoords) {
  PolygonMesh mesh = base_mesh();
  MeshAttributes& a = mesh.attributes;
  a.position_type = ScalarType::float32;
  a.vertex_properties = {
      {"quality", ScalarType::float32, {0.5, -1.25, 3, 0, 1e-3f}},
      {"flags", ScalarType::uint8, {0, 1, 128, 255, 7}},
      {"id", ScalarType::int32, {-2147483647.0 - 1, -1, 0, 1, 2147483647}},
      {"weight", ScalarType::float64, {0.1, 1e300, -2.5e-300, 3, 0}},
      {"level", ScalarType::int16, {-32768, -1, 0, 1, 32767}},
  };
  a.face_properties = {
      {"label", ScalarType::uint16, {0, 65535, 12}},
      {"area", ScalarType::float32, {0.5, 0.25, 0.125}},
      {"tag", ScalarType::int8, {-128, 0, 127}},
      {"count", ScalarType::uint32, {0, 4294967295.0, 1}},
  };
  // Every corner of a face has texture coordinates, or none does (the second triangle).
  a.texcoords = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.25, 0}};
  a.corner_texcoord = {0, 1, 2, 3, 1, 4, 2, kNoAttribute, kNoAttribute, kNoAttribute};
  const PolygonMesh read = written_and_read(mesh, scratch_dir() / "m.ply");
  expect_same_faces(read, mesh);
  const MeshAttributes& r = read.attributes;
  EXPECT_EQ(r.position_type, ScalarType::float32);
  expect_same_columns(r.vertex_properties, a.vertex_properties);
  expect_same_columns(r.face_properties, a.face_properties);
  EXPECT_EQ(corner_texcoords(read), corner_texcoords(mesh));
  EXPECT_TRUE(r.normals.empty());
  EXPECT_TRUE(r.corner_normal.empty());
  EXPECT_TRUE(r.face_material.empty() && r.face_group.empty() && r.face_smoothing.empty());
}

TEST(IoAlone, OffWithNormalsAndVertexAndFaceColours) {
  PolygonMesh mesh = base_mesh();
  MeshAttributes& a = mesh.attributes;
  // As the reader orders them: normals, then the colour.
  a.vertex_properties = {
      {"nx", ScalarType::float32, {0, 1, 0, 0.5, -1}},
      {"ny", ScalarType::float32, {0, 0, 1, 0.5, 0}},
      {"nz", ScalarType::float32, {1, 0, 0, 0.25, 0}},
      {"red", ScalarType::uint8, {255, 0, 0, 10, 20}},
      {"green", ScalarType::uint8, {0, 255, 0, 30, 40}},
      {"blue", ScalarType::uint8, {0, 0, 255, 50, 60}},
      {"alpha", ScalarType::uint8, {255, 255, 255, 128, 0}},
  };
  // Whole numbers too: a float colour is written so that it reads back as float.
  a.face_properties = {
      {"red", ScalarType::float32, {0.5, 1, 0}},
      {"green", ScalarType::float32, {0.25, 0, 1}},
      {"blue", ScalarType::float32, {0.125, 0, 0.75}},
  };
  const PolygonMesh read = written_and_read(mesh, scratch_dir() / "m.off");
  expect_same_faces(read, mesh);
  expect_same_columns(read.attributes.vertex_properties, a.vertex_properties);
  expect_same_columns(read.attributes.face_properties, a.face_properties);
  EXPECT_FALSE(read.attributes.has_corner_attributes());
}

TEST(IoAlone, ErrorsCarryTheFileAndTheLine) {
  const fs::path dir = scratch_dir();
  try {
    read_mesh((dir / "missing.off").string());
    FAIL() << "read a missing file";
  } catch (const FileError& e) {
    EXPECT_EQ(e.file(), (dir / "missing.off").string());
    EXPECT_EQ(e.line(), 0u);
  }
  try {
    parse_mesh("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", MeshFormat::off, "bad.off");
    FAIL() << "parsed an index out of range";
  } catch (const FileError& e) {
    EXPECT_EQ(e.file(), "bad.off");
    EXPECT_EQ(e.line(), 6u);
    EXPECT_STREQ(e.what(), "bad.off:6: face 0: vertex index 7 out of range (3 vertices)");
  }
}

}  // namespace
}  // namespace petersen
