// Every text reader shares one line splitter: a UTF-8 byte-order mark is skipped and lines end
// in "\n", "\r\n" or a lone "\r" (old Mac files), alike in the mesh formats (OFF, OBJ, an ASCII
// PLY header) and the graph formats (read_graph_test.cpp has those); an empty file is refused
// in every format.

#include <gtest/gtest.h>

#include <string>

#include "petersen/io/file_error.hpp"
#include "petersen/io/read_mesh.hpp"

namespace petersen {
namespace {

// `body` with '|' as the line end `end`, after a byte-order mark when `bom`.
std::string text(const std::string& body, const char* end, bool bom) {
  std::string out = bom ? "\xEF\xBB\xBF" : "";
  for (char c : body) out += c == '|' ? std::string(end) : std::string(1, c);
  return out;
}

TEST(LineEnds, MeshFormatsReadTheSameTriangleWhateverTheLineEndsAndMark) {
  const std::pair<MeshFormat, std::string> files[] = {
      {MeshFormat::off, "OFF|3 1 0|0 0 0|1 0 0|0 1 0|3 0 1 2|"},
      {MeshFormat::obj, "# a triangle|v 0 0 0|v 1 0 0|v 0 1 0|f 1 2 3|"},
      {MeshFormat::ply,
       "ply|format ascii 1.0|element vertex 3|property float x|property float y|property float "
       "z|element face 1|property list uchar int vertex_indices|end_header|0 0 0|1 0 0|0 1 0|3 0 "
       "1 2|"},
  };
  for (const auto& [format, body] : files) {
    for (const char* end : {"\n", "\r\n", "\r"}) {
      for (bool bom : {false, true}) {
        const std::string bytes = text(body, end, bom);
        SCOPED_TRACE(bytes);
        const PolygonMesh mesh = parse_mesh(bytes, format, "in");
        EXPECT_EQ(mesh.positions.size(), 3u);
        EXPECT_EQ(mesh.face_count(), 1u);
      }
    }
  }
}

TEST(LineEnds, EmptyMeshFilesAreRefusedInEveryFormat) {
  for (MeshFormat format : {MeshFormat::off, MeshFormat::obj, MeshFormat::ply}) {
    for (const char* empty : {"", "\xEF\xBB\xBF", "\r"}) {
      EXPECT_THROW(parse_mesh(empty, format, "in"), FileError);
    }
  }
}

}  // namespace
}  // namespace petersen
