// OBJ: only "v x y z" and "f a b c ..." lines matter. A corner is written v, v/vt, v//vn or
// v/vt/vn; a negative v counts back from the last vertex read so far (-1 is the latest), per the
// OBJ spec. Faces have any number of corners from 3 on.

#include <vector>

#include "parsers.hpp"
#include "text_scan.hpp"

namespace petersen {

PolygonMesh parse_obj(std::string_view bytes, const std::string& source, FaceKinds kinds) {
  text::Lines lines{bytes};
  const text::Located at{source, lines};
  PolygonMesh mesh;
  // Reserving by a guess from the size keeps the large files from re-growing many times: a "v"
  // line is about 30 bytes and there are about two triangles (6 corners) per vertex.
  mesh.positions.reserve(bytes.size() / 90);
  mesh.corners.reserve(bytes.size() / 15);
  // The corners of the face being read: reused, so a face line allocates nothing. Messages are
  // built only on error.
  std::vector<VertexId> face;
  std::string_view line, token;
  bool any_content = false;
  auto face_name = [&] { return "face " + std::to_string(mesh.face_count()); };
  while (lines.next(line)) {
    text::Tokens tokens{text::strip_comment(line)};
    if (!tokens.next(token)) continue;
    any_content = true;
    if (token == "v") {
      std::array<double, 3> p;
      for (double& x : p) {
        if (!tokens.next(token)) {
          at.fail("vertex " + std::to_string(mesh.positions.size()) + ": expected 3 coordinates");
        }
        if (!text::parse_real(token, x)) {
          at.fail("vertex " + std::to_string(mesh.positions.size()) + ": bad coordinate " +
                  text::Located::quote(token));
        }
      }
      if (mesh.positions.size() == 0xFFFFFFFFu) at.fail("more than 2^32 - 1 vertices");
      mesh.positions.push_back(p);
    } else if (token == "f") {
      face.clear();
      const std::int64_t count = static_cast<std::int64_t>(mesh.positions.size());
      while (tokens.next(token)) {
        // Only the vertex index, before the first '/', matters.
        const std::string_view index_text = token.substr(0, token.find('/'));
        std::int64_t index = 0;
        if (!text::parse_integer(index_text, index) || index == 0) {
          at.fail(face_name() + ": bad vertex index " + text::Located::quote(token));
        }
        const std::int64_t zero_based = index > 0 ? index - 1 : count + index;
        if (zero_based < 0 || zero_based >= count) {
          at.fail(face_name() + ": vertex index " + std::to_string(index) + " out of range (" +
                  std::to_string(count) + " vertices read so far)");
        }
        face.push_back(static_cast<VertexId>(zero_based));
      }
      if (!corner_count_ok(face.size(), kinds)) {
        at.fail(corner_count_error(mesh.face_count(), face.size()));
      }
      if (!corners_fit(mesh, face.size())) at.fail("more than 2^32 - 1 face corners");
      mesh.add_face(face);
    }
  }
  if (!any_content) throw MeshError(source + ": empty file");
  return mesh;
}

}  // namespace petersen
