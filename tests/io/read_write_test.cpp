// The readers and writers through files: round trips in every format, gzip, atomic writes.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "petersen/generators/surface_generators.hpp"
#include "petersen/io/read_mesh.hpp"
#include "petersen/io/write_mesh.hpp"

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
  PolygonMesh mesh = random_closed_surface(2, 30, 30, 7);
  mesh.positions[0] = {0.1, -1e-300, 12345.678901234567};  // needs every digit to survive
  for (const char* name : {"m.off", "m.obj", "m.ply", "m.off.gz", "m.OBJ.gz", "m.ply.gz"}) {
    const std::string path = (dir / name).string();
    write_mesh(path, mesh);
    const PolygonMesh back = read_mesh(path);
    EXPECT_EQ(back.positions, mesh.positions) << name;
    EXPECT_EQ(back.corners, mesh.corners) << name;
    EXPECT_TRUE(back.all_triangles()) << name;
  }
  EXPECT_EQ(slurp(dir / "m.off.gz").substr(0, 2), "\x1f\x8b");  // really compressed
}

// A binary PLY over 64 MB is written past the page cache (O_DIRECT) but for its last partial
// block, and read back through a mapping of the file: both must give the same bytes as the
// buffered paths, whatever the size's remainder by the block.
TEST(ReadWrite, LargeBinaryPlyRoundTripsThroughDirectWritesAndMapping) {
  const fs::path dir = scratch_dir();
  PolygonMesh mesh;
  constexpr std::uint32_t kVertices = 3'000'001;  // 72 MB of positions, an odd file size
  mesh.positions.resize(kVertices);
  for (std::uint32_t v = 0; v < kVertices; ++v) {
    mesh.positions[v] = {v * 0.5, -1.0 / (v + 1), v % 977 * 1e-7};
  }
  for (std::uint32_t t = 0; t + 2 < kVertices; t += 3) {
    for (VertexId v : {t, t + 1, t + 2}) mesh.corners.push_back(v);
  }
  const std::string path = (dir / "large.ply").string();
  write_mesh(path, mesh);
  EXPECT_GT(fs::file_size(path), std::uintmax_t{64} << 20);
  EXPECT_NE(fs::file_size(path) % 4096, 0u);
  const PolygonMesh back = read_mesh(path);
  EXPECT_EQ(back.positions, mesh.positions);
  EXPECT_EQ(back.corners, mesh.corners);
  fs::remove_all(dir);
}

TEST(ReadWrite, QuadFilesHaveTheirFacesInEachFormat) {
  const fs::path dir = scratch_dir();
  PolygonMesh quads;
  quads.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  quads.add_face(std::array<VertexId, 4>{0, 1, 2, 3});
  quads.add_face(std::array<VertexId, 4>{3, 2, 1, 0});
  write_mesh((dir / "q.off").string(), quads);
  write_mesh((dir / "q.obj").string(), quads);
  write_mesh((dir / "q.ply").string(), quads);
  EXPECT_EQ(slurp(dir / "q.off"), "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n4 3 2 1 0\n");
  EXPECT_EQ(slurp(dir / "q.obj"), "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\nf 4 3 2 1\n");
  const std::string ply = slurp(dir / "q.ply");
  const std::string header_end = "end_header\n";
  const std::size_t data = ply.find(header_end) + header_end.size();
  EXPECT_NE(ply.find("format binary_little_endian 1.0"), std::string::npos);
  EXPECT_EQ(ply.size() - data, 4 * 24 + 2 * (1 + 16));
  EXPECT_EQ(ply[data + 4 * 24], 4);  // the first face's corner count
}

TEST(ReadWrite, FormatFollowsTheExtension) {
  EXPECT_EQ(mesh_format_of("a/b.Off"), MeshFormat::off);
  EXPECT_EQ(mesh_format_of("b.obj.gz"), MeshFormat::obj);
  EXPECT_EQ(mesh_format_of("c.PLY"), MeshFormat::ply);
  EXPECT_THROW(mesh_format_of("d.stl"), FileError);
  EXPECT_THROW(mesh_format_of("e.gz"), FileError);
  EXPECT_THROW(read_mesh("/nonexistent/f.off"), FileError);
}

TEST(ReadWrite, UnwritablePathIsAnError) {
  EXPECT_THROW(write_mesh("/nonexistent/q.off", PolygonMesh{}), FileError);
}

void spit(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

void expect_same(const PolygonMesh& a, const PolygonMesh& b, const std::string& what) {
  EXPECT_EQ(a.positions, b.positions) << what;
  EXPECT_EQ(a.corners, b.corners) << what;
  EXPECT_EQ(a.face_start, b.face_start) << what;
}

// A closed surface with some triangle pairs merged into quads, a face with a repeated corner and
// one face of 300 corners (past what a PLY uchar count can say).
PolygonMesh polygon_mesh() {
  const PolygonMesh triangles = random_closed_surface(1, 20, 40, 3);
  PolygonMesh mesh;
  mesh.positions = triangles.positions;
  for (FaceId t = 0; t < triangles.face_count(); ++t) {
    const auto tri = triangles.face(t);
    if (t % 5 == 1) {
      const std::vector<VertexId> square{tri[0], tri[1], tri[2], tri[1]};
      mesh.add_face(square);
    } else {
      mesh.add_face(tri);
    }
  }
  std::vector<VertexId> big;
  for (VertexId v = 0; v < 300; ++v) big.push_back(v % mesh.positions.size());
  mesh.add_face(big);
  mesh.positions[0] = {0.1, -1e-300, 12345.678901234567};  // needs every digit to survive
  return mesh;
}

TEST(ReadWrite, PolygonRoundTripThroughEveryFormatAndGzip) {
  const fs::path dir = scratch_dir();
  const PolygonMesh mesh = polygon_mesh();
  ASSERT_FALSE(mesh.all_triangles());
  for (const char* name : {"p.off", "p.obj", "p.ply", "p.off.gz", "p.obj.gz", "p.PLY.GZ"}) {
    const std::string path = (dir / name).string();
    write_mesh(path, mesh);
    expect_same(read_mesh(path), mesh, name);
  }
  // All-triangle meshes keep implicit face starts through write_mesh and read_mesh.
  const PolygonMesh triangles = random_closed_surface(2, 30, 30, 7);
  for (const char* name : {"t.off", "t.obj", "t.ply.gz"}) {
    write_mesh((dir / name).string(), triangles);
    const PolygonMesh back = read_mesh((dir / name).string());
    EXPECT_TRUE(back.all_triangles()) << name;
    expect_same(back, triangles, name);
  }
}

// No file in the folder but the ones listed: a failed write leaves no temporary file behind.
std::vector<std::string> files_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(ReadWrite, WritingOverTheInputReplacesItWhole) {
  const fs::path dir = scratch_dir();
  const std::string path = (dir / "m.obj").string();
  const PolygonMesh mesh = polygon_mesh();
  write_mesh(path, random_closed_surface(0, 3, 3, 1));
  fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  write_mesh(path, read_mesh(path));  // the same file in and out
  write_mesh(path, mesh);
  expect_same(read_mesh(path), mesh, path);
  EXPECT_EQ(fs::status(path).permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  EXPECT_EQ(files_in(dir), std::vector<std::string>{"m.obj"});
}

TEST(ReadWrite, FailedWritesLeaveTheOldFileAndNoTemporary) {
  const fs::path dir = scratch_dir();
  const PolygonMesh mesh = polygon_mesh();
  const std::string old_bytes = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  spit(dir / "m.off", old_bytes);
  // The rename fails: the target is a folder.
  fs::create_directory(dir / "d.off");
  EXPECT_THROW(write_mesh((dir / "d.off").string(), mesh), FileError);
  // The write fails half-way: a child process limited to 1000-byte files writes a larger mesh
  // over m.off (SIGXFSZ ignored, so write() reports EFBIG).
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{1000, 1000};
    setrlimit(RLIMIT_FSIZE, &limit);
    int code = 1;
    try {
      write_mesh((dir / "m.off").string(), mesh);
    } catch (const FileError& e) {
      code = std::string(e.what()).find("m.off: write failed") != std::string::npos ? 0 : 2;
    }
    _exit(code);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "1: no error raised, 2: the error did not name the file";
  EXPECT_EQ(slurp(dir / "m.off"), old_bytes);
  EXPECT_EQ(files_in(dir), (std::vector<std::string>{"d.off", "m.off"}));
}

TEST(ReadWrite, AKilledWriteLeavesTheOldFileAndNothingElse) {
  const fs::path dir = scratch_dir();
  const std::string path = (dir / "m.obj").string();
  write_mesh(path, polygon_mesh());
  const std::string old_bytes = slurp(path);
  int ready[2];
  ASSERT_EQ(pipe(ready), 0);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    // A mesh whose OBJ takes tens of milliseconds to write, killed while it is written.
    const PolygonMesh large = random_closed_surface(3, 100000, 0, 5);
    const char byte = 1;
    if (write(ready[1], &byte, 1) != 1) _exit(3);
    for (;;) write_mesh(path, large);
  }
  char byte = 0;
  ASSERT_EQ(read(ready[0], &byte, 1), 1);
  usleep(20000);
  kill(child, SIGKILL);
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  close(ready[0]);
  close(ready[1]);
  // Either the old file or a whole new one, and no temporary file (where O_TMPFILE works).
  const std::string bytes = slurp(path);
  if (bytes != old_bytes) {
    EXPECT_GT(read_mesh(path).face_count(), 200000u);
  }
  EXPECT_EQ(files_in(dir), std::vector<std::string>{"m.obj"});
}

TEST(ReadWrite, GzipMembersPaddingAndDamage) {
  const fs::path dir = scratch_dir();
  // Two members (two OBJ files compressed apart, one after the other) and zero padding read as
  // one OBJ file, as gzip -dc would give it.
  const PolygonMesh first = polygon_mesh(), second = random_closed_surface(0, 0, 0, 1);
  write_mesh((dir / "a.obj.gz").string(), first);
  write_mesh((dir / "b.obj.gz").string(), second);
  const std::string a = slurp(dir / "a.obj.gz"), b = slurp(dir / "b.obj.gz");
  spit(dir / "two.obj.gz", a + b + std::string(16, '\0'));
  const PolygonMesh both = read_mesh((dir / "two.obj.gz").string());
  EXPECT_EQ(both.positions.size(), first.positions.size() + second.positions.size());
  EXPECT_EQ(both.face_count(), first.face_count() + second.face_count());
  // A gzip file is recognised by its bytes whatever its name, a plain one too.
  spit(dir / "zipped.obj", b);
  expect_same(read_mesh((dir / "zipped.obj").string()), second, "zipped.obj");
  write_mesh((dir / "plain.obj").string(), second);
  fs::rename(dir / "plain.obj", dir / "plain.obj.gz");
  expect_same(read_mesh((dir / "plain.obj.gz").string()), second, "plain.obj.gz");
  auto error = [&](const std::string& bytes) {
    spit(dir / "bad.obj.gz", bytes);
    try {
      read_mesh((dir / "bad.obj.gz").string());
    } catch (const FileError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string path = (dir / "bad.obj.gz").string();
  EXPECT_EQ(error(a + "junk"),
            path + ": 4 bytes after the gzip data, from byte " + std::to_string(a.size()));
  std::string corrupt = a + b;
  corrupt[a.size() + 12] ^= 0x55;
  EXPECT_EQ(error(corrupt), path + ": corrupt gzip data in the member starting at byte " +
                                std::to_string(a.size()));
  EXPECT_EQ(error(a.substr(0, a.size() - 3)),
            path + ": corrupt gzip data in the member starting at byte 0");
}

}  // namespace
}  // namespace petersen
