#pragma once
// The per-format parsers behind parse_mesh; each throws located MeshErrors.

#include <cstdint>
#include <string>
#include <string_view>

#include "petersen/dualize/mesh.hpp"

namespace petersen {

/// Which faces a parser accepts: any polygon of three or more corners, or only triangles (for
/// parse_triangle_mesh, whose error then names the file's line or element like any other).
enum class FaceKinds { polygons, triangles };

PolygonMesh parse_off(std::string_view bytes, const std::string& source, FaceKinds kinds);
PolygonMesh parse_obj(std::string_view bytes, const std::string& source, FaceKinds kinds);
PolygonMesh parse_ply(std::string_view bytes, const std::string& source, FaceKinds kinds);

/// True when `kinds` accepts a face of `corners` corners.
inline bool corner_count_ok(std::uint64_t corners, FaceKinds kinds) {
  return corners >= 3 && (kinds == FaceKinds::polygons || corners == 3);
}

/// The complaint about face `face` whose corner count corner_count_ok refused, worded the same
/// by every parser.
inline std::string corner_count_error(std::uint64_t face, std::uint64_t corners) {
  std::string what =
      "face " + std::to_string(face) + " has " + std::to_string(corners) + " corners; ";
  what += corners < 3 ? "a face needs at least 3" : "only triangles are supported";
  return what;
}

/// The corners a mesh can hold: face_start holds 32-bit offsets.
inline bool corners_fit(const PolygonMesh& mesh, std::uint64_t more) {
  return mesh.corners.size() + more <= 0xFFFFFFFFu;
}

}  // namespace petersen
