#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "petersen/dualize/read_mesh.hpp"
#include "petersen/dualize/surface_generators.hpp"
#include "petersen/dualize/write_mesh.hpp"

namespace petersen {
namespace {

namespace fs = std::filesystem;

// A fresh folder per test, so parallel ctest runs never share files.
fs::path scratch_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  fs::path dir = fs::temp_directory_path() /
                 ("petersen-io-" + std::to_string(::getpid()) + "-" + info->name());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(ReadWrite, TriangleRoundTripThroughEveryFormatAndGzip) {
  const fs::path dir = scratch_dir();
  TriangleMesh mesh = random_closed_surface(2, 30, 30, 7);
  mesh.positions[0] = {0.1, -1e-300, 12345.678901234567};  // needs every digit to survive
  for (const char* name : {"m.off", "m.obj", "m.ply", "m.off.gz", "m.OBJ.gz", "m.ply.gz"}) {
    const std::string path = (dir / name).string();
    write_triangle_mesh(path, mesh);
    const TriangleMesh back = read_triangle_mesh(path);
    EXPECT_EQ(back.positions, mesh.positions) << name;
    EXPECT_EQ(back.triangles, mesh.triangles) << name;
  }
  EXPECT_EQ(slurp(dir / "m.off.gz").substr(0, 2), "\x1f\x8b");  // really compressed
}

TEST(ReadWrite, QuadFilesHaveTheirFacesInEachFormat) {
  const fs::path dir = scratch_dir();
  const QuadMesh quads{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2, 3}, {3, 2, 1, 0}}};
  write_quad_mesh((dir / "q.off").string(), quads);
  write_quad_mesh((dir / "q.obj").string(), quads);
  write_quad_mesh((dir / "q.ply").string(), quads);
  EXPECT_EQ(slurp(dir / "q.off"), "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n4 3 2 1 0\n");
  EXPECT_EQ(slurp(dir / "q.obj"), "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\nf 4 3 2 1\n");
  const std::string ply = slurp(dir / "q.ply");
  const std::string header_end = "end_header\n";
  const std::size_t data = ply.find(header_end) + header_end.size();
  EXPECT_NE(ply.find("format binary_little_endian 1.0"), std::string::npos);
  EXPECT_EQ(ply.size() - data, 4 * 24 + 2 * (1 + 16));
  EXPECT_EQ(ply[data + 4 * 24], 4);  // the first face's corner count
  // The triangle reader refuses the quads and names the first face.
  try {
    read_triangle_mesh((dir / "q.obj").string());
    FAIL() << "quads read as triangles";
  } catch (const MeshError& e) {
    EXPECT_NE(std::string(e.what()).find(":5: face 0 has 4 corners"), std::string::npos)
        << e.what();
  }
}

TEST(ReadWrite, FormatFollowsTheExtension) {
  EXPECT_EQ(mesh_format_of("a/b.Off"), MeshFormat::off);
  EXPECT_EQ(mesh_format_of("b.obj.gz"), MeshFormat::obj);
  EXPECT_EQ(mesh_format_of("c.PLY"), MeshFormat::ply);
  EXPECT_THROW(mesh_format_of("d.stl"), MeshError);
  EXPECT_THROW(mesh_format_of("e.gz"), MeshError);
  EXPECT_THROW(read_triangle_mesh("/nonexistent/f.off"), MeshError);
}

TEST(ReadWrite, UnwritablePathIsAnError) {
  EXPECT_THROW(write_quad_mesh("/nonexistent/q.off", QuadMesh{}), MeshError);
}

}  // namespace
}  // namespace petersen
