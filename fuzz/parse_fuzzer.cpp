// libFuzzer target for one mesh reader (PETERSEN_FUZZ_FORMAT: obj, off or ply). Bad bytes must
// give a FileError; any other exception, a crash, a sanitizer report, a hang or a huge
// allocation is a finding. What parses must be a well-formed polygon mesh with consistent
// attributes, faces of three or more corners in range.

#include <cstdint>
#include <string_view>

#include "petersen/io/read_mesh.hpp"
#include "require.hpp"

namespace {

using namespace petersen;

constexpr MeshFormat kFormat = MeshFormat::PETERSEN_FUZZ_FORMAT;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  bool parsed = false;
  PolygonMesh mesh;
  try {
    mesh = parse_mesh(bytes, kFormat, "fuzz");
    parsed = true;
  } catch (const FileError&) {
  }
  if (parsed) {
    REQUIRE(mesh.face_count() > 0);
    // What the reader keeps beside the faces is consistent with them (a MeshError here is a
    // reader's bug, not bad input).
    try {
      check_attributes(mesh);
    } catch (const MeshError& e) {
      fuzz::broken(e.what(), __FILE__, __LINE__);
    }
    REQUIRE(mesh.all_triangles()
                ? mesh.corners.size() % 3 == 0
                : mesh.face_start.front() == 0 && mesh.face_start.back() == mesh.corners.size());
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
      const auto face = mesh.face(static_cast<FaceId>(f));
      REQUIRE(face.size() >= 3);
      for (VertexId v : face) REQUIRE(v < mesh.positions.size());
    }
  }
  return 0;
}
