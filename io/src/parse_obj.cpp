// OBJ: positions ("v x y z", or "v x y z r g b" with a vertex colour), texture coordinates
// ("vt u [v [w]]"), normals ("vn x y z") and faces ("f" and corners written v, v/vt, v//vn or
// v/vt/vn; a negative index counts back from the last one read so far, -1 being the latest, per
// the OBJ spec), with the face attributes "usemtl", "g", "o" and "s" set, and "mtllib" lines.
// Faces have any number of corners from 3 on. Every other statement (l, p, curv, vp, ...) is read
// past and reported as dropped. A texture coordinate or normal index past those read so far
// (dangling) drops that attribute of the face, reported once per attribute, or is refused when
// strict. Messages number vertices, texture coordinates, normals and faces from 1, as OBJ does.

#include <string>
#include <unordered_map>
#include <vector>

#include "parsers.hpp"
#include "text_scan.hpp"

namespace petersen {

namespace {

// Material, group or object names, each kept once, with the index faces refer to it by.
class NameTable {
 public:
  explicit NameTable(std::vector<std::string>& names) : names_(names) {}
  std::uint32_t index(std::string_view name) {
    const auto [it, added] =
        index_.try_emplace(std::string(name), static_cast<std::uint32_t>(names_.size()));
    if (added) names_.push_back(it->first);
    return it->second;
  }

 private:
  std::vector<std::string>& names_;
  std::unordered_map<std::string, std::uint32_t> index_;
};

// A statement's argument: the rest of the line without surrounding white space, since names may
// hold spaces ("g left arm").
std::string_view argument(std::string_view rest) {
  while (!rest.empty() && text::is_space(rest.front())) rest.remove_prefix(1);
  while (!rest.empty() && text::is_space(rest.back())) rest.remove_suffix(1);
  return rest;
}

// The names of the attributes a face index refers to, for messages.
constexpr const char* kIndexKinds[3] = {"vertex", "texture coordinate", "normal"};

const char* const kColourNames[3] = {"red", "green", "blue"};

// The reader's state between lines: what the face statements set, and scratch reused by every
// face line so that one allocates nothing. Messages are built only on error.
class ObjReader {
 public:
  ObjReader(std::string_view bytes, const std::string& source, const ReadMeshOptions& options)
      : options_(options),
        lines_{bytes},
        at_{source, lines_},
        source_(source),
        mesh_(options.memory),
        attributes_(mesh_.attributes),
        materials_{attributes_.material_names},
        groups_{attributes_.group_names},
        objects_{attributes_.object_names} {
    // Reserving by a guess from the size keeps the large files from re-growing many times: a "v"
    // line is about 30 bytes and there are about two triangles (6 corners) per vertex.
    mesh_.positions.reserve(bytes.size() / 90);
    mesh_.corners.reserve(bytes.size() / 15);
  }

  PolygonMesh read(std::vector<std::string>& dropped) {
    std::string_view line, token;
    bool any_content = false;
    while (lines_.next(line)) {
      text::Tokens tokens{text::strip_comment(line)};
      if (!tokens.next(token)) continue;
      any_content = true;
      if (token == "v") {
        read_vertex(tokens);
      } else if (token == "f") {
        read_face(tokens);
      } else {
        statement(token, tokens);
      }
    }
    if (!any_content) throw FileError(source_, 0, "empty file");
    tally_.report(dropped);
    if (!attributes_.vertex_properties.empty() && uncoloured_vertices_ > 0) {
      dropped.push_back(std::to_string(uncoloured_vertices_) +
                        " vertices without a colour in a file with vertex colours: given 0 0 0");
    }
    return std::move(mesh_);
  }

 private:
  // "v x y z", or "v x y z r g b" with a colour.
  void read_vertex(text::Tokens& tokens) {
    std::array<double, 6> values;
    std::string_view token;
    for (std::size_t k = 0; k < 3; ++k) {
      if (!tokens.next(token)) at_.fail(vertex_name() + ": expected 3 coordinates");
      if (!text::parse_real(token, values[k])) {
        at_.fail(vertex_name() + ": bad coordinate " + text::Located::quote(token));
      }
    }
    std::size_t count = 3;
    while (tokens.next(token)) {
      double x = 0;
      if (!text::parse_real(token, x)) {
        at_.fail(vertex_name() + ": bad value " + text::Located::quote(token));
      }
      if (count < values.size()) values[count] = x;
      ++count;
    }
    if (mesh_.positions.size() == 0xFFFFFFFFu) at_.fail("more than 2^32 - 1 vertices");
    if (count == 3 && attributes_.vertex_properties.empty()) {
      ++uncoloured_vertices_;
    } else {
      vertex_colour(values, count);
    }
    mesh_.positions.push_back({values[0], values[1], values[2]});
  }

  // "f" and its corners: the face's corners, with texture coordinate and normal indices when some
  // corner has a slash.
  void read_face(text::Tokens& tokens) {
    face_.clear();
    face_texcoords_.clear();
    face_normals_.clear();
    dangling_[0] = dangling_[1] = false;
    bool slashes = false;  // some corner is written with a texture coordinate or normal
    std::string_view token;
    while (tokens.next(token)) {
      if (token.find('/') == std::string_view::npos) {
        // The common "f 1 2 3", checked first: large files are mostly that.
        face_.push_back(resolve(token, token, 0, mesh_.positions.size()));
        if (slashes) {
          face_texcoords_.push_back(kNoAttribute);
          face_normals_.push_back(kNoAttribute);
        }
        continue;
      }
      if (!slashes) {
        // The face's first corner with a slash: those before it have neither.
        slashes = true;
        face_texcoords_.assign(face_.size(), kNoAttribute);
        face_normals_.assign(face_.size(), kNoAttribute);
      }
      read_slashed_corner(token);
    }
    if (!corner_count_ok(face_.size())) {
      at_.fail(corner_count_error(mesh_.face_count() + 1, face_.size()));
    }
    if (dangling_[0] || dangling_[1]) drop_dangling();
    if (!corners_fit(mesh_, face_.size())) at_.fail("more than 2^32 - 1 face corners");
    if (!slashes && attributes_.has_corner_attributes()) {
      // Corners without a texture coordinate or normal in a file that has some elsewhere.
      face_texcoords_.assign(face_.size(), kNoAttribute);
      face_normals_.assign(face_.size(), kNoAttribute);
      slashes = true;
    }
    if (slashes || face_statements_) face_attributes(slashes);
    mesh_.add_face(face_);
  }

  // v/vt, v//vn or v/vt/vn: an empty or absent part is no index.
  void read_slashed_corner(std::string_view token) {
    std::string_view parts[3];
    std::string_view rest = token;
    int part_count = 0;
    for (;;) {
      const std::size_t slash = rest.find('/');
      if (part_count == 3) at_.fail(face_name() + ": bad corner " + text::Located::quote(token));
      parts[part_count++] = rest.substr(0, slash);
      if (slash == std::string_view::npos) break;
      rest.remove_prefix(slash + 1);
    }
    face_.push_back(resolve(token, parts[0], 0, mesh_.positions.size()));
    face_texcoords_.push_back(parts[1].empty()
                                  ? kNoAttribute
                                  : resolve(token, parts[1], 1, attributes_.texcoords.size()));
    face_normals_.push_back(
        parts[2].empty() ? kNoAttribute : resolve(token, parts[2], 2, attributes_.normals.size()));
  }

  // An index as written in a face ("3", "-1"), into the `count` values of its kind read so far. A
  // texture coordinate or normal index past them is dangling: no index (kNoAttribute), the face
  // marked for drop_dangling, unless strict.
  std::uint32_t resolve(std::string_view corner, std::string_view index_text, int kind,
                        std::size_t count) {
    std::int64_t index = 0;
    if (!text::parse_integer(index_text, index) || index == 0) bad_index(corner, kind);
    const std::int64_t signed_count = static_cast<std::int64_t>(count);
    const std::int64_t zero_based = index > 0 ? index - 1 : signed_count + index;
    if (zero_based < 0 || zero_based >= signed_count) {
      if (kind == 0 || options_.strict) index_out_of_range(index, kind, count);
      dangling_[kind - 1] = true;
      return kNoAttribute;
    }
    return static_cast<std::uint32_t>(zero_based);
  }

  // A face with a dangling texture coordinate or normal index has none of that attribute at any
  // corner: half a face's normals would make a seam the file never had.
  [[gnu::cold, gnu::noinline]] void drop_dangling() {
    if (dangling_[0]) {
      face_texcoords_.assign(face_.size(), kNoAttribute);
      tally_.add(
          "faces' texture coordinate indices past the file's texture coordinates (those "
          "faces have none)",
          lines_.line);
    }
    if (dangling_[1]) {
      face_normals_.assign(face_.size(), kNoAttribute);
      tally_.add("faces' normal indices past the file's normals (those faces have none)",
                 lines_.line);
    }
  }

  // Elements as OBJ numbers them, from 1.
  std::string face_name() const { return "face " + std::to_string(mesh_.face_count() + 1); }
  std::string vertex_name() const { return "vertex " + std::to_string(mesh_.positions.size() + 1); }

  // The messages of a bad index, out of line: the loop over corners is the reader's hot path.
  [[noreturn, gnu::cold, gnu::noinline]] void bad_index(std::string_view corner, int kind) const {
    at_.fail(face_name() + ": bad " + kIndexKinds[kind] + " index " + text::Located::quote(corner));
  }
  [[noreturn, gnu::cold, gnu::noinline]] void index_out_of_range(std::int64_t index, int kind,
                                                                 std::size_t count) const {
    at_.fail(face_name() + ": " + kIndexKinds[kind] + " index " + std::to_string(index) +
             " out of range (" + std::to_string(count) + " " +
             (kind == 0   ? "vertices"
              : kind == 1 ? "texture coordinates"
                          : "normals") +
             " read so far)");
  }

  // Every statement but v and f, out of line: the loop over v and f lines is the hot path.
  [[gnu::noinline]] void statement(std::string_view token, text::Tokens& tokens) {
    if (token == "vt" || token == "vn") {
      read_texcoord_or_normal(token == "vn", tokens);
    } else if (token == "usemtl" || token == "g" || token == "o") {
      // No name (a bare "g") is no group: the faces after it have none, as before the first.
      const std::string_view name = argument(tokens.rest);
      std::uint32_t& value = token == "usemtl" ? material_ : token == "g" ? group_ : object_;
      NameTable& table = token == "usemtl" ? materials_ : token == "g" ? groups_ : objects_;
      value = name.empty() ? kNoAttribute : table.index(name);
      face_statements_ = true;
    } else if (token == "s") {
      read_smoothing(argument(tokens.rest));
    } else if (token == "mtllib") {
      const std::string_view name = argument(tokens.rest);
      if (name.empty()) at_.fail("mtllib without a file name");
      attributes_.material_libraries.emplace_back(name);
    } else {
      // Built by appends: GCC 12 gives a false -Wrestrict on chains of operator+ here.
      std::string kind(1, '\'');
      kind.append(token.substr(0, 40)).append("' lines");
      tally_.add(kind, lines_.line);
    }
  }

  // "vt u [v [w]]" or "vn x y z".
  void read_texcoord_or_normal(bool is_normal, text::Tokens& tokens) {
    auto& values = is_normal ? attributes_.normals : attributes_.texcoords;
    auto name = [&] {
      return std::string(is_normal ? "normal " : "texture coordinate ") +
             std::to_string(values.size() + 1);
    };
    std::array<double, 3> value{0, 0, 0};
    std::size_t count = 0;
    std::string_view token;
    while (tokens.next(token)) {
      if (count == 3) at_.fail(name() + ": more than 3 values");
      if (!text::parse_real(token, value[count])) {
        at_.fail(name() + ": bad value " + text::Located::quote(token));
      }
      ++count;
    }
    if (is_normal ? count != 3 : count == 0) {
      at_.fail(name() + (is_normal ? ": expected 3 values" : ": expected 1 to 3 values"));
    }
    if (values.size() == 0xFFFFFFFFu - 1) {
      at_.fail("more than 2^32 - 2 " + std::string(is_normal ? "normals" : "texture coordinates"));
    }
    if (!is_normal && count == 3) attributes_.texcoord_components = 3;
    values.push_back(value);
  }

  // "s off", "s 0" (none) or "s N".
  void read_smoothing(std::string_view value) {
    std::int64_t number = 0;
    if (value == "off") {
      smoothing_ = 0;
    } else if (text::parse_integer(value, number) && number >= 0 && number <= 0xFFFFFFFFll) {
      smoothing_ = static_cast<std::uint32_t>(number);
      face_statements_ = true;
    } else {
      at_.fail("bad smoothing group " + text::Located::quote(value) +
               " (expected off or a number)");
    }
  }

  // A vertex's colour (r g b after x y z), or 0 0 0 for one without in a file with colours.
  [[gnu::noinline]] void vertex_colour(const std::array<double, 6>& values, std::size_t count) {
    std::vector<PropertyColumn>& colours = attributes_.vertex_properties;
    if (count == 6) {
      if (colours.empty()) {
        // The first coloured vertex: those before it had none.
        for (const char* name : kColourNames) {
          colours.push_back({name, ScalarType::float32, {}});
          colours.back().values.assign(mesh_.positions.size(), 0.0);
        }
      }
      for (int k = 0; k < 3; ++k) colours[k].values.push_back(values[3 + k]);
      return;
    }
    if (count != 3) {
      tally_.add("'v' lines with values beyond x y z other than a colour", lines_.line);
    }
    for (PropertyColumn& column : colours) column.values.push_back(0.0);
    ++uncoloured_vertices_;
  }

  // The attributes of the face being read, before add_face: its corners' texture coordinates
  // and normals, and the values the usemtl, g, o and s lines set.
  [[gnu::noinline]] void face_attributes(bool corners) {
    const std::size_t corners_before = mesh_.corners.size(), faces_before = mesh_.face_count();
    if (corners) {
      for (std::size_t k = 0; k < face_.size(); ++k) {
        push_attribute(attributes_.corner_texcoord, face_texcoords_[k], kNoAttribute,
                       corners_before + k);
        push_attribute(attributes_.corner_normal, face_normals_[k], kNoAttribute,
                       corners_before + k);
      }
    }
    push_attribute(attributes_.face_material, material_, kNoAttribute, faces_before);
    push_attribute(attributes_.face_group, group_, kNoAttribute, faces_before);
    push_attribute(attributes_.face_object, object_, kNoAttribute, faces_before);
    push_attribute(attributes_.face_smoothing, smoothing_, 0, faces_before);
  }

  const ReadMeshOptions& options_;
  text::Lines lines_;
  const text::Located at_;
  const std::string& source_;
  PolygonMesh mesh_;
  MeshAttributes& attributes_;  // mesh_'s
  std::vector<VertexId> face_;
  std::vector<std::uint32_t> face_texcoords_, face_normals_;
  NameTable materials_, groups_, objects_;
  std::uint32_t material_ = kNoAttribute, group_ = kNoAttribute, object_ = kNoAttribute;
  std::uint32_t smoothing_ = 0;
  bool face_statements_ = false;  // a usemtl, g, o or s line has been read
  // Per attribute (texture coordinate, normal): the face being read names one not read so far.
  bool dangling_[2] = {false, false};
  DroppedTally tally_;
  std::uint64_t uncoloured_vertices_ = 0;
};

}  // namespace

PolygonMesh parse_obj(std::string_view bytes, const std::string& source,
                      const ReadMeshOptions& options, std::vector<std::string>& dropped) {
  return ObjReader(bytes, source, options).read(dropped);
}

}  // namespace petersen
