// PLY tristrips: strips read into the triangles they stand for, in every encoding, byte order and
// index type, -1 restarting a strip, every other triangle turned back; the triangles repeating a
// vertex (a strip's turns and joins) left out and counted; bad indices named by strip and position.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "petersen/io/read_mesh.hpp"
#include "tristrip_ply.hpp"

namespace petersen {
namespace {

using testing::PlyEncoding;

std::vector<VertexId> corners_of(const PolygonMesh& mesh) {
  return {mesh.corners.begin(), mesh.corners.end()};
}

std::string error_of(const std::string& bytes) {
  try {
    parse_mesh(bytes, MeshFormat::ply, "in");
  } catch (const FileError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Tristrips, ReadAsTheTrianglesTheyStandFor) {
  const testing::StripGrid grid = testing::strip_grid(3, 6);
  ASSERT_GT(grid.joins, 0u);
  const std::pair<const char*, const char*> types[] = {{"int", "int"},
                                                       {"uchar", "uint"},
                                                       {"ushort", "short"},
                                                       {"uint", "ushort"},
                                                       {"char", "uchar"}};
  for (PlyEncoding encoding : {PlyEncoding::ascii, PlyEncoding::little, PlyEncoding::big}) {
    for (const auto& [count_type, index_type] : types) {
      SCOPED_TRACE(std::to_string(int(encoding)) + " " + count_type + " " + index_type);
      const std::string bytes = testing::tristrip_ply(grid.faces.positions, grid.records, encoding,
                                                      count_type, index_type);
      std::vector<std::string> dropped;
      const PolygonMesh mesh = parse_mesh(bytes, MeshFormat::ply, "in", &dropped);
      EXPECT_TRUE(mesh.all_triangles());
      EXPECT_EQ(corners_of(mesh), corners_of(grid.faces));
      ASSERT_EQ(mesh.positions.size(), grid.faces.positions.size());
      for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        for (int k = 0; k < 3; ++k) {
          EXPECT_EQ(mesh.positions[v][k], float(grid.faces.positions[v][k]));
        }
      }
      EXPECT_EQ(dropped,
                std::vector<std::string>{
                    std::to_string(grid.joins) +
                    " triangles of strips repeating a vertex (a strip's turns and joins)"});
    }
  }
}

TEST(Tristrips, OrientationAlternatesAndRestarts) {
  const Positions square = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 0, 0}};
  // 0 1 2 3 | 1 4 3: (0 1 2), (2 1 3), then a new strip (1 4 3).
  const PolygonMesh mesh =
      parse_mesh(testing::tristrip_ply(square, {{0, 1, 2, 3, -1, 1, 4, 3}}, PlyEncoding::ascii),
                 MeshFormat::ply, "in");
  EXPECT_EQ(corners_of(mesh), (std::vector<VertexId>{0, 1, 2, 2, 1, 3, 1, 4, 3}));
  // An unsigned index type may spell the restart -1 in ascii too.
  const std::string minus =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty "
      "float z\nelement tristrips 1\nproperty list uchar uint vertex_indices\nend_header\n0 0 0\n"
      "1 0 0\n0 1 0\n1 1 0\n7 0 1 2 -1 1 3 2\n";
  EXPECT_EQ(corners_of(parse_mesh(minus, MeshFormat::ply, "in")),
            (std::vector<VertexId>{0, 1, 2, 1, 3, 2}));
  // Strips of fewer than three vertices make no triangle; a trailing -1 ends nothing.
  EXPECT_EQ(error_of(testing::tristrip_ply(square, {{0, 1, -1, 2, -1}}, PlyEncoding::ascii)),
            "in: no faces");
}

TEST(Tristrips, ErrorsNameTheStripAndThePosition) {
  const Positions square = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  const std::vector<std::vector<std::int64_t>> past = {{0, 1, 2, -1, 1, 2, 9}};
  EXPECT_EQ(error_of(testing::tristrip_ply(square, past, PlyEncoding::ascii)),
            "in:14: tristrips 0, strip 1 (list position 6): vertex index 9 out of range (4 "
            "vertices)");
  const std::string binary = error_of(testing::tristrip_ply(square, past, PlyEncoding::big));
  EXPECT_EQ(binary.rfind("in: tristrips 0, strip 1 (list position 6): vertex index 9 out of range "
                         "(4 vertices) (byte ",
                         0),
            0u)
      << binary;
  EXPECT_EQ(error_of(testing::tristrip_ply(square, {{0, 1, 2}, {0, -2, 3}}, PlyEncoding::ascii)),
            "in:15: tristrips 1, strip 0 (list position 1): vertex index -2 out of range (4 "
            "vertices)");
  // Truncated: the list runs past the end.
  std::string cut = testing::tristrip_ply(square, {{0, 1, 2, 3}}, PlyEncoding::little);
  cut.resize(cut.size() - 2);
  EXPECT_NE(error_of(cut).find("truncated in tristrips 0 of 1"), std::string::npos);
  // Faces come from one element: a face element beside tristrips is refused where declared.
  std::string both = testing::tristrip_ply(square, {{0, 1, 2}}, PlyEncoding::ascii);
  both.insert(both.find("end_header"), "element face 0\nproperty list uchar int vertex_indices\n");
  EXPECT_EQ(error_of(both),
            "in:9: both a 'face' and a 'tristrips' element: the faces come from one");
  std::string unnamed = testing::tristrip_ply(square, {{0, 1, 2}}, PlyEncoding::ascii);
  unnamed.replace(unnamed.find("vertex_indices"), 14, "corners");
  EXPECT_EQ(error_of(unnamed), "in:7: tristrips element has no vertex_indices list");
}

}  // namespace
}  // namespace petersen
