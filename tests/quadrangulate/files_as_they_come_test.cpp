// Meshes as files hold them, through the front door: triangle strips pair as the same triangles
// written as faces, and a mesh whose every face is doubled is counted and, with its copies
// dropped, pairs as its single copy does.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "../io/tristrip_ply.hpp"
#include "petersen/io/read_mesh.hpp"
#include "petersen/io/write_mesh.hpp"
#include "petersen/mesh/duplicate_faces.hpp"
#include "petersen/quadrangulate/quadrangulate.hpp"
#include "petersen/testing/mesh_classes.hpp"
#include "result_check.hpp"

namespace petersen {
namespace {

using testing::PlyEncoding;

std::string temporary_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() /
          ("petersen-" + std::to_string(::getpid()) + "-" + name))
      .string();
}

// The pairing's answer: the output faces and what they came from.
void expect_same_result(const QuadResult& a, const QuadResult& b) {
  EXPECT_EQ(std::vector<VertexId>(a.mesh.corners.begin(), a.mesh.corners.end()),
            std::vector<VertexId>(b.mesh.corners.begin(), b.mesh.corners.end()));
  using Sources = std::vector<std::array<FaceId, 2>>;
  EXPECT_EQ(Sources(a.sources.begin(), a.sources.end()),
            Sources(b.sources.begin(), b.sources.end()));
  EXPECT_EQ(a.stats.pairs, b.stats.pairs);
  EXPECT_EQ(a.stats.added_vertices, b.stats.added_vertices);
}

const QuadOptions kModes[] = {
    {},
    {.all_quad = true},
    {.objective = Objective::quality},
    {.objective = Objective::quality, .all_quad = true},
};

TEST(FilesAsTheyCome, TristripPlyPairsAsTheSameMeshWrittenAsFaces) {
  const testing::StripGrid grid = testing::strip_grid(7, 6);
  const std::string faces_path = temporary_path("faces.ply");
  write_mesh(faces_path, grid.faces);
  const PolygonMesh faces = read_mesh(faces_path);
  std::filesystem::remove(faces_path);
  for (PlyEncoding encoding : {PlyEncoding::ascii, PlyEncoding::little, PlyEncoding::big}) {
    const std::string strips_path = temporary_path("strips.ply");
    std::ofstream(strips_path, std::ios::binary)
        << testing::tristrip_ply(grid.faces.positions, grid.records, encoding);
    const PolygonMesh strips = read_mesh(strips_path);
    std::filesystem::remove(strips_path);
    for (const QuadOptions& options : kModes) {
      SCOPED_TRACE(std::to_string(int(encoding)) + (options.all_quad ? " all-quad" : "") + " " +
                   std::string(to_string(options.objective)));
      const QuadResult from_strips = quadrangulate(strips, options);
      EXPECT_EQ(testing::check_quad_result(strips, from_strips, options), "");
      EXPECT_GT(from_strips.stats.pairs, 0u);
      expect_same_result(from_strips, quadrangulate(faces, options));
    }
  }
}

// Every face twice (the second copy reversed, as a file of two-sided faces holds it): every edge
// has four faces, nothing pairs, and the stats say why; dropped, the copies leave the single mesh.
TEST(FilesAsTheyCome, DoubledFacesAreCountedAndDropped) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const PolygonMesh single = testing::mesh_of_class(testing::MeshClass::closed, seed, 200);
    PolygonMesh doubled = single;
    for (FaceId f = 0; f < single.face_count(); ++f) {
      const auto c = single.face(f);
      const std::array<VertexId, 3> reversed{c[2], c[1], c[0]};
      doubled.add_face(reversed);
    }
    for (const QuadOptions& options : kModes) {
      const QuadResult as_is = quadrangulate(doubled, options);
      EXPECT_EQ(as_is.stats.duplicate_faces, single.face_count());
      EXPECT_EQ(as_is.stats.pairs, 0u);
      EXPECT_EQ(testing::check_quad_result(doubled, as_is, options), "");
      const DroppedFaces dropped = drop_duplicate_faces(doubled);
      EXPECT_EQ(dropped.dropped.size(), single.face_count());
      const QuadResult once = quadrangulate(dropped.mesh, options);
      EXPECT_EQ(once.stats.duplicate_faces, 0u);
      expect_same_result(once, quadrangulate(single, options));
      // A closed mesh: the maximum pairs every triangle (quads may leave some, at their price).
      if (options.objective != Objective::quads) EXPECT_EQ(once.stats.triangles_left, 0u);
    }
  }
}

}  // namespace
}  // namespace petersen
