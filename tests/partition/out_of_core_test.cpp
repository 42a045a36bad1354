// The out-of-core conversion on small meshes with tiny memory limits, so that they are cut into
// many parts; the output read back by the ordinary reader and checked on its own: every face a
// quad or a left triangle, every input triangle used exactly once, each quad's two triangles
// sharing its diagonal.

#include "petersen/partition/out_of_core.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "petersen/generators/polygon_generators.hpp"
#include "petersen/generators/streamed_plate.hpp"
#include "petersen/io/file_error.hpp"
#include "petersen/io/ply_stream.hpp"
#include "petersen/io/read_mesh.hpp"
#include "petersen/quadrangulate/quadrangulate.hpp"
#include "quad_mesh_check.hpp"

namespace petersen {
namespace {

namespace fs = std::filesystem;

struct TempDir {
  fs::path path;
  TempDir() {
    path = fs::temp_directory_path() /
           ("petersen-ooc-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
  std::string operator/(const std::string& name) const { return (path / name).string(); }
};

void write_triangles(const std::string& path, std::uint64_t vertices,
                     const std::vector<VertexId>& corners) {
  PlyStreamWriter out(path,
                      "element vertex " + std::to_string(vertices) +
                          "\nproperty float x\nproperty float y\nproperty float z\n",
                      corners.size() / 3);
  for (std::uint64_t v = 0; v < vertices; ++v) {
    const float xyz[3] = {float(v), float(v % 7), 0.5f};
    out.write_vertex_records({reinterpret_cast<const char*>(xyz), sizeof xyz});
  }
  for (std::size_t i = 0; i < corners.size(); i += 3) {
    out.write_triangle(corners[i], corners[i + 1], corners[i + 2]);
  }
  out.commit();
}

// Checks the output against the input on its own (pairing_problem); returns its quads.
std::uint64_t checked_quads(const std::vector<VertexId>& input, const PolygonMesh& output,
                            std::uint64_t vertices) {
  EXPECT_EQ(output.positions.size(), vertices);
  PolygonMesh source;
  source.corners.assign(input.begin(), input.end());
  std::uint64_t quads = 0;
  EXPECT_EQ(testing::pairing_problem(source, output, quads), "");
  return quads;
}

// The plate's triangles, written to `path` as binary PLY.
std::vector<VertexId> write_plate(const StreamedPlate& plate, const std::string& path) {
  std::vector<VertexId> corners;
  for_each_plate_triangle(plate, [&](VertexId a, VertexId b, VertexId c) {
    corners.insert(corners.end(), {a, b, c});
  });
  write_triangles(path, plate.vertices(), corners);
  return corners;
}

TEST(OutOfCore, ClosedPlateInManyPartsIsPerfect) {
  const TempDir dir;
  const StreamedPlate plate = streamed_plate_of_size(60000);
  const std::vector<VertexId> corners = write_plate(plate, dir / "plate.ply");
  for (std::uint64_t limit : {std::uint64_t{200} << 10, std::uint64_t{1} << 20}) {
    const OutOfCoreStats stats =
        quad_out_of_core(dir / "plate.ply", dir / "quads.ply", {.memory_limit = limit});
    EXPECT_GE(stats.parts, 10u) << "limit " << limit;
    EXPECT_TRUE(stats.closed);
    EXPECT_TRUE(stats.perfect_certified);
    EXPECT_EQ(stats.triangles_left, 0u);
    const PolygonMesh out = read_mesh(dir / "quads.ply");
    EXPECT_EQ(checked_quads(corners, out, plate.vertices()), plate.triangles() / 2);
    EXPECT_EQ(stats.pairs, plate.triangles() / 2);
  }
  // Nothing left beside the output.
  std::uint64_t files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir.path)) ++files;
  EXPECT_EQ(files, 2u);
}

// Whatever the part size, a closed mesh comes out perfect: a window with an odd number of free
// triangles leaves one, which must be moved across the part to its far border to be carried
// forward (PartPairingOptions::move_budget).
TEST(OutOfCore, ClosedPlateIsPerfectForEveryPartSize) {
  const TempDir dir;
  const StreamedPlate plate = streamed_plate_of_size(100000);
  const std::vector<VertexId> corners = write_plate(plate, dir / "plate.ply");
  for (std::uint64_t part : {997u, 2048u, 3001u, 6250u, 7919u, 12345u, 20011u, 33333u, 49999u}) {
    const OutOfCoreStats stats =
        quad_out_of_core(dir / "plate.ply", dir / "quads.ply", {.part_triangles = part});
    EXPECT_TRUE(stats.perfect_certified) << "parts of " << part;
    EXPECT_EQ(stats.triangles_left, 0u) << "parts of " << part;
  }
  const PolygonMesh out = read_mesh(dir / "quads.ply");
  EXPECT_EQ(checked_quads(corners, out, plate.vertices()), plate.triangles() / 2);
}

TEST(OutOfCore, OpenMeshMatchesTheInMemoryMaximum) {
  const TempDir dir;
  const PolygonMesh mesh = punch_holes(open_grid(60, 50), 20, 3);
  const std::vector<VertexId> corners(mesh.corners.begin(), mesh.corners.end());
  write_triangles(dir / "open.ply", mesh.positions.size(), corners);
  const OutOfCoreStats stats =
      quad_out_of_core(dir / "open.ply", dir / "quads.ply", {.part_triangles = 500});
  EXPECT_GE(stats.parts, 8u);
  EXPECT_FALSE(stats.closed);
  EXPECT_FALSE(stats.perfect_certified);
  const PolygonMesh out = read_mesh(dir / "quads.ply");
  const std::uint64_t quads = checked_quads(corners, out, mesh.positions.size());
  EXPECT_EQ(quads, stats.pairs);
  QuadOptions options;
  options.objective = Objective::pairs;  // the maximum, which the parts are compared with
  options.sources = false;
  EXPECT_EQ(stats.pairs, quadrangulate(mesh, options).stats.pairs);
}

TEST(OutOfCore, RefusesWhatItCannotStreamNamingTheFileAndFace) {
  const TempDir dir;
  {
    std::ofstream ascii(dir / "ascii.ply");
    ascii << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
             "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
             "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  }
  EXPECT_THROW(quad_out_of_core(dir / "ascii.ply", dir / "out.ply"), FileError);
  write_triangles(dir / "range.ply", 3, {0, 1, 7});
  try {
    quad_out_of_core(dir / "range.ply", dir / "out.ply");
    FAIL() << "no error";
  } catch (const FileError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("range.ply"), std::string::npos) << what;
    EXPECT_NE(what.find("face 0"), std::string::npos) << what;
  }
  EXPECT_FALSE(fs::exists(dir / "out.ply"));
}

}  // namespace
}  // namespace petersen
