// OFF: an optional "OFF" keyword (COFF, NOFF, ... too), the counts "V F E", V vertex lines and F
// face lines "n i1 ... in" (n >= 3); '#' starts a comment; extra values on a line (colours) are
// ignored.

#include <vector>

#include "parsers.hpp"
#include "text_scan.hpp"

namespace petersen {

namespace {

// Reads the next line with content, without its comment, or false at the end of the text.
bool next_content(text::Lines& lines, text::Tokens& tokens) {
  std::string_view line;
  while (lines.next(line)) {
    tokens.rest = text::strip_comment(line);
    text::Tokens probe = tokens;
    std::string_view token;
    if (probe.next(token)) return true;
  }
  return false;
}

}  // namespace

PolygonMesh parse_off(std::string_view bytes, const std::string& source, FaceKinds kinds) {
  text::Lines lines{bytes};
  const text::Located at{source, lines};
  text::Tokens tokens;
  if (!next_content(lines, tokens)) at.fail("empty file");

  // The keyword may be followed by the counts on the same line, or the keyword may be absent.
  std::string_view token;
  text::Tokens probe = tokens;
  probe.next(token);
  if (token.size() >= 3 && token.substr(token.size() - 3) == "OFF") {
    if (token.find_first_of("4n") != std::string_view::npos) {
      at.fail("only 3-dimensional OFF is supported, not " + text::Located::quote(token));
    }
    tokens = probe;
    if (!probe.next(token) && !next_content(lines, tokens)) at.fail("truncated: no counts");
  } else if (std::int64_t unused; !text::parse_integer(token, unused)) {
    at.fail("not an OFF file: starts with " + text::Located::quote(token));
  }

  std::int64_t counts[2];
  for (std::int64_t& count : counts) {
    if (!tokens.next(token)) at.fail("expected the vertex and face counts");
    if (!text::parse_integer(token, count) || count < 0 || count > 0xFFFFFFFFll) {
      at.fail("bad count " + text::Located::quote(token));
    }
  }
  const std::uint64_t vertex_count = counts[0], face_count = counts[1];
  // A vertex line takes at least 6 bytes ("0 0 0\n"), a face line 8 ("3 0 1 2\n").
  if (vertex_count * 6 + face_count * 8 > lines.remaining() + 2) {
    at.fail("header declares " + std::to_string(vertex_count) + " vertices and " +
            std::to_string(face_count) + " faces, more than the remaining " +
            std::to_string(lines.remaining()) + " bytes can hold");
  }

  PolygonMesh mesh;
  mesh.positions.reserve(text::safe_reserve(vertex_count, lines.remaining(), 6));
  for (std::uint64_t v = 0; v < vertex_count; ++v) {
    if (!next_content(lines, tokens)) {
      at.fail("truncated: expected " + std::to_string(vertex_count) + " vertices, found " +
              std::to_string(v));
    }
    std::array<double, 3> p;
    for (double& x : p) {
      if (!tokens.next(token)) at.fail("vertex " + std::to_string(v) + ": expected 3 coordinates");
      if (!text::parse_real(token, x)) {
        at.fail("vertex " + std::to_string(v) + ": bad coordinate " + text::Located::quote(token));
      }
    }
    mesh.positions.push_back(p);
  }
  // Triangles are the common case: 3 corners per face, bounded by what the bytes can hold.
  mesh.corners.reserve(3 * text::safe_reserve(face_count, lines.remaining(), 8));
  std::vector<VertexId> face;  // reused: a face line allocates nothing
  for (std::uint64_t f = 0; f < face_count; ++f) {
    if (!next_content(lines, tokens)) {
      at.fail("truncated: expected " + std::to_string(face_count) + " faces, found " +
              std::to_string(f));
    }
    std::int64_t corners = 0;
    tokens.next(token);
    if (!text::parse_integer(token, corners) || corners < 0) {
      at.fail("face " + std::to_string(f) + ": bad corner count " + text::Located::quote(token));
    }
    if (!corner_count_ok(static_cast<std::uint64_t>(corners), kinds)) {
      at.fail(corner_count_error(f, static_cast<std::uint64_t>(corners)));
    }
    face.clear();
    for (std::int64_t k = 0; k < corners; ++k) {
      std::int64_t index = 0;
      if (!tokens.next(token)) {
        at.fail("face " + std::to_string(f) + ": expected " + std::to_string(corners) +
                " vertex indices");
      }
      if (!text::parse_integer(token, index)) {
        at.fail("face " + std::to_string(f) + ": bad vertex index " + text::Located::quote(token));
      }
      if (index < 0 || static_cast<std::uint64_t>(index) >= vertex_count) {
        at.fail("face " + std::to_string(f) + ": vertex index " + std::to_string(index) +
                " out of range (" + std::to_string(vertex_count) + " vertices)");
      }
      face.push_back(static_cast<VertexId>(index));
    }
    if (!corners_fit(mesh, face.size())) at.fail("more than 2^32 - 1 face corners");
    mesh.add_face(face);
  }
  return mesh;
}

}  // namespace petersen
