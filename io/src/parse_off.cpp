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

// What the OFF keyword's prefixes declare a vertex line carries after x y z.
struct Declared {
  bool normals = false, colours = false, st = false;
  bool any() const { return normals || colours || st; }
};

class OffReader {
 public:
  OffReader(std::string_view bytes, std::pmr::memory_resource* memory)
      : lines_{bytes}, mesh_(memory) {}

  PolygonMesh read(const std::string& source, std::vector<std::string>& dropped) {
    const text::Located at{source, lines_};
    read_header(at);
    read_vertices(at);
    read_faces(at);
    tally_.report(dropped);
    vertex_colours_.finish("vertices", dropped);
    face_colours_.finish("faces", dropped);
    return std::move(mesh_);
  }

 private:
  // The keyword (which may be absent, or followed by the counts on its line) and the counts.
  void read_header(const text::Located& at) {
    text::Tokens tokens;
    if (!next_content(lines_, tokens)) at.fail("empty file");
    std::string_view token;
    text::Tokens probe = tokens;
    probe.next(token);
    if (token.size() >= 3 && token.substr(token.size() - 3) == "OFF") {
      const std::string_view prefix = token.substr(0, token.size() - 3);
      if (prefix.find_first_of("4n") != std::string_view::npos) {
        at.fail("only 3-dimensional OFF is supported, not " + text::Located::quote(token));
      }
      declared_.normals = prefix.find('N') != std::string_view::npos;
      declared_.colours = prefix.find('C') != std::string_view::npos;
      declared_.st = prefix.find("ST") != std::string_view::npos;
      tokens = probe;
      if (!probe.next(token) && !next_content(lines_, tokens)) at.fail("truncated: no counts");
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
    vertex_count_ = counts[0];
    face_count_ = counts[1];
    // A vertex line takes at least 6 bytes ("0 0 0\n"), a face line 8 ("3 0 1 2\n").
    if (vertex_count_ * 6 + face_count_ * 8 > lines_.remaining() + 2) {
      at.fail("header declares " + std::to_string(vertex_count_) + " vertices and " +
              std::to_string(face_count_) + " faces, more than the remaining " +
              std::to_string(lines_.remaining()) + " bytes can hold");
    }
  }

  void read_vertices(const text::Located& at) {
    std::vector<PropertyColumn>& properties = mesh_.attributes.vertex_properties;
    if (declared_.normals) {
      for (const char* name : {"nx", "ny", "nz"})
        properties.push_back({name, ScalarType::float32, {}});
    }
    if (declared_.st) {
      for (const char* name : {"s", "t"}) properties.push_back({name, ScalarType::float32, {}});
    }
    mesh_.positions.reserve(text::safe_reserve(vertex_count_, lines_.remaining(), 6));
    text::Tokens tokens;
    for (std::uint64_t v = 0; v < vertex_count_; ++v) {
      if (!next_content(lines_, tokens)) {
        at.fail("truncated: expected " + std::to_string(vertex_count_) + " vertices, found " +
                std::to_string(v));
      }
      std::array<double, 3> p;
      std::string_view token;
      for (double& x : p) {
        if (!tokens.next(token)) {
          at.fail("vertex " + std::to_string(v) + ": expected 3 coordinates");
        }
        if (!text::parse_real(token, x)) {
          at.fail("vertex " + std::to_string(v) + ": bad coordinate " +
                  text::Located::quote(token));
        }
      }
      mesh_.positions.push_back(p);
      const std::size_t count = read_extra(tokens);
      if (count > 0 || declared_.any()) read_vertex_extra(at, v, count);
    }
  }

  // The values after a vertex's x y z, in Geomview's order: normal, colour, texture coordinates.
  void read_vertex_extra(const text::Located& at, std::uint64_t v, std::size_t count) {
    const std::size_t declared = (declared_.normals ? 3 : 0) + (declared_.st ? 2 : 0);
    if (count < declared + (declared_.colours ? 3 : 0) ||
        (declared_.st && count == std::size(extra_))) {
      at.fail("vertex " + std::to_string(v) + ": expected " +
              (declared_.normals ? "a normal (nx ny nz) " : "") +
              (declared_.colours ? "a colour " : "") +
              (declared_.st ? "texture coordinates (s t) " : "") +
              "after x y z, as the keyword says");
    }
    std::vector<PropertyColumn>& properties = mesh_.attributes.vertex_properties;
    std::size_t column = 0;
    auto take = [&](std::size_t k) {
      double value = 0;
      if (!text::parse_real(extra_[k], value)) {
        at.fail("vertex " + std::to_string(v) + ": bad value " + text::Located::quote(extra_[k]));
      }
      properties[column++].values.push_back(value);
    };
    if (declared_.normals) {
      for (std::size_t k = 0; k < 3; ++k) take(k);
    }
    if (declared_.st) {
      for (std::size_t k = count - 2; k < count; ++k) take(k);
      count -= 2;
    }
    const std::size_t colour_first = declared_.normals ? 3 : 0, colour_count = count - colour_first;
    if (!declared_.colours) {
      if (colour_count > 0) {
        tally_.add("vertex lines with values the keyword does not declare", lines_.line);
      }
    } else if ((colour_count != 3 && colour_count != 4) ||
               !vertex_colours_.add(extra_ + colour_first, colour_count, v)) {
      at.fail("vertex " + std::to_string(v) + ": bad colour (expected 3 or 4 numbers, as many as " +
              "the vertices before)");
    }
  }

  void read_faces(const text::Located& at) {
    // Triangles are the common case: 3 corners per face, bounded by what the bytes can hold.
    mesh_.corners.reserve(3 * text::safe_reserve(face_count_, lines_.remaining(), 8));
    text::Tokens tokens;
    for (std::uint64_t f = 0; f < face_count_; ++f) {
      if (!next_content(lines_, tokens)) {
        at.fail("truncated: expected " + std::to_string(face_count_) + " faces, found " +
                std::to_string(f));
      }
      read_corners(at, f, tokens);
      const std::size_t count = read_extra(tokens);
      if (count == 3 || count == 4) {
        if (!face_colours_.add(extra_, count, f)) {
          at.fail("face " + std::to_string(f) +
                  ": bad colour (expected 3 or 4 numbers, as many as the faces before)");
        }
      } else {
        if (count > 0) {
          tally_.add(
              "face lines with values after the indices that are not a colour (a colour-map "
              "index)",
              lines_.line);
        }
        face_colours_.add_none();
      }
      mesh_.add_face(face_);
    }
  }

  // "n i1 ... in" into face_. Inlined into the face loop: a call per face costs about 1.5 % of
  // reading a large OFF.
  [[gnu::always_inline]] void read_corners(const text::Located& at, std::uint64_t f,
                                           text::Tokens& tokens) {
    std::int64_t corners = 0;
    std::string_view token;
    tokens.next(token);
    if (!text::parse_integer(token, corners) || corners < 0) {
      at.fail("face " + std::to_string(f) + ": bad corner count " + text::Located::quote(token));
    }
    if (!corner_count_ok(static_cast<std::uint64_t>(corners))) {
      at.fail(corner_count_error(f, static_cast<std::uint64_t>(corners)));
    }
    face_.clear();
    const std::uint64_t vertex_count = vertex_count_;  // in a register across the pushes
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
      face_.push_back(static_cast<VertexId>(index));
    }
    if (!corners_fit(mesh_, face_.size())) at.fail("more than 2^32 - 1 face corners");
  }

  // The rest of the line's tokens into extra_; how many (at most its size).
  std::size_t read_extra(text::Tokens& tokens) {
    std::size_t count = 0;
    while (count < std::size(extra_) && tokens.next(extra_[count])) ++count;
    return count;
  }

  text::Lines lines_;
  Declared declared_;
  std::uint64_t vertex_count_ = 0, face_count_ = 0;
  PolygonMesh mesh_;
  Colours vertex_colours_{&mesh_.attributes.vertex_properties};
  Colours face_colours_{&mesh_.attributes.face_properties};
  DroppedTally tally_;
  // The values after what a line must hold (x y z, or a face's indices): at most 9 are kept (a
  // normal, a colour, s t); a tenth only says there are too many.
  std::string_view extra_[10];
  std::vector<VertexId> face_;  // reused: a face line allocates nothing
};

}  // namespace

PolygonMesh parse_off(std::string_view bytes, const std::string& source,
                      std::vector<std::string>& dropped, std::pmr::memory_resource* memory) {
  return OffReader(bytes, memory).read(source, dropped);
}

}  // namespace petersen
