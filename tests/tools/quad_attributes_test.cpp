// `petersen quad` end to end on what a mesh carries: an OBJ with texture
// coordinates, normals, several materials and groups, and a PLY with vertex colours, converted
// by the tool; its output read back and checked against the input, face by face.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "petersen/io/read_mesh.hpp"
#include "petersen/io/write_mesh.hpp"

namespace petersen {
namespace {

namespace fs = std::filesystem;

class QuadAttributes : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("petersen-quad-attributes-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  // Runs `petersen quad IN OUT OPTIONS`; its exit code.
  int quad(const std::string& in, const std::string& out, const std::string& options = "") {
    const std::string command = std::string(PETERSEN_BINARY) + " quad " + path(in) + " " +
                                path(out) + " " + options + " >" + path("stdout") + " 2>" +
                                path("stderr");
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

  fs::path dir_;
};

using Value = std::optional<std::array<double, 3>>;

Value value(const std::pmr::vector<std::uint32_t>& index,
            const std::pmr::vector<std::array<double, 3>>& values, std::size_t corner) {
  if (index.empty() || index[corner] == kNoAttribute) return std::nullopt;
  return values[index[corner]];
}

std::optional<std::string> name(const std::pmr::vector<std::uint32_t>& index,
                                const std::vector<std::string>& names, FaceId f) {
  if (index.empty() || index[f] == kNoAttribute) return std::nullopt;
  return names[index[f]];
}

// A face's corner at vertex v, or none.
std::optional<std::size_t> corner_at(const PolygonMesh& mesh, FaceId f, VertexId v) {
  const std::size_t first = mesh.all_triangles() ? 3 * std::size_t{f} : mesh.face_start[f];
  for (std::size_t c = first; c < first + mesh.arity(f); ++c)
    if (mesh.corners[c] == v) return c;
  return std::nullopt;
}

// A grid of 4 x 2 squares, each cut into two triangles, on 15 vertices: a UV seam down the
// middle (the right half's texture coordinates are another chart), material red on the bottom
// row and blue on the top, group "body" on the first three columns and "lid" on the last, one
// normal written twice (equal values under two indices: no seam).
std::string grid_obj() {
  std::string text = "mtllib grid.mtl\n";
  for (int y = 0; y <= 2; ++y)
    for (int x = 0; x <= 4; ++x)
      text += "v " + std::to_string(x) + " " + std::to_string(y) + " 0\n";
  // Chart 1: vertices with x <= 2 (indices 1..15 by vertex); chart 2: x >= 2, shifted in u.
  for (int y = 0; y <= 2; ++y)
    for (int x = 0; x <= 4; ++x)
      text += "vt " + std::to_string(x * 0.25) + " " + std::to_string(y * 0.5) + "\n";
  for (int y = 0; y <= 2; ++y)
    for (int x = 0; x <= 4; ++x)
      text += "vt " + std::to_string(x * 0.25 + 0.125) + " " + std::to_string(y * 0.5) + "\n";
  text += "vn 0 0 1\nvn 0 0 1\n";
  auto corner = [](int x, int y, int column) {
    const int v = y * 5 + x + 1;
    const int vt = v + (column >= 2 ? 15 : 0);
    const int vn = (x + y) % 2 + 1;
    // Appends, not a chain of operator+: GCC 12 gives a false -Wrestrict on those.
    std::string piece = " ";
    piece += std::to_string(v);
    piece += "/";
    piece += std::to_string(vt);
    piece += "/";
    piece += std::to_string(vn);
    return piece;
  };
  for (int y = 0; y < 2; ++y) {
    text += std::string("usemtl ") + (y == 0 ? "red" : "blue") + "\n";
    for (int x = 0; x < 4; ++x) {
      if (x == 0) text += "g body\n";
      if (x == 3) text += "g lid\n";
      text += "f";
      text += corner(x, y, x) + corner(x + 1, y, x) + corner(x + 1, y + 1, x) + "\n";
      text += "f";
      text += corner(x, y, x) + corner(x + 1, y + 1, x) + corner(x, y + 1, x) + "\n";
    }
  }
  return text;
}

TEST_F(QuadAttributes, ObjKeepsCornersMaterialsAndGroups) {
  std::ofstream(path("in.obj")) << grid_obj();
  ASSERT_EQ(quad("in.obj", "out.obj", "--stats-json " + path("stats.json")), 0);
  // The grid's cuts by construction: the seam's 2 edges, the material border's 4, the group
  // border's 2; the two normals are equal, so no normal seam.
  std::ifstream json(path("stats.json"));
  const std::string stats((std::istreambuf_iterator<char>(json)), std::istreambuf_iterator<char>());
  for (const char* count : {"\"uv_seam\": 2,", "\"material\": 4,", "\"group\": 2,",
                            "\"normal_seam\": 0,", "\"boundary\": 12,"}) {
    EXPECT_NE(stats.find(count), std::string::npos) << count << " not in " << stats;
  }
  const PolygonMesh in = read_mesh(path("in.obj"));
  const PolygonMesh out = read_mesh(path("out.obj"));
  const MeshAttributes &a = in.attributes, &b = out.attributes;
  ASSERT_EQ(in.face_count(), 16u);
  ASSERT_FALSE(a.corner_texcoord.empty());  // the reader keeps what the test is about
  ASSERT_FALSE(b.corner_texcoord.empty());
  ASSERT_FALSE(b.corner_normal.empty());
  EXPECT_EQ(b.material_libraries, a.material_libraries);
  // Every square is a quad of the maximum pairing, whatever the algorithm picks.
  ASSERT_EQ(out.face_count(), 8u);
  using Points = std::vector<std::array<double, 3>>;
  ASSERT_EQ(Points(out.positions.begin(), out.positions.end()),
            Points(in.positions.begin(), in.positions.end()));
  std::map<std::pair<VertexId, VertexId>, int> faces_on_edge;
  for (FaceId f = 0; f < in.face_count(); ++f) {
    const auto c = in.face(f);
    for (int k = 0; k < 3; ++k) {
      ++faces_on_edge[{std::min(c[k], c[(k + 1) % 3]), std::max(c[k], c[(k + 1) % 3])}];
    }
  }
  for (FaceId o = 0; o < out.face_count(); ++o) {
    SCOPED_TRACE("output face " + std::to_string(o));
    const auto quad = out.face(o);
    ASSERT_EQ(quad.size(), 4u);
    // Its triangles: the input faces on three of its four vertices.
    std::vector<FaceId> triangles;
    for (FaceId f = 0; f < in.face_count(); ++f) {
      const auto c = in.face(f);
      if (std::all_of(c.begin(), c.end(), [&](VertexId v) {
            return std::find(quad.begin(), quad.end(), v) != quad.end();
          })) {
        triangles.push_back(f);
      }
    }
    ASSERT_EQ(triangles.size(), 2u);
    const FaceId t1 = triangles[0], t2 = triangles[1];
    // The removed edge: the vertices both triangles have. Not a border, not a seam, not a
    // material or group border.
    std::vector<VertexId> shared;
    for (VertexId v : in.face(t1))
      if (corner_at(in, t2, v)) shared.push_back(v);
    ASSERT_EQ(shared.size(), 2u);
    EXPECT_EQ((faces_on_edge[{std::min(shared[0], shared[1]), std::max(shared[0], shared[1])}]), 2);
    for (VertexId v : shared) {
      EXPECT_EQ(value(a.corner_texcoord, a.texcoords, *corner_at(in, t1, v)),
                value(a.corner_texcoord, a.texcoords, *corner_at(in, t2, v)));
      EXPECT_EQ(value(a.corner_normal, a.normals, *corner_at(in, t1, v)),
                value(a.corner_normal, a.normals, *corner_at(in, t2, v)));
    }
    for (FaceId t : {t1, t2}) {
      EXPECT_EQ(name(b.face_material, b.material_names, o),
                name(a.face_material, a.material_names, t));
      EXPECT_EQ(name(b.face_group, b.group_names, o), name(a.face_group, a.group_names, t));
    }
    // Each corner's v/vt/vn: those of the same vertex's corner in its triangle.
    const std::size_t first = out.face_start.empty() ? 4 * std::size_t{o} : out.face_start[o];
    for (std::size_t k = 0; k < 4; ++k) {
      const VertexId v = quad[k];
      const std::size_t c = *(corner_at(in, t1, v) ? corner_at(in, t1, v) : corner_at(in, t2, v));
      EXPECT_EQ(value(b.corner_texcoord, b.texcoords, first + k),
                value(a.corner_texcoord, a.texcoords, c));
      EXPECT_EQ(value(b.corner_normal, b.normals, first + k), value(a.corner_normal, a.normals, c));
    }
  }
}

TEST_F(QuadAttributes, PlyKeepsVertexColours) {
  std::ofstream(path("in.ply")) << "ply\nformat ascii 1.0\nelement vertex 4\n"
                                   "property float x\nproperty float y\nproperty float z\n"
                                   "property uchar red\nproperty uchar green\nproperty uchar blue\n"
                                   "element face 2\nproperty list uchar int vertex_indices\n"
                                   "end_header\n"
                                   "0 0 0 255 0 0\n1 0 0 0 255 0\n1 1 0 0 0 255\n0 1 0 17 34 51\n"
                                   "3 0 1 2\n3 0 2 3\n";
  ASSERT_EQ(quad("in.ply", "out.ply"), 0);
  const PolygonMesh in = read_mesh(path("in.ply"));
  const PolygonMesh out = read_mesh(path("out.ply"));
  ASSERT_EQ(out.face_count(), 1u);
  EXPECT_EQ(out.arity(0), 4u);
  ASSERT_EQ(in.attributes.vertex_properties.size(), 3u);
  ASSERT_EQ(out.attributes.vertex_properties.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    const PropertyColumn &x = in.attributes.vertex_properties[k],
                         &y = out.attributes.vertex_properties[k];
    EXPECT_EQ(y.name, x.name);
    EXPECT_EQ(y.type, ScalarType::uint8);
    EXPECT_EQ(std::vector<double>(y.values.begin(), y.values.end()),
              std::vector<double>(x.values.begin(), x.values.end()));
  }
}

// A binary PLY of float coordinates comes back as float (half the bytes of double), through the
// pairing and through all_quad's splits.
TEST_F(QuadAttributes, FloatPlyStaysFloat) {
  PolygonMesh in;
  in.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}};
  for (std::array<VertexId, 3> t : {std::array<VertexId, 3>{0, 1, 2}, {0, 2, 3}, {1, 4, 2}}) {
    in.add_face(t);
  }
  in.attributes.position_type = ScalarType::float32;
  write_mesh(path("in.ply"), in);
  ASSERT_EQ(read_mesh(path("in.ply")).attributes.position_type, ScalarType::float32);
  for (const std::string options : {"", "--all-quad"}) {
    ASSERT_EQ(quad("in.ply", "out.ply", options), 0) << options;
    const PolygonMesh out = read_mesh(path("out.ply"));
    EXPECT_EQ(out.attributes.position_type, ScalarType::float32) << options;
    ASSERT_EQ(out.face_count(), 2u) << options;  // a pair's quad and the third triangle
    const bool one_triangle = out.arity(0) == 3 || out.arity(1) == 3;
    // all_quad splits the third triangle at its boundary.
    EXPECT_EQ(one_triangle, options.empty()) << options;
  }
}

}  // namespace
}  // namespace petersen
