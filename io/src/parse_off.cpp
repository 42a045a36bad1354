// OFF: an optional "OFF" keyword, the counts "V F E", V vertex lines and F face lines
// "n i1 ... in" (n >= 3); '#' starts a comment. The keyword's prefixes say what a vertex line
// carries after x y z (Geomview's order): N normals "nx ny nz", C a colour "r g b [a]", ST texture
// coordinates "s t"; they become vertex properties of those names. A face line may end with a
// colour "r g b [a]" (face properties red, green, blue[, alpha]). A colour of whole numbers from 0
// to 255 is kept as uint8, any other as float32. Values nothing declares (a colour-map index, a
// vertex colour under a plain OFF keyword) are read past and reported as dropped.

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

// Vertex or face colours: created at the first element that has one (earlier elements get 0),
// with 3 or 4 components fixed by that element.
struct Colours {
  std::vector<PropertyColumn>* columns;
  std::size_t components = 0;
  bool bytes = true;             // every value so far a whole number from 0 to 255
  std::uint64_t uncoloured = 0;  // elements with no colour once or before there were colours

  static constexpr const char* kNames[4] = {"red", "green", "blue", "alpha"};

  // Adds the colour of element `before` (elements already read) from its tokens; false when the
  // number of values differs from the colours before.
  bool add(const std::string_view* tokens, std::size_t count, std::size_t before) {
    if (components == 0) {
      components = count;
      for (std::size_t k = 0; k < count; ++k) {
        columns->push_back({kNames[k], ScalarType::uint8, {}});
        columns->back().values.assign(before, 0.0);
      }
    }
    if (count != components) return false;
    for (std::size_t k = 0; k < count; ++k) {
      double value = 0;
      std::int64_t whole = 0;
      if (!text::parse_real(tokens[k], value)) return false;
      bytes = bytes && text::parse_integer(tokens[k], whole) && whole >= 0 && whole <= 255;
      (*columns)[columns->size() - components + k].values.push_back(value);
    }
    return true;
  }
  void add_none() {
    ++uncoloured;
    for (std::size_t k = 0; k < components; ++k) {
      (*columns)[columns->size() - components + k].values.push_back(0.0);
    }
  }
  // Sets the columns' type once every value is known.
  void finish(const char* elements, std::vector<std::string>& dropped) const {
    if (components == 0) return;
    for (std::size_t k = 0; k < components; ++k) {
      (*columns)[columns->size() - components + k].type =
          bytes ? ScalarType::uint8 : ScalarType::float32;
    }
    if (uncoloured > 0) {
      dropped.push_back(std::to_string(uncoloured) + " " + elements +
                        " without a colour in a file with colours: given 0 0 0");
    }
  }
};

}  // namespace

PolygonMesh parse_off(std::string_view bytes, const std::string& source, FaceKinds kinds,
                      std::vector<std::string>& dropped) {
  text::Lines lines{bytes};
  const text::Located at{source, lines};
  text::Tokens tokens;
  if (!next_content(lines, tokens)) at.fail("empty file");

  // The keyword may be followed by the counts on the same line, or the keyword may be absent.
  std::string_view token;
  text::Tokens probe = tokens;
  probe.next(token);
  bool has_normals = false, has_colours = false, has_st = false;
  if (token.size() >= 3 && token.substr(token.size() - 3) == "OFF") {
    const std::string_view prefix = token.substr(0, token.size() - 3);
    if (prefix.find_first_of("4n") != std::string_view::npos) {
      at.fail("only 3-dimensional OFF is supported, not " + text::Located::quote(token));
    }
    has_normals = prefix.find('N') != std::string_view::npos;
    has_colours = prefix.find('C') != std::string_view::npos;
    has_st = prefix.find("ST") != std::string_view::npos;
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
  std::vector<PropertyColumn>& vertex_properties = mesh.attributes.vertex_properties;
  if (has_normals) {
    for (const char* name : {"nx", "ny", "nz"})
      vertex_properties.push_back({name, ScalarType::float32, {}});
  }
  if (has_st) {
    for (const char* name : {"s", "t"})
      vertex_properties.push_back({name, ScalarType::float32, {}});
  }
  Colours vertex_colours{&vertex_properties}, face_colours{&mesh.attributes.face_properties};
  DroppedTally tally;
  // The values after what a line must hold (x y z, or a face's indices): at most 9 are kept (a
  // normal, a colour, s t); a tenth only says there are too many.
  std::string_view extra[10];
  auto read_extra = [&](text::Tokens& rest) {
    std::size_t count = 0;
    while (count < std::size(extra) && rest.next(extra[count])) ++count;
    return count;
  };
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
    std::size_t count = read_extra(tokens);
    if (count == 0 && !has_normals && !has_colours && !has_st) continue;
    // Geomview's order: normal, colour, texture coordinates.
    const std::size_t declared = (has_normals ? 3 : 0) + (has_st ? 2 : 0);
    if (count < declared + (has_colours ? 3 : 0) || (has_st && count == std::size(extra))) {
      at.fail("vertex " + std::to_string(v) + ": expected " +
              (has_normals ? "a normal (nx ny nz) " : "") + (has_colours ? "a colour " : "") +
              (has_st ? "texture coordinates (s t) " : "") + "after x y z, as the keyword says");
    }
    std::size_t column = 0;
    auto take = [&](std::size_t k) {
      double value = 0;
      if (!text::parse_real(extra[k], value)) {
        at.fail("vertex " + std::to_string(v) + ": bad value " + text::Located::quote(extra[k]));
      }
      vertex_properties[column++].values.push_back(value);
    };
    if (has_normals) {
      for (std::size_t k = 0; k < 3; ++k) take(k);
    }
    if (has_st) {
      for (std::size_t k = count - 2; k < count; ++k) take(k);
      count -= 2;
    }
    const std::size_t colour_first = has_normals ? 3 : 0, colour_count = count - colour_first;
    if (!has_colours) {
      if (colour_count > 0)
        tally.add("vertex lines with values the keyword does not declare", lines.line);
    } else if ((colour_count != 3 && colour_count != 4) ||
               !vertex_colours.add(extra + colour_first, colour_count, v)) {
      at.fail("vertex " + std::to_string(v) + ": bad colour (expected 3 or 4 numbers, as many as " +
              "the vertices before)");
    }
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
    const std::size_t count = read_extra(tokens);
    if (count == 3 || count == 4) {
      if (!face_colours.add(extra, count, f)) {
        at.fail("face " + std::to_string(f) + ": bad colour (expected 3 or 4 numbers, as many as " +
                "the faces before)");
      }
    } else {
      if (count > 0)
        tally.add(
            "face lines with values after the indices that are not a colour (a colour-map index)",
            lines.line);
      face_colours.add_none();
    }
    mesh.add_face(face);
  }
  tally.report(dropped);
  vertex_colours.finish("vertices", dropped);
  face_colours.finish("faces", dropped);
  return mesh;
}

}  // namespace petersen
