// Attributes through the readers and writers: each format's syntax for them, round trips (read,
// write, read gives the same data) on examples and on random meshes, what a conversion drops,
// located errors in the new syntax, and check_attributes.

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "petersen/io/read_mesh.hpp"
#include "petersen/io/write_mesh.hpp"
#include "petersen/testing/random_attributes.hpp"

namespace petersen {
using testing::AttributeSet;
using testing::meshes_with_attributes;
namespace {

namespace fs = std::filesystem;

fs::path scratch_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  fs::path dir = fs::temp_directory_path() /
                 ("petersen-attr-" + std::to_string(::getpid()) + "-" + info->name());
  fs::create_directories(dir);
  return dir;
}

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::string error_of(std::string_view bytes, MeshFormat format, ReadMeshOptions options = {}) {
  try {
    parse_mesh(bytes, format, "in", nullptr, options);
  } catch (const FileError& e) {
    return e.what();
  }
  return "no error";
}

#define EXPECT_ERROR(bytes, format, expected)                                 \
  do {                                                                        \
    const std::string error_ = error_of(bytes, format);                       \
    EXPECT_NE(error_.find(expected), std::string::npos) << "got: " << error_; \
  } while (0)

std::size_t first_corner(const PolygonMesh& mesh, FaceId f) {
  return mesh.all_triangles() ? 3 * std::size_t{f} : mesh.face_start[f];
}

// What a mesh carries, with every index resolved to its value, so that two meshes compare equal
// when they carry the same data however a format numbers it (PLY gives every corner its own
// texture coordinate; OBJ numbers names in the order faces first use them).
std::string resolved_corner(const PolygonMesh& mesh, std::size_t c) {
  const MeshAttributes& a = mesh.attributes;
  std::string out;
  const std::uint32_t t = a.corner_texcoord.empty() ? kNoAttribute : a.corner_texcoord[c];
  const std::uint32_t n = a.corner_normal.empty() ? kNoAttribute : a.corner_normal[c];
  if (t != kNoAttribute) {
    for (int k = 0; k < a.texcoord_components; ++k) out += std::to_string(a.texcoords[t][k]) + " ";
    out += "w=" + std::to_string(a.texcoords[t][2]);  // a dropped w shows
  }
  out += "/";
  if (n != kNoAttribute) {
    for (double x : a.normals[n]) out += std::to_string(x) + " ";
  }
  return out;
}

std::string resolved_face(const PolygonMesh& mesh, FaceId f) {
  const MeshAttributes& a = mesh.attributes;
  auto name = [f](const std::pmr::vector<std::uint32_t>& values,
                  const std::vector<std::string>& names) {
    return values.empty() || values[f] == kNoAttribute ? std::string("-") : names[values[f]];
  };
  return name(a.face_material, a.material_names) + "|" + name(a.face_group, a.group_names) + "|" +
         name(a.face_object, a.object_names) + "|" +
         std::to_string(a.face_smoothing.empty() ? 0 : a.face_smoothing[f]);
}

std::string columns_text(const std::vector<PropertyColumn>& columns) {
  std::string out;
  for (const PropertyColumn& column : columns) {
    out += column.name + ":" + std::to_string(int(column.type)) + "[";
    for (double x : column.values) {
      char buffer[32];
      std::snprintf(buffer, sizeof buffer, "%.17g ", x);
      out += buffer;
    }
    out += "] ";
  }
  return out;
}

// The first difference in the data two meshes carry, or "" when they carry the same.
std::string difference(const PolygonMesh& a, const PolygonMesh& b) {
  if (a.positions.size() != b.positions.size()) return "vertex counts";
  for (std::size_t v = 0; v < a.positions.size(); ++v) {
    if (a.positions[v] != b.positions[v]) {
      char buffer[256];
      std::snprintf(buffer, sizeof buffer,
                    "vertex %zu: %.17g %.17g %.17g against %.17g %.17g %.17g", v, a.positions[v][0],
                    a.positions[v][1], a.positions[v][2], b.positions[v][0], b.positions[v][1],
                    b.positions[v][2]);
      return buffer + std::string(" types ") + std::to_string(int(a.attributes.position_type)) +
             " " + std::to_string(int(b.attributes.position_type));
    }
  }
  if (a.face_count() != b.face_count()) return "face counts";
  for (FaceId f = 0; f < a.face_count(); ++f) {
    if (!std::equal(a.face(f).begin(), a.face(f).end(), b.face(f).begin(), b.face(f).end())) {
      return "face " + std::to_string(f);
    }
    if (resolved_face(a, f) != resolved_face(b, f)) {
      return "face " + std::to_string(f) + ": " + resolved_face(a, f) + " against " +
             resolved_face(b, f);
    }
    for (std::size_t c = first_corner(a, f); c < first_corner(a, f) + a.arity(f); ++c) {
      if (resolved_corner(a, c) != resolved_corner(b, c)) {
        return "corner " + std::to_string(c) + ": " + resolved_corner(a, c) + " against " +
               resolved_corner(b, c);
      }
    }
  }
  if (columns_text(a.attributes.vertex_properties) !=
      columns_text(b.attributes.vertex_properties)) {
    return "vertex properties: " + columns_text(a.attributes.vertex_properties).substr(0, 300) +
           " against " + columns_text(b.attributes.vertex_properties).substr(0, 300);
  }
  if (columns_text(a.attributes.face_properties) != columns_text(b.attributes.face_properties)) {
    return "face properties: " + columns_text(a.attributes.face_properties).substr(0, 300) +
           " against " + columns_text(b.attributes.face_properties).substr(0, 300);
  }
  if (a.attributes.material_libraries != b.attributes.material_libraries) return "mtllib";
  return "";
}

std::string joined(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& line : lines) out += line + "\n";
  return out;
}

// ---------------------------------------------------------------------------------------------
// OBJ

const std::string kObj =
    "# a textured square and a triangle\n"
    "mtllib scene.mtl\n"
    "mtllib other lib.mtl\n"
    "v 0 0 0 1 0 0\n"
    "v 1 0 0 0 1 0\n"
    "v 1 1 0 0 0 1\n"
    "v 0 1 0 0.5 0.5 0.5\n"
    "vt 0 0\n"
    "vt 1 0 0.25\n"
    "vt 1 1\n"
    "vn 0 0 1\n"
    "vn 0 0 -1\n"
    "o thing\n"
    "g left arm\n"
    "usemtl red\n"
    "s 1\n"
    "f 1/1/1 2/2/1 3/3/1 4//2\n"
    "l 1 2\n"
    "usemtl blue\n"
    "s off\n"
    "f -4/-3 -3/-2 -2/-1\n"
    "p 1\n"
    "g\n"
    "f 1 3 4\n"
    "l 3 4\n";

TEST(ObjAttributes, EveryStatementIsKept) {
  std::vector<std::string> dropped;
  const PolygonMesh mesh = parse_mesh(kObj, MeshFormat::obj, "in", &dropped);
  const MeshAttributes& a = mesh.attributes;
  ASSERT_EQ(mesh.face_count(), 3u);
  EXPECT_EQ(a.material_libraries, (std::vector<std::string>{"scene.mtl", "other lib.mtl"}));
  EXPECT_EQ(a.texcoord_components, 3);
  EXPECT_EQ(a.texcoords.size(), 3u);
  EXPECT_EQ(a.texcoords[1], (std::array<double, 3>{1, 0, 0.25}));
  EXPECT_EQ(a.normals.size(), 2u);
  const std::vector<std::uint32_t> texcoords{
      0, 1, 2, kNoAttribute, 0, 1, 2, kNoAttribute, kNoAttribute, kNoAttribute};
  EXPECT_EQ(std::vector<std::uint32_t>(a.corner_texcoord.begin(), a.corner_texcoord.end()),
            texcoords);
  const std::vector<std::uint32_t> normals{
      0,           0, 0, 1, kNoAttribute, kNoAttribute, kNoAttribute, kNoAttribute, kNoAttribute,
      kNoAttribute};
  EXPECT_EQ(std::vector<std::uint32_t>(a.corner_normal.begin(), a.corner_normal.end()), normals);
  EXPECT_EQ(resolved_face(mesh, 0), "red|left arm|thing|1");
  EXPECT_EQ(resolved_face(mesh, 1), "blue|left arm|thing|0");
  EXPECT_EQ(resolved_face(mesh, 2), "blue|-|thing|0");
  ASSERT_EQ(a.vertex_properties.size(), 3u);
  EXPECT_EQ(a.vertex_properties[0].name, "red");
  EXPECT_EQ(a.vertex_properties[2].values[3], 0.5);
  EXPECT_EQ(dropped, (std::vector<std::string>{"2 'l' lines, the first at line 18",
                                               "1 'p' lines, the first at line 22"}));
}

TEST(ObjAttributes, AFaceBeforeTheFirstValueHasNone) {
  const PolygonMesh mesh = parse_mesh(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1 2 3\nusemtl m\nf 1/1 2 3\n", MeshFormat::obj, "in");
  EXPECT_EQ(resolved_face(mesh, 0), "-|-|-|0");
  EXPECT_EQ(resolved_face(mesh, 1), "m|-|-|0");
  ASSERT_EQ(mesh.attributes.corner_texcoord.size(), 6u);
  EXPECT_EQ(mesh.attributes.corner_texcoord[0], kNoAttribute);
  EXPECT_EQ(mesh.attributes.corner_texcoord[3], 0u);
  EXPECT_TRUE(mesh.attributes.corner_normal.empty());
}

TEST(ObjAttributes, ErrorsAreLocated) {
  const std::string vs = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n";
  const ReadMeshOptions strict{.strict = true};
  EXPECT_EQ(error_of(vs + "f 1/2 2 3\n", MeshFormat::obj, strict),
            "in:6: face 1: texture coordinate index 2 out of range (1 texture coordinates read "
            "so far)");
  EXPECT_EQ(error_of(vs + "f 1/-2 2 3\n", MeshFormat::obj, strict)
                .rfind("in:6: face 1: texture coordinate index -2", 0),
            0u);
  EXPECT_EQ(error_of(vs + "f 1 2 3\nf 1//2 2 3\n", MeshFormat::obj, strict),
            "in:7: face 2: normal index 2 out of range (1 normals read so far)");
  EXPECT_ERROR(vs + "f 1/0 2 3\n", MeshFormat::obj, "in:6: face 1: bad texture coordinate index");
  EXPECT_ERROR(vs + "f 1//x 2 3\n", MeshFormat::obj, "in:6: face 1: bad normal index '1//x'");
  EXPECT_ERROR(vs + "f 1/1/1/1 2 3\n", MeshFormat::obj, "in:6: face 1: bad corner '1/1/1/1'");
  EXPECT_ERROR(vs + "vt\n", MeshFormat::obj, "in:6: texture coordinate 2: expected 1 to 3 values");
  EXPECT_ERROR(vs + "vt 0 0 0 0\n", MeshFormat::obj, "in:6: texture coordinate 2: more than 3");
  EXPECT_ERROR(vs + "vn 0 1\n", MeshFormat::obj, "in:6: normal 2: expected 3 values");
  EXPECT_ERROR(vs + "vn 0 1 nan\n", MeshFormat::obj, "in:6: normal 2: bad value 'nan'");
  EXPECT_ERROR(vs + "s on\n", MeshFormat::obj, "in:6: bad smoothing group 'on'");
  EXPECT_ERROR(vs + "mtllib\n", MeshFormat::obj, "in:6: mtllib without a file name");
  EXPECT_ERROR("v 0 0 0 1 x 0\n", MeshFormat::obj, "in:1: vertex 1: bad value 'x'");
}

// A texture coordinate or normal index past those the file has drops that attribute of that face
// (every corner of it), with one line per attribute saying how many faces and the first line; the
// geometry and the other faces' attributes are read as written. Strict refuses instead.
TEST(ObjAttributes, DanglingIndicesDropTheFacesAttribute) {
  const std::string obj =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n"
      "f 1/1/1 2/2/1 3/3/1\n"   // line 9: whole
      "f 2/2/1 4/4/1 3/3/1\n"   // line 10: texture coordinate 4 dangles
      "f 1//2 2//1 3//1\n"      // line 11: normal 2 dangles
      "f 1/1/3 2/9/3 3/3/3\n";  // line 12: both dangle
  std::vector<std::string> dropped;
  const PolygonMesh mesh = parse_mesh(obj, MeshFormat::obj, "in", &dropped);
  ASSERT_EQ(mesh.face_count(), 4u);
  const auto second = mesh.face(1);
  EXPECT_EQ(std::vector<VertexId>(second.begin(), second.end()), (std::vector<VertexId>{1, 3, 2}));
  const MeshAttributes& a = mesh.attributes;
  const std::vector<std::uint32_t> texcoords(a.corner_texcoord.begin(), a.corner_texcoord.end());
  const std::vector<std::uint32_t> normals(a.corner_normal.begin(), a.corner_normal.end());
  const std::uint32_t n = kNoAttribute;
  EXPECT_EQ(texcoords, (std::vector<std::uint32_t>{0, 1, 2, n, n, n, n, n, n, n, n, n}));
  EXPECT_EQ(normals, (std::vector<std::uint32_t>{0, 0, 0, 0, 0, 0, n, n, n, n, n, n}));
  EXPECT_EQ(dropped, (std::vector<std::string>{
                         "2 faces' texture coordinate indices past the file's texture coordinates "
                         "(those faces have none), the first at line 10",
                         "2 faces' normal indices past the file's normals (those faces have "
                         "none), the first at line 11"}));
  check_attributes(mesh);
  EXPECT_EQ(error_of(obj, MeshFormat::obj, {.strict = true}),
            "in:10: face 2: texture coordinate index 4 out of range (3 texture coordinates read "
            "so far)");
  // A file with no normals at all, as a subdivision suite writes them: read as if none were named.
  dropped.clear();
  const PolygonMesh bare =
      parse_mesh("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2//1 3//1\n", MeshFormat::obj, "in", &dropped);
  EXPECT_TRUE(bare.attributes.corner_normal.empty());
  EXPECT_EQ(dropped.size(), 1u);
}

TEST(ObjAttributes, RoundTripKeepsEveryStatement) {
  const fs::path dir = scratch_dir();
  const PolygonMesh mesh = parse_mesh(kObj, MeshFormat::obj, "in");
  const std::string path = (dir / "a.obj").string();
  EXPECT_TRUE(write_mesh(path, mesh).empty());
  const std::string text = slurp(path);
  EXPECT_EQ(text.substr(0, 39), "mtllib scene.mtl\nmtllib other lib.mtl\nv");
  EXPECT_NE(text.find("\nv 1 0 0 0 1 0\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\nvt 1 0 0.25\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\no thing\ng left arm\nusemtl red\ns 1\nf 1/1/1 2/2/1 3/3/1 4//2\n"
                      "usemtl blue\ns off\nf 1/1 2/2 3/3\ng\nf 1 3 4\n"),
            std::string::npos)
      << text;
  const PolygonMesh back = read_mesh(path);
  EXPECT_EQ(difference(mesh, back), "");
}

// ---------------------------------------------------------------------------------------------
// OFF

TEST(OffAttributes, NormalsColoursAndTextureCoordinates) {
  const std::string text =
      "STCNOFF\n3 2 0\n"
      "0 0 0  0 0 1  255 0 0 255  0.5 0.25\n"
      "1 0 0  0 0 1  0 255 0 128  1 0\n"
      "0 1 0  0 0 1  0 0 255 0  0 1\n"
      "3 0 1 2 0.5 0.25 1\n"
      "3 0 2 1\n";
  std::vector<std::string> dropped;
  const PolygonMesh mesh = parse_mesh(text, MeshFormat::off, "in", &dropped);
  const auto& vertex = mesh.attributes.vertex_properties;
  ASSERT_EQ(vertex.size(), 9u);
  const char* names[] = {"nx", "ny", "nz", "s", "t", "red", "green", "blue", "alpha"};
  for (std::size_t k = 0; k < 9; ++k) EXPECT_EQ(vertex[k].name, names[k]);
  EXPECT_EQ(vertex[2].type, ScalarType::float32);
  EXPECT_EQ(vertex[5].type, ScalarType::uint8);
  EXPECT_EQ(vertex[8].values[1], 128);
  EXPECT_EQ(vertex[3].values[0], 0.5);
  const auto& face = mesh.attributes.face_properties;
  ASSERT_EQ(face.size(), 3u);
  EXPECT_EQ(face[0].type, ScalarType::float32);
  EXPECT_EQ(face[1].values[0], 0.25);
  EXPECT_EQ(face[1].values[1], 0);
  EXPECT_EQ(
      dropped,
      (std::vector<std::string>{"1 faces without a colour in a file with colours: given 0 0 0"}));
  const fs::path dir = scratch_dir();
  EXPECT_TRUE(write_mesh((dir / "a.off").string(), mesh).empty());
  EXPECT_EQ(slurp(dir / "a.off").substr(0, 52),
            "STCNOFF\n3 2 0\n0 0 0 0.0 0.0 1.0 255 0 0 255 0.5 0.25");
  EXPECT_EQ(difference(mesh, read_mesh((dir / "a.off").string())), "");
}

TEST(OffAttributes, UndeclaredValuesAreReportedAndBadColoursLocated) {
  std::vector<std::string> dropped;
  parse_mesh("OFF\n3 1 0\n0 0 0 1\n1 0 0\n0 1 0 1\n3 0 1 2 7\n", MeshFormat::off, "in", &dropped);
  EXPECT_EQ(dropped, (std::vector<std::string>{
                         "2 vertex lines with values the keyword does not declare, the first at "
                         "line 3",
                         "1 face lines with values after the indices that are not a colour (a "
                         "colour-map index), the first at line 6"}));
  const std::string vs = "0 0 0 1 1 1\n1 0 0 1 1 1\n0 1 0 1 1 1\n";
  EXPECT_ERROR("COFF\n3 1 0\n0 0 0 1 1\n1 0 0 1 1 1\n0 1 0 1 1 1\n3 0 1 2\n", MeshFormat::off,
               "in:3: vertex 0: expected a colour after x y z");
  EXPECT_ERROR("COFF\n3 1 0\n0 0 0 1 1 1\n1 0 0 1 1 1 1\n0 1 0 1 1 1\n3 0 1 2\n", MeshFormat::off,
               "in:4: vertex 1: bad colour");
  EXPECT_ERROR("NOFF\n3 1 0\n0 0 0 1 x 1\n1 0 0 1 1 1\n0 1 0 1 1 1\n3 0 1 2\n", MeshFormat::off,
               "in:3: vertex 0: bad value 'x'");
  EXPECT_ERROR("COFF\n3 2 0\n" + vs + "3 0 1 2 1 1 1\n3 0 2 1 1 1 1 1\n", MeshFormat::off,
               "in:7: face 1: bad colour");
  EXPECT_ERROR("COFF\n3 1 0\n" + vs + "3 0 1 2 1 x 1\n", MeshFormat::off,
               "in:6: face 0: bad colour");
}

// ---------------------------------------------------------------------------------------------
// PLY

const std::string kPlyHeader =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
    "property float z\nproperty uchar red\nproperty short temperature\nproperty list uchar int "
    "neighbours\nelement face 2\nproperty list uchar int vertex_indices\nproperty int "
    "texnumber\nproperty list uchar float texcoord\nelement edge 1\nproperty int vertex1\n"
    "property int vertex2\nend_header\n";

TEST(PlyAttributes, PropertiesAndCornerTexcoordsAreKept) {
  const std::string text = kPlyHeader +
                           "0 0 0 255 -7 1 0\n1 0 0 0 300 0\n1 1 0 9 0 0\n0 1 0 1 1 0\n"
                           "4 0 1 2 3 2 8 0 0 1 0 1 1 0 1\n3 0 2 3 5 0\n0 1\n";
  std::vector<std::string> dropped;
  const PolygonMesh mesh = parse_mesh(text, MeshFormat::ply, "in", &dropped);
  const MeshAttributes& a = mesh.attributes;
  ASSERT_EQ(a.vertex_properties.size(), 2u);
  EXPECT_EQ(a.vertex_properties[0].name, "red");
  EXPECT_EQ(a.vertex_properties[0].type, ScalarType::uint8);
  EXPECT_EQ(a.vertex_properties[1].type, ScalarType::int16);
  EXPECT_EQ(a.vertex_properties[1].values[0], -7);
  ASSERT_EQ(a.face_properties.size(), 1u);
  EXPECT_EQ(a.face_properties[0].values[1], 5);
  ASSERT_EQ(a.corner_texcoord.size(), 7u);
  EXPECT_EQ(a.texcoords[a.corner_texcoord[2]], (std::array<double, 3>{1, 1, 0}));
  EXPECT_EQ(a.corner_texcoord[4], kNoAttribute);    // the triangle's list is empty
  EXPECT_EQ(a.position_type, ScalarType::float64);  // ascii positions keep their digits
  EXPECT_EQ(dropped, (std::vector<std::string>{"vertex list property 'neighbours'",
                                               "element 'edge' (1 records)"}));
  // Written as binary PLY and read back: the same data, every property with its type.
  const fs::path dir = scratch_dir();
  for (const char* name : {"a.ply", "a.ply.gz"}) {
    EXPECT_TRUE(write_mesh((dir / name).string(), mesh).empty());
    EXPECT_EQ(difference(mesh, read_mesh((dir / name).string())), "") << name;
  }
  const std::string bytes = slurp(dir / "a.ply");
  EXPECT_NE(bytes.find("property uchar red\nproperty short temperature\nelement face 2\n"
                       "property list uchar uint vertex_indices\nproperty int texnumber\n"
                       "property list uchar float texcoord\nend_header\n"),
            std::string::npos)
      << bytes.substr(0, 400);
}

TEST(PlyAttributes, FloatPositionsAreWrittenBackAsFloat) {
  PolygonMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0.5, 0}, {0, 1, 0.25}};
  mesh.add_face(std::vector<VertexId>{0, 1, 2});
  mesh.attributes.position_type = ScalarType::float32;
  const fs::path dir = scratch_dir();
  const std::string path = (dir / "f.ply").string();
  write_mesh(path, mesh);
  const std::string bytes = slurp(path);
  EXPECT_NE(bytes.find("property float x\nproperty float y\nproperty float z\n"),
            std::string::npos);
  const PolygonMesh back = read_mesh(path);
  EXPECT_EQ(back.positions, mesh.positions);
  EXPECT_EQ(back.attributes.position_type, ScalarType::float32);
}

TEST(PlyAttributes, ErrorsAreLocated) {
  const std::string vertices = "0 0 0 1 1 0\n1 0 0 1 1 0\n1 1 0 1 1 0\n0 1 0 1 1 0\n";
  EXPECT_ERROR(kPlyHeader + vertices + "4 0 1 2 3 2 4 0 0 1 0\n", MeshFormat::ply,
               "face 0: texcoord list of 4 values for 4 corners (expected 2 per corner, or none)");
  const std::string rest =
      vertices.substr(vertices.find('\n') + 1) + "3 0 1 2 2 0\n" + "3 0 1 2 2 0\n0 1\n";
  EXPECT_ERROR(kPlyHeader + "0 0 0 256 1 0\n" + rest, MeshFormat::ply,
               "in:18: vertex 0: value 256 out of range for the type of property red");
  EXPECT_ERROR(kPlyHeader + "0 0 0 1 40000 0\n" + rest, MeshFormat::ply,
               "in:18: vertex 0: value 40000 out of range");
}

// ---------------------------------------------------------------------------------------------
// Conversions: what a format cannot hold is dropped and said.

TEST(AttributeConversions, EachFormatSaysWhatItDrops) {
  const fs::path dir = scratch_dir();
  const PolygonMesh obj = parse_mesh(kObj, MeshFormat::obj, "in");
  EXPECT_EQ(joined(write_mesh((dir / "o.ply").string(), obj)),
            "corner normals (vn): PLY has no place for them\n"
            "face materials (usemtl): PLY has no place for them\n"
            "face groups (g): PLY has no place for them\n"
            "face objects (o): PLY has no place for them\n"
            "smoothing groups (s): PLY has no place for them\n"
            "material libraries (mtllib): PLY has no place for them\n"
            "texture coordinates of 3 corners of faces with a corner without one: PLY's per-face "
            "texcoord list has no place for them\n"
            "third texture coordinates (w): PLY's texcoord list holds u v\n");
  // The colours survive into PLY; the square's texture coordinates too.
  const PolygonMesh from_ply = read_mesh((dir / "o.ply").string());
  EXPECT_EQ(columns_text(from_ply.attributes.vertex_properties),
            columns_text(obj.attributes.vertex_properties));
  EXPECT_EQ(from_ply.attributes.texcoords[from_ply.attributes.corner_texcoord[6]][1], 1);
  EXPECT_EQ(from_ply.attributes.corner_texcoord[0], kNoAttribute);

  EXPECT_EQ(joined(write_mesh((dir / "o.off").string(), obj)),
            "texture coordinates (vt): OFF has no place for them\n"
            "corner normals (vn): OFF has no place for them\n"
            "face materials (usemtl): OFF has no place for them\n"
            "face groups (g): OFF has no place for them\n"
            "face objects (o): OFF has no place for them\n"
            "smoothing groups (s): OFF has no place for them\n"
            "material libraries (mtllib): OFF has no place for them\n");
  EXPECT_EQ(slurp(dir / "o.off").substr(0, 29), "COFF\n4 3 0\n0 0 0 1.0 0.0 0.0\n");
  EXPECT_EQ(columns_text(read_mesh((dir / "o.off").string()).attributes.vertex_properties),
            columns_text(obj.attributes.vertex_properties));

  // PLY into OBJ and OFF: byte colours become OBJ's 0-1 reals; other properties are dropped.
  const std::string ply_text = kPlyHeader +
                               "0 0 0 255 -7 1 0\n1 0 0 0 300 0\n1 1 0 51 0 0\n0 1 0 1 1 0\n"
                               "4 0 1 2 3 2 8 0 0 1 0 1 1 0 1\n3 0 2 3 5 0\n0 1\n";
  PolygonMesh ply = parse_mesh(ply_text, MeshFormat::ply, "in");
  for (const char* name : {"green", "blue"}) {
    ply.attributes.vertex_properties.push_back({name, ScalarType::uint8, {0, 0, 0, 0}});
  }
  EXPECT_EQ(joined(write_mesh((dir / "p.obj").string(), ply)),
            "vertex property 'temperature': OBJ has no place for it\n"
            "face property 'texnumber': OBJ has no place for it\n");
  EXPECT_NE(slurp(dir / "p.obj").find("v 1 1 0 0.2 0 0\n"), std::string::npos);
  EXPECT_NE(slurp(dir / "p.obj").find("vt 0 1\nf 1/1 2/2 3/3 4/4\nf 1 3 4\n"), std::string::npos)
      << slurp(dir / "p.obj");
  EXPECT_EQ(joined(write_mesh((dir / "p.off").string(), ply)),
            "texture coordinates (vt): OFF has no place for them\n"
            "vertex property 'temperature': OFF has no place for it\n"
            "face property 'texnumber': OFF has no place for it\n");
  EXPECT_EQ(slurp(dir / "p.off").substr(0, 27), "COFF\n4 2 0\n0 0 0 255 0 0\n1 ");
}

TEST(AttributeConversions, OffIntoObjAndPly) {
  const fs::path dir = scratch_dir();
  const PolygonMesh off = parse_mesh(
      "CNOFF\n3 1 0\n0 0 0 0 0 1 255 0 0 7\n1 0 0 0 0 1 0 255 0 7\n0 1 0 0 0 1 0 0 255 7\n"
      "3 0 1 2 1 2 3\n",
      MeshFormat::off, "in");
  // The vertex normals become a vn per vertex, each corner naming its vertex's.
  EXPECT_EQ(joined(write_mesh((dir / "c.obj").string(), off)),
            "vertex property 'alpha': OBJ has no place for it\n"
            "face property 'red': OBJ has no place for it\n"
            "face property 'green': OBJ has no place for it\n"
            "face property 'blue': OBJ has no place for it\n");
  EXPECT_NE(slurp(dir / "c.obj").find("v 1 0 0 0 1 0\n"), std::string::npos);
  EXPECT_NE(slurp(dir / "c.obj").find("vn 0 0 1\nvn 0 0 1\nvn 0 0 1\nf 1//1 2//2 3//3\n"),
            std::string::npos)
      << slurp(dir / "c.obj");
  // PLY holds every OFF property with its type.
  EXPECT_TRUE(write_mesh((dir / "c.ply").string(), off).empty());
  EXPECT_EQ(difference(off, read_mesh((dir / "c.ply").string())), "");
}

// A scan's per-vertex normals and texture coordinates (PLY nx ny nz and u v) survive into OBJ:
// read back, every corner has its vertex's values, and nothing is reported dropped.
TEST(AttributeConversions, PlyVertexNormalsAndTexcoordsIntoObj) {
  const fs::path dir = scratch_dir();
  const std::string text =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nproperty float nx\nproperty float ny\nproperty float nz\n"
      "property float u\nproperty float v\nelement face 2\n"
      "property list uchar int vertex_indices\nend_header\n"
      "0 0 0 0 0 1 0 0\n1 0 0 0 0.6 0.8 1 0\n1 1 0 0 -0.6 0.8 1 1\n0 1 0 1 0 0 0 0.5\n"
      "3 0 1 2\n3 0 2 3\n";
  const PolygonMesh ply = parse_mesh(text, MeshFormat::ply, "in");
  EXPECT_TRUE(write_mesh((dir / "n.obj").string(), ply).empty());
  const PolygonMesh obj = read_mesh((dir / "n.obj").string());
  const MeshAttributes& a = obj.attributes;
  ASSERT_EQ(a.corner_normal.size(), ply.corners.size());
  ASSERT_EQ(a.corner_texcoord.size(), ply.corners.size());
  auto column = [&](const char* name) {
    for (const PropertyColumn& c : ply.attributes.vertex_properties)
      if (c.name == name) return &c;
    return static_cast<const PropertyColumn*>(nullptr);
  };
  for (std::size_t k = 0; k < ply.corners.size(); ++k) {
    const VertexId v = ply.corners[k];
    const std::array<double, 3>& n = a.normals[a.corner_normal[k]];
    const std::array<double, 3>& t = a.texcoords[a.corner_texcoord[k]];
    EXPECT_FLOAT_EQ(n[0], column("nx")->values[v]) << "corner " << k;
    EXPECT_FLOAT_EQ(n[1], column("ny")->values[v]) << "corner " << k;
    EXPECT_FLOAT_EQ(n[2], column("nz")->values[v]) << "corner " << k;
    EXPECT_FLOAT_EQ(t[0], column("u")->values[v]) << "corner " << k;
    EXPECT_FLOAT_EQ(t[1], column("v")->values[v]) << "corner " << k;
  }
  // With corner normals of its own the mesh keeps those, and the vertex columns are dropped.
  PolygonMesh both = obj;
  both.attributes.vertex_properties = ply.attributes.vertex_properties;
  const std::string dropped = joined(write_mesh((dir / "b.obj").string(), both));
  EXPECT_NE(dropped.find("vertex property 'nx'"), std::string::npos) << dropped;
  EXPECT_NE(dropped.find("vertex property 'u'"), std::string::npos) << dropped;
}

// The other way: OBJ normals that are per vertex (every corner of a vertex has the same) become
// PLY's and OFF's nx ny nz; per-vertex texture coordinates become OFF's s t. A flat-shaded mesh
// (a vertex with two normals) keeps its normals only in OBJ, and says so.
TEST(AttributeConversions, ObjVertexNormalsIntoPlyAndOff) {
  const fs::path dir = scratch_dir();
  const std::string smooth =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
      "vn 0 0 1\nvn 0 0.6 0.8\nvn 0.6 0 0.8\nvn 0 0 1\n"
      "f 1/1/1 2/2/2 3/3/3\nf 1/1/4 3/3/3 4/4/2\n";
  const PolygonMesh obj = parse_mesh(smooth, MeshFormat::obj, "in");
  // Vertex 0's corners name normals 1 and 4, equal in value; vertex 3's normal is normal 2.
  const std::vector<std::array<double, 3>> expected = {
      {0, 0, 1}, {0, 0.6, 0.8}, {0.6, 0, 0.8}, {0, 0.6, 0.8}};
  for (const char* name : {"s.ply", "s.off"}) {
    const std::vector<std::string> dropped = write_mesh((dir / name).string(), obj);
    EXPECT_TRUE(dropped.empty()) << name << ": " << joined(dropped);
    const PolygonMesh back = read_mesh((dir / name).string());
    const MeshAttributes& a = back.attributes;
    ASSERT_GE(a.vertex_properties.size(), 3u) << name;
    for (std::size_t v = 0; v < 4; ++v) {
      for (std::size_t j = 0; j < 3; ++j) {
        EXPECT_FLOAT_EQ(a.vertex_properties[j].values[v], expected[v][j]) << name << " " << v;
      }
    }
  }
  EXPECT_EQ(
      columns_text(read_mesh((dir / "s.off").string()).attributes.vertex_properties).substr(0, 3),
      "nx:");
  EXPECT_NE(slurp(dir / "s.off").find("STNOFF"), std::string::npos) << slurp(dir / "s.off");

  const std::string flat =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nvn 0 0 -1\n"
      "f 1//1 2//1 3//1\nf 1//2 3//2 4//2\n";
  const PolygonMesh flat_obj = parse_mesh(flat, MeshFormat::obj, "in");
  EXPECT_EQ(joined(write_mesh((dir / "f.ply").string(), flat_obj)),
            "corner normals (vn): PLY has no place for them\n");
  EXPECT_TRUE(read_mesh((dir / "f.ply").string()).attributes.vertex_properties.empty());
}

TEST(AttributeConversions, NamesAFormatCannotSpellAreRefused) {
  const fs::path dir = scratch_dir();
  PolygonMesh mesh = parse_mesh("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", MeshFormat::obj, "in");
  mesh.attributes.material_names = {"a#b"};
  mesh.attributes.face_material = {0};
  EXPECT_THROW(write_mesh((dir / "m.obj").string(), mesh), FileError);
  mesh.attributes.material_names = {};
  mesh.attributes.face_material = {};
  mesh.attributes.face_properties.push_back({"two words", ScalarType::uint8, {1}});
  EXPECT_THROW(write_mesh((dir / "m.ply").string(), mesh), FileError);
  mesh.attributes.face_properties[0] = {"big", ScalarType::uint8, {256}};
  EXPECT_THROW(write_mesh((dir / "m.ply").string(), mesh), FileError);
  EXPECT_FALSE(fs::exists(dir / "m.ply"));
  // A binary PLY holds a NaN colour; the text formats cannot.
  mesh.attributes.face_properties.clear();
  for (const char* name : {"red", "green", "blue"}) {
    mesh.attributes.vertex_properties.push_back({name, ScalarType::float32, {0.5, NAN, 1}});
  }
  EXPECT_TRUE(write_mesh((dir / "nan.ply").string(), mesh).empty());
  EXPECT_TRUE(
      std::isnan(read_mesh((dir / "nan.ply").string()).attributes.vertex_properties[1].values[1]));
  EXPECT_THROW(write_mesh((dir / "nan.off").string(), mesh), FileError);
  EXPECT_THROW(write_mesh((dir / "nan.obj").string(), mesh), FileError);
  // The refusal names the file it would have written.
  const std::string path = (dir / "nan.obj").string();
  try {
    write_mesh(path, mesh);
  } catch (const FileError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.line(), 0u);
    EXPECT_EQ(std::string(e.what()),
              path +
                  ": property 'red' has a value that is not finite (nan); a text format "
                  "cannot hold it");
  }
}

// ---------------------------------------------------------------------------------------------
// check_attributes

TEST(CheckAttributes, SizesAndIndices) {
  PolygonMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.add_face(std::vector<VertexId>{0, 1, 2});
  EXPECT_NO_THROW(check_attributes(mesh));
  auto error = [](const PolygonMesh& m) {
    try {
      check_attributes(m);
    } catch (const MeshError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  PolygonMesh m = mesh;
  m.attributes.corner_texcoord = {0, 0};
  EXPECT_EQ(error(m), "attribute corner_texcoord has 2 entries; the mesh has 3 corners");
  m.attributes.corner_texcoord = {0, kNoAttribute, 0};
  EXPECT_EQ(error(m), "attribute corner_texcoord[0] = 0 is out of range (0 values)");
  m.attributes.texcoords = {{0, 0, 0}};
  EXPECT_EQ(error(m), "no error");
  m = mesh;
  m.attributes.face_group = {1};
  m.attributes.group_names = {"g"};
  EXPECT_EQ(error(m), "attribute face_group[0] = 1 is out of range (1 values)");
  m = mesh;
  m.attributes.face_smoothing = {0, 0};
  EXPECT_EQ(error(m), "attribute face_smoothing has 2 entries; the mesh has 1 faces");
  m = mesh;
  m.attributes.vertex_properties.push_back({"red", ScalarType::uint8, {}});
  EXPECT_EQ(error(m), "attribute vertex property red has 0 entries; the mesh has 3 vertices");
  m = mesh;
  m.attributes.face_properties.push_back({"q", ScalarType::float32, {1, 2}});
  EXPECT_EQ(error(m), "attribute face property q has 2 entries; the mesh has 1 faces");
  // The writers check first and write nothing.
  const fs::path dir = scratch_dir();
  EXPECT_THROW(write_mesh((dir / "bad.obj").string(), m), MeshError);
  EXPECT_FALSE(fs::exists(dir / "bad.obj"));
}

// ---------------------------------------------------------------------------------------------
// Random meshes with random attributes: what a format holds comes back the same.

void round_trip(AttributeSet set, const char* extension) {
  const PolygonMesh mesh = *meshes_with_attributes(set);
  check_attributes(mesh);
  const fs::path path =
      fs::temp_directory_path() / ("petersen-attr-rc-" + std::to_string(::getpid()) + extension);
  const std::vector<std::string> dropped = write_mesh(path.string(), mesh);
  RC_ASSERT(joined(dropped) == "");
  std::vector<std::string> read_dropped;
  const PolygonMesh back = read_mesh(path.string(), &read_dropped);
  RC_ASSERT(joined(read_dropped) == "");
  RC_ASSERT(difference(mesh, back) == "");
  // And once more from what was read: the file is a fixed point.
  RC_ASSERT(write_mesh(path.string(), back).empty());
  RC_ASSERT(difference(back, read_mesh(path.string())) == "");
  if (set == AttributeSet::ply)
    RC_ASSERT(back.attributes.position_type == mesh.attributes.position_type);
  fs::remove(path);
}

RC_GTEST_PROP(AttributeRoundTrip, Obj, ()) {
  round_trip(AttributeSet::obj, ".obj");
}
RC_GTEST_PROP(AttributeRoundTrip, Off, ()) {
  round_trip(AttributeSet::off, ".off");
}
RC_GTEST_PROP(AttributeRoundTrip, Ply, ()) {
  round_trip(AttributeSet::ply, ".ply");
}
RC_GTEST_PROP(AttributeRoundTrip, PlyGzip, ()) {
  round_trip(AttributeSet::ply, ".ply.gz");
}

// Every attribute at once, into each format: what comes back is what the format holds, and the
// writer names the rest; nothing it writes fails to read.
RC_GTEST_PROP(AttributeRoundTrip, ConversionsKeepWhatTheFormatHolds, ()) {
  const PolygonMesh mesh = *meshes_with_attributes(AttributeSet::all);
  for (const char* extension : {".obj", ".off", ".ply"}) {
    const fs::path path =
        fs::temp_directory_path() / ("petersen-attr-all-" + std::to_string(::getpid()) + extension);
    const std::vector<std::string> dropped = write_mesh(path.string(), mesh);
    const PolygonMesh back = read_mesh(path.string());
    check_attributes(back);
    RC_ASSERT(back.positions == mesh.positions);
    const MeshAttributes& a = mesh.attributes;
    const bool obj = std::string(extension) == ".obj";
    // Materials live in OBJ alone, and a PLY property has no place in OBJ.
    const bool obj_only = !a.face_material.empty() || !a.face_group.empty() ||
                          !a.face_object.empty() || !a.face_smoothing.empty() ||
                          !a.material_libraries.empty();
    const bool properties = !a.vertex_properties.empty() || !a.face_properties.empty();
    if (obj) RC_ASSERT(dropped.empty() == !properties);
    if (!obj && obj_only) RC_ASSERT(!dropped.empty());
    // Corner normals reach PLY and OFF as vertex normals, after the vertex's own columns, when
    // every corner of each vertex has the same; else they are said to be dropped.
    const std::vector<PropertyColumn>& back_columns = back.attributes.vertex_properties;
    const bool has_nx = std::any_of(back_columns.begin(), back_columns.end(),
                                    [](const PropertyColumn& c) { return c.name == "nx"; });
    if (!obj && !a.normals.empty()) {
      const bool said = std::any_of(dropped.begin(), dropped.end(), [](const std::string& line) {
        return line.rfind("corner normals", 0) == 0;
      });
      RC_ASSERT(said != has_nx);
      static constexpr const char* kNames[3] = {"nx", "ny", "nz"};
      for (std::size_t k = 0; has_nx && k < mesh.corners.size(); ++k) {
        const std::array<double, 3>& n = a.normals[a.corner_normal[k]];
        for (std::size_t j = 0; j < 3; ++j) {
          const PropertyColumn* column = nullptr;
          for (const PropertyColumn& c : back_columns)
            if (c.name == kNames[j]) column = &c;
          RC_ASSERT(column != nullptr);
          RC_ASSERT(float(column->values[mesh.corners[k]]) == float(n[j]));
        }
      }
    }
    if (std::string(extension) == ".ply") {
      const std::vector<PropertyColumn> own(
          back_columns.begin(),
          back_columns.begin() + static_cast<std::ptrdiff_t>(a.vertex_properties.size()));
      RC_ASSERT(columns_text(own) == columns_text(a.vertex_properties));
    }
    fs::remove(path);
  }
}

}  // namespace
}  // namespace petersen
