#include "ply_header.hpp"

#include <utility>

#include "ply_types.hpp"

namespace petersen::ply {

namespace {

class HeaderReader {
 public:
  HeaderReader(text::Lines& lines, const std::string& source, std::vector<std::string>& dropped)
      : lines_(lines), source_(source), dropped_(dropped), at_{source, lines} {}

  Header read() {
    std::string_view line;
    if (!lines_.next(line)) throw FileError(source_, 0, "empty file");
    if (line != "ply") at_.fail("not a PLY file: the first line is not 'ply'");
    bool have_format = false;
    while (read_line(have_format)) {
    }
    if (!have_format) at_.fail("header has no format line");
    assign_uses();
    return std::move(header_);
  }

 private:
  // One header line; false at end_header.
  bool read_line(bool& have_format) {
    std::string_view line, token;
    if (!lines_.next(line)) at_.fail("truncated header: no end_header");
    text::Tokens tokens{line};
    if (!tokens.next(token) || token == "comment" || token == "obj_info") return true;
    if (token == "end_header") return false;
    if (token == "format") {
      read_format(tokens);
      have_format = true;
    } else if (token == "element") {
      read_element(tokens);
    } else if (token == "property") {
      if (header_.elements.empty()) at_.fail("property before any element");
      header_.elements.back().properties.push_back(read_property(tokens));
    } else {
      at_.fail("unknown header keyword " + text::Located::quote(token));
    }
    return true;
  }

  void read_format(text::Tokens& tokens) {
    std::string_view token;
    tokens.next(token);
    if (token == "ascii") {
      header_.encoding = Encoding::ascii;
    } else if (token == "binary_little_endian") {
      header_.encoding = Encoding::little;
    } else if (token == "binary_big_endian") {
      header_.encoding = Encoding::big;
    } else {
      at_.fail("unknown PLY format " + text::Located::quote(token));
    }
  }

  void read_element(text::Tokens& tokens) {
    std::string_view name, count_text;
    tokens.next(name);
    tokens.next(count_text);
    std::int64_t count = 0;
    if (name.empty() || !text::parse_integer(count_text, count) || count < 0) {
      at_.fail("expected 'element NAME COUNT'");
    }
    Element& element = header_.elements.emplace_back();
    element.name = std::string(name);
    element.count = static_cast<std::uint64_t>(count);
    element.line = lines_.line;
  }

  Property read_property(text::Tokens& tokens) {
    Property property;
    std::string_view token;
    tokens.next(token);
    if (token == "list") {
      property.is_list = true;
      property.use = Use::skip_list;
      tokens.next(token);
      if (!parse_type(token, property.count_type) || !is_integer(property.count_type)) {
        at_.fail("bad list count type " + text::Located::quote(token));
      }
      tokens.next(token);
    }
    if (!parse_type(token, property.type)) at_.fail("unknown type " + text::Located::quote(token));
    if (!tokens.next(token)) at_.fail("property without a name");
    property.name = std::string(token);
    return property;
  }

  [[noreturn]] void fail_at(const Element& element, const std::string& what) const {
    throw FileError(source_, element.line, what);
  }

  // Gives every property of the vertex and face elements its use; every other property keeps
  // skip or skip_list.
  void assign_uses() {
    const auto [vertex, face] = find_vertex_and_face();
    if (vertex->count > 0xFFFFFFFFu) fail_at(*vertex, "more than 2^32 - 1 vertices");
    if (face->count > 0xFFFFFFFFu) fail_at(*face, "more than 2^32 - 1 faces");
    header_.vertex_count = vertex->count;
    place_coordinates(*vertex);
    place_face_lists(*face);
    keep_columns(*vertex, header_.vertex_columns);
    // A strip's scalars belong to no one triangle: read past.
    if (face->role == Role::face) keep_columns(*face, header_.face_columns);
    for (const Element& element : header_.elements) {
      if (element.role == Role::strips) {
        for (const Property& p : element.properties) {
          if (p.use == Use::corners) continue;
          dropped_.push_back("tristrips " + std::string(p.is_list ? "list " : "") + "property '" +
                             p.name + "'");
        }
      }
      if (element.role == Role::other) {
        dropped_.push_back("element '" + element.name + "' (" + std::to_string(element.count) +
                           " records)");
      }
    }
    // Written back as float when all three were; anything else is written as double.
    bool all_float = header_.encoding != Encoding::ascii;
    for (const Property& p : vertex->properties) {
      if (p.use == Use::coordinate) all_float = all_float && p.type == ScalarType::float32;
    }
    header_.position_type = all_float ? ScalarType::float32 : ScalarType::float64;
  }

  // The one vertex and the one face (or tristrips) element, given their roles; a second of
  // either is refused where the header declares it.
  std::pair<Element*, Element*> find_vertex_and_face() {
    Element* vertex = nullptr;
    Element* face = nullptr;
    for (Element& element : header_.elements) {
      const bool is_faces = element.name == "face" || element.name == "tristrips";
      if (element.name != "vertex" && !is_faces) continue;
      Element*& found = is_faces ? face : vertex;
      if (found && found->name != element.name) {
        fail_at(element, "both a 'face' and a 'tristrips' element: the faces come from one");
      }
      if (found) fail_at(element, "second '" + element.name + "' element");
      found = &element;
    }
    if (!vertex) at_.fail("header declares no vertex element");
    if (!face) at_.fail("header declares no face element (nor tristrips)");
    vertex->role = Role::vertex;
    face->role = face->name == "face" ? Role::face : Role::strips;
    return {vertex, face};
  }

  // x, y and z: the last scalar property of each name.
  void place_coordinates(Element& vertex) {
    static constexpr const char* axes[3] = {"x", "y", "z"};
    for (int axis = 0; axis < 3; ++axis) {
      Property* found = nullptr;
      for (Property& p : vertex.properties) {
        if (p.name == axes[axis] && !p.is_list) found = &p;
      }
      if (!found) {
        fail_at(vertex, std::string("vertex element has no scalar property ") + axes[axis]);
      }
      found->use = Use::coordinate;
      found->slot = axis;
    }
  }

  // The corner list (vertex_indices or vertex_index) and MeshLab's texcoord list: the last of
  // each. A strip has no texcoord list of its own.
  void place_face_lists(Element& face) {
    Property* corners = nullptr;
    Property* texcoords = nullptr;
    for (Property& p : face.properties) {
      if (p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index")) {
        if (!is_integer(p.type)) fail_at(face, face.name + " indices must have an integer type");
        corners = &p;
      }
      if (p.is_list && p.name == "texcoord" && face.role == Role::face) texcoords = &p;
    }
    if (!corners) fail_at(face, face.name + " element has no vertex_indices list");
    corners->use = Use::corners;
    if (texcoords) texcoords->use = Use::texcoords;
  }

  // Every other scalar of the element becomes a column; a list, or an x, y or z declared again,
  // is dropped.
  void keep_columns(Element& element, std::vector<PropertyColumn>& columns) {
    const bool is_vertex = element.role == Role::vertex;
    for (Property& p : element.properties) {
      if (p.use != Use::skip && p.use != Use::skip_list) continue;
      const bool duplicate_axis = is_vertex && (p.name == "x" || p.name == "y" || p.name == "z");
      if (p.is_list || duplicate_axis) {
        dropped_.push_back(element.name + " " + (p.is_list ? "list " : "") + "property '" + p.name +
                           "'" + (duplicate_axis ? " (declared again)" : ""));
        continue;
      }
      p.use = Use::column;
      p.slot = static_cast<int>(columns.size());
      columns.push_back({p.name, p.type, {}});
    }
  }

  text::Lines& lines_;
  const std::string& source_;
  std::vector<std::string>& dropped_;
  text::Located at_;
  Header header_;
};

}  // namespace

Header read_header(text::Lines& lines, const std::string& source,
                   std::vector<std::string>& dropped) {
  return HeaderReader(lines, source, dropped).read();
}

}  // namespace petersen::ply
