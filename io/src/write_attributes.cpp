// The writers of meshes with attributes: each format gets back what its reader keeps, spelled the
// way that reader reads it, and whatever it has no place for is listed as dropped.

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "ply_types.hpp"
#include "text_scan.hpp"
#include "write_buffer.hpp"

namespace petersen {

namespace {

// A number and the space or newline after it, at its longest.
constexpr std::size_t kNumber = Buffer::kLongestNumber + 1;

// Where face f's corners start in the corner arrays (mesh.corners, corner_texcoord, ...).
std::size_t first_corner(const PolygonMesh& mesh, FaceId f) {
  return mesh.all_triangles() ? 3 * std::size_t{f} : mesh.face_start[f];
}

const PropertyColumn* find_column(const std::vector<PropertyColumn>& columns,
                                  std::string_view name) {
  for (const PropertyColumn& column : columns) {
    if (column.name == name) return &column;
  }
  return nullptr;
}

// The columns of the given names, in that order: all of them, or none when one is missing.
std::vector<const PropertyColumn*> all_of(const std::vector<PropertyColumn>& columns,
                                          std::initializer_list<std::string_view> names) {
  std::vector<const PropertyColumn*> found;
  for (std::string_view name : names) {
    const PropertyColumn* column = find_column(columns, name);
    if (!column) return {};
    found.push_back(column);
  }
  return found;
}

// red, green, blue and, when there is one, alpha; or none without all of red, green and blue.
std::vector<const PropertyColumn*> colour_of(const std::vector<PropertyColumn>& columns,
                                             bool with_alpha = true) {
  std::vector<const PropertyColumn*> colour = all_of(columns, {"red", "green", "blue"});
  const PropertyColumn* alpha = find_column(columns, "alpha");
  if (!colour.empty() && alpha && with_alpha) colour.push_back(alpha);
  return colour;
}

// Lists every column the writer does not write.
void drop_columns_but(const std::vector<PropertyColumn>& columns,
                      const std::vector<const PropertyColumn*>& written, const char* element,
                      const char* format, std::vector<std::string>& dropped) {
  for (const PropertyColumn& column : columns) {
    if (std::find(written.begin(), written.end(), &column) == written.end()) {
      dropped.push_back(std::string(element) + " property '" + column.name + "': " + format +
                        " has no place for it");
    }
  }
}

// Lists the OBJ attributes a format has no place for; PLY keeps corner texture coordinates, and
// both keep corner normals and texture coordinates that are per vertex (vertex_columns_of).
void drop_obj_attributes(const MeshAttributes& a, const char* format, bool keeps_texcoords,
                         bool keeps_normals, std::vector<std::string>& dropped) {
  auto drop = [&](bool has, const char* what) {
    if (has) dropped.push_back(std::string(what) + ": " + format + " has no place for them");
  };
  drop(!keeps_texcoords && !a.texcoords.empty(), "texture coordinates (vt)");
  drop(!keeps_normals && !a.normals.empty(), "corner normals (vn)");
  drop(!a.face_material.empty(), "face materials (usemtl)");
  drop(!a.face_group.empty(), "face groups (g)");
  drop(!a.face_object.empty(), "face objects (o)");
  drop(!a.face_smoothing.empty(), "smoothing groups (s)");
  drop(!a.material_libraries.empty(), "material libraries (mtllib)");
}

// OBJ's corner normals or texture coordinates as vertex columns of the given names (PLY's and
// OFF's nx ny nz, OFF's s t), when every corner has one, the corners of each vertex agree on it,
// and the mesh has no columns of those names; else none. A vertex no corner uses gets zeros.
// float32 when every value is one exactly (as OBJ text written from floats is), else float64.
std::vector<PropertyColumn> vertex_columns_of(const PolygonMesh& mesh,
                                              const std::pmr::vector<std::uint32_t>& corner_index,
                                              const std::pmr::vector<std::array<double, 3>>& values,
                                              std::initializer_list<const char*> names) {
  const std::vector<PropertyColumn>& existing = mesh.attributes.vertex_properties;
  const std::size_t count = names.size();
  if (corner_index.empty() || find_column(existing, *names.begin())) return {};
  std::vector<std::uint32_t> chosen(mesh.positions.size(), kNoAttribute);
  for (std::size_t k = 0; k < mesh.corners.size(); ++k) {
    const std::uint32_t index = corner_index[k];
    if (index == kNoAttribute) return {};
    std::uint32_t& first = chosen[mesh.corners[k]];
    if (first == kNoAttribute) {
      first = index;
    } else if (first != index && !std::equal(values[first].begin(), values[first].begin() + count,
                                             values[index].begin())) {
      return {};
    }
  }
  // What the count leaves out (a third texture coordinate) must be zero: else it would be lost.
  for (const std::array<double, 3>& value : values) {
    for (std::size_t j = count; j < 3; ++j) {
      if (value[j] != 0) return {};
    }
  }
  std::vector<PropertyColumn> columns;
  bool all_float = true;
  for (const char* name : names) {
    const auto j = columns.size();
    PropertyColumn& column = columns.emplace_back();
    column.name = name;
    column.values.resize(mesh.positions.size());
    for (std::size_t v = 0; v < chosen.size(); ++v) {
      const double value = chosen[v] == kNoAttribute ? 0 : values[chosen[v]][j];
      column.values[v] = value;
      all_float = all_float && double(float(value)) == value;
    }
  }
  for (PropertyColumn& column : columns)
    column.type = all_float ? ScalarType::float32 : ScalarType::float64;
  return columns;
}

// A property value in text: a whole number for an integer type, a real one otherwise (see
// Buffer::real), as the OFF reader tells them apart.
// A binary PLY may hold NaN or infinity in a property; no text reader takes it back.
void check_finite(const std::string& path, const PropertyColumn& column, double value) {
  if (!std::isfinite(value)) {
    throw FileError(path, 0,
                    "property '" + column.name + "' has a value that is not finite (" +
                        std::to_string(value) + "); a text format cannot hold it");
  }
}

void put_value(Buffer& out, const std::string& path, const PropertyColumn& column, double value) {
  check_finite(path, column, value);
  if (column.type == ScalarType::float32 || column.type == ScalarType::float64) {
    out.real(value);
  } else {
    out.number(value);
  }
}

}  // namespace

Buffer off_with_attributes(const PolygonMesh& mesh, const std::string& path,
                           std::vector<std::string>& dropped) {
  const MeshAttributes& a = mesh.attributes;
  const std::vector<PropertyColumn> corner_normal =
      vertex_columns_of(mesh, a.corner_normal, a.normals, {"nx", "ny", "nz"});
  const std::vector<PropertyColumn> corner_st =
      vertex_columns_of(mesh, a.corner_texcoord, a.texcoords, {"s", "t"});
  drop_obj_attributes(a, "OFF", !corner_st.empty(), !corner_normal.empty(), dropped);
  auto pointers = [](const std::vector<PropertyColumn>& columns) {
    std::vector<const PropertyColumn*> all;
    for (const PropertyColumn& column : columns) all.push_back(&column);
    return all;
  };
  // Geomview's order on a vertex line: normal, colour, texture coordinates.
  const std::vector<const PropertyColumn*> normal =
                                               corner_normal.empty()
                                                   ? all_of(a.vertex_properties, {"nx", "ny", "nz"})
                                                   : pointers(corner_normal),
                                           colour = colour_of(a.vertex_properties),
                                           st = corner_st.empty()
                                                    ? all_of(a.vertex_properties, {"s", "t"})
                                                    : pointers(corner_st),
                                           face_colour = colour_of(a.face_properties);
  std::vector<const PropertyColumn*> vertex_columns = normal;
  vertex_columns.insert(vertex_columns.end(), colour.begin(), colour.end());
  vertex_columns.insert(vertex_columns.end(), st.begin(), st.end());
  drop_columns_but(a.vertex_properties, vertex_columns, "vertex", "OFF", dropped);
  drop_columns_but(a.face_properties, face_colour, "face", "OFF", dropped);

  const std::size_t faces = mesh.face_count();
  Buffer out(64 + mesh.positions.size() * (3 + vertex_columns.size()) * kNumber +
             faces * (1 + face_colour.size()) * kNumber + mesh.corners.size() * kNumber);
  out.word(st.empty() ? "" : "ST");
  out.word(colour.empty() ? "" : "C");
  out.word(normal.empty() ? "" : "N");
  out.word("OFF\n");
  out.number(mesh.positions.size());
  out.put(' ');
  out.number(faces);
  out.word(" 0\n");
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    for (int axis = 0; axis < 3; ++axis) {
      if (axis > 0) out.put(' ');
      out.number(mesh.positions[v][axis]);
    }
    for (const PropertyColumn* column : vertex_columns) {
      out.put(' ');
      put_value(out, path, *column, column->values[v]);
    }
    out.put('\n');
  }
  for (FaceId f = 0; f < faces; ++f) {
    out.number(mesh.arity(f));
    for (VertexId v : mesh.face(f)) {
      out.put(' ');
      out.number(v);
    }
    for (const PropertyColumn* column : face_colour) {
      out.put(' ');
      put_value(out, path, *column, column->values[f]);
    }
    out.put('\n');
  }
  return out;
}

namespace {

// A name as an OBJ statement's argument: the reader trims the line and cuts it at '#', and reads
// a bare statement as no name, so only names it reads back whole can be written.
void check_obj_name(const std::string& path, const std::string& name, const char* what) {
  const bool ok = !name.empty() && !text::is_space(name.front()) && !text::is_space(name.back()) &&
                  name.find_first_of("#\n\r") == std::string::npos;
  if (!ok) {
    throw FileError(
        path, 0,
        std::string(what) + " name '" + name.substr(0, 40) +
            "' cannot be written in OBJ (empty, '#', a line break, or spaces at its ends)");
  }
}

// Checks every name the OBJ will hold; returns the longest one's length.
std::size_t check_obj_names(const std::string& path, const MeshAttributes& a) {
  std::size_t longest_name = 0;
  for (const auto& [names, what] : {std::pair{&a.material_names, "material"},
                                    {&a.group_names, "group"},
                                    {&a.object_names, "object"},
                                    {&a.material_libraries, "material library"}}) {
    for (const std::string& name : *names) {
      check_obj_name(path, name, what);
      longest_name = std::max(longest_name, name.size());
    }
  }
  return longest_name;
}

// The vertex columns an OBJ holds: a colour after x y z (reals from 0 to 1; a byte colour, PLY's
// usual uchar, is scaled to that), and PLY's and OFF's vertex normals and texture coordinates
// when the mesh has no corner ones (a vn and a vt per vertex, each corner naming its vertex's,
// read back as corner attributes).
struct ObjVertexColumns {
  std::vector<const PropertyColumn*> colour, normal, texcoord;

  explicit ObjVertexColumns(const MeshAttributes& a)
      : colour(colour_of(a.vertex_properties, false)) {
    if (a.normals.empty()) normal = all_of(a.vertex_properties, {"nx", "ny", "nz"});
    for (auto [u, v] : {std::pair{"s", "t"},
                        {"u", "v"},
                        {"texture_u", "texture_v"},
                        {"texture_s", "texture_t"}}) {
      if (!a.texcoords.empty()) break;
      texcoord = all_of(a.vertex_properties, {u, v});
      if (!texcoord.empty()) break;
    }
  }
  std::vector<const PropertyColumn*> all() const {
    std::vector<const PropertyColumn*> written = colour;
    written.insert(written.end(), normal.begin(), normal.end());
    written.insert(written.end(), texcoord.begin(), texcoord.end());
    return written;
  }
};

void put_obj_vertices(Buffer& out, const std::string& path, const PolygonMesh& mesh,
                      const std::vector<const PropertyColumn*>& colour) {
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    out.ensure(2 + 6 * kNumber);
    out.word("v ");
    for (int axis = 0; axis < 3; ++axis) {
      if (axis > 0) out.put(' ');
      out.number(mesh.positions[v][axis]);
    }
    for (const PropertyColumn* column : colour) {
      out.put(' ');
      const double value = column->values[v];
      check_finite(path, *column, value);
      out.number(column->type == ScalarType::uint8 ? value / 255 : value);
    }
    out.put('\n');
  }
}

// One vt or vn line.
void put_obj_line(Buffer& out, const std::string& path, const char* keyword, const double* value,
                  int components) {
  out.ensure(3 + 3 * kNumber);
  out.word(keyword);
  for (int k = 0; k < components; ++k) {
    if (k > 0) out.put(' ');
    if (!std::isfinite(value[k])) {
      throw FileError(path, 0,
                      "a texture coordinate or normal is not finite (" + std::to_string(value[k]) +
                          "); OBJ cannot hold it");
    }
    out.number(value[k]);
  }
  out.put('\n');
}

// The vt lines, then the vn lines: the mesh's own, or one per vertex from its columns.
void put_obj_texcoords_and_normals(Buffer& out, const std::string& path, const PolygonMesh& mesh,
                                   const ObjVertexColumns& vertex) {
  const MeshAttributes& a = mesh.attributes;
  struct Lines {
    const decltype(a.texcoords)* values;
    const std::vector<const PropertyColumn*>* columns;
    const char* keyword;
  };
  for (const auto& [values, columns, keyword] :
       {Lines{&a.texcoords, &vertex.texcoord, "vt "}, Lines{&a.normals, &vertex.normal, "vn "}}) {
    const int components = values == &a.texcoords ? a.texcoord_components : 3;
    for (const std::array<double, 3>& value : *values) {
      put_obj_line(out, path, keyword, value.data(), components);
    }
    if (columns->empty()) continue;
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      double value[3];
      for (std::size_t k = 0; k < columns->size(); ++k) value[k] = (*columns)[k]->values[v];
      put_obj_line(out, path, keyword, value, static_cast<int>(columns->size()));
    }
  }
}

// A statement that sets a face attribute (o, g, usemtl, s), written where the value changes from
// the face before (none before the first face); a bare statement goes back to none.
struct FaceStatement {
  const std::pmr::vector<std::uint32_t>* values;
  const std::vector<std::string>* names;  // null: a number (smoothing groups)
  const char* keyword;
  std::uint32_t none, current;

  void put(Buffer& out, FaceId f, std::size_t longest_name) {
    const std::uint32_t value = values->empty() ? none : (*values)[f];
    if (value == current) return;
    current = value;
    out.ensure(longest_name + kNumber + 8);
    out.word(keyword);
    if (!names) {
      out.put(' ');
      if (value == 0) {
        out.word("off");
      } else {
        out.number(value);
      }
    } else if (value != kNoAttribute) {
      out.put(' ');
      out.word((*names)[value]);
    }
    out.put('\n');
  }
};

// "f v/vt/vn ...", each part written as the corner has it.
void put_obj_face(Buffer& out, const PolygonMesh& mesh, const ObjVertexColumns& vertex, FaceId f) {
  const MeshAttributes& a = mesh.attributes;
  const std::size_t first = first_corner(mesh, f);
  const std::span<const VertexId> corners = mesh.face(f);
  out.ensure(2 + corners.size() * (3 * kNumber));
  out.put('f');
  for (std::size_t k = 0; k < corners.size(); ++k) {
    out.put(' ');
    out.number(std::uint64_t{corners[k]} + 1);  // OBJ counts from 1
    const std::uint32_t texcoord = !vertex.texcoord.empty()    ? corners[k]
                                   : a.corner_texcoord.empty() ? kNoAttribute
                                                               : a.corner_texcoord[first + k];
    const std::uint32_t normal = !vertex.normal.empty()    ? corners[k]
                                 : a.corner_normal.empty() ? kNoAttribute
                                                           : a.corner_normal[first + k];
    if (texcoord == kNoAttribute && normal == kNoAttribute) continue;
    out.put('/');
    if (texcoord != kNoAttribute) out.number(std::uint64_t{texcoord} + 1);
    if (normal == kNoAttribute) continue;
    out.put('/');
    out.number(std::uint64_t{normal} + 1);
  }
  out.put('\n');
}

void put_obj_faces(Buffer& out, const PolygonMesh& mesh, const ObjVertexColumns& vertex,
                   std::size_t longest_name) {
  const MeshAttributes& a = mesh.attributes;
  FaceStatement statements[4] = {
      {&a.face_object, &a.object_names, "o", kNoAttribute, kNoAttribute},
      {&a.face_group, &a.group_names, "g", kNoAttribute, kNoAttribute},
      {&a.face_material, &a.material_names, "usemtl", kNoAttribute, kNoAttribute},
      {&a.face_smoothing, nullptr, "s", 0, 0}};
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    for (FaceStatement& statement : statements) statement.put(out, f, longest_name);
    put_obj_face(out, mesh, vertex, f);
  }
}

}  // namespace

Buffer obj_with_attributes(const PolygonMesh& mesh, const std::string& path,
                           std::vector<std::string>& dropped) {
  const MeshAttributes& a = mesh.attributes;
  const ObjVertexColumns vertex(a);
  drop_columns_but(a.vertex_properties, vertex.all(), "vertex", "OBJ", dropped);
  drop_columns_but(a.face_properties, {}, "face", "OBJ", dropped);
  const std::size_t longest_name = check_obj_names(path, a);

  Buffer out(mesh.positions.size() * (2 + 3 * kNumber) + mesh.face_count() * 2 +
             mesh.corners.size() * kNumber + 64);
  for (const std::string& library : a.material_libraries) {
    out.ensure(library.size() + 8);
    out.word("mtllib ");
    out.word(library);
    out.put('\n');
  }
  put_obj_vertices(out, path, mesh, vertex.colour);
  put_obj_texcoords_and_normals(out, path, mesh, vertex);
  put_obj_faces(out, mesh, vertex, longest_name);
  return out;
}

namespace {

template <typename T>
void put_as(Buffer& out, const std::string& path, double value, const PropertyColumn& column,
            std::size_t index) {
  if constexpr (std::is_integral_v<T>) {
    if (!(value >= double(std::numeric_limits<T>::min()) &&
          value <= double(std::numeric_limits<T>::max()) && value == std::trunc(value))) {
      throw FileError(path, 0,
                      "property '" + column.name + "' of element " + std::to_string(index) + ": " +
                          std::to_string(value) + " does not fit its type " +
                          ply::type_name(column.type));
    }
  }
  const T typed = static_cast<T>(value);
  out.binary(&typed, 1);
}

// A value of the column in its declared type; throws FileError for a value the type cannot hold.
void put_typed(Buffer& out, const std::string& path, const PropertyColumn& column,
               std::size_t index) {
  const double value = column.values[index];
  switch (column.type) {
    case ScalarType::int8:
      return put_as<std::int8_t>(out, path, value, column, index);
    case ScalarType::uint8:
      return put_as<std::uint8_t>(out, path, value, column, index);
    case ScalarType::int16:
      return put_as<std::int16_t>(out, path, value, column, index);
    case ScalarType::uint16:
      return put_as<std::uint16_t>(out, path, value, column, index);
    case ScalarType::int32:
      return put_as<std::int32_t>(out, path, value, column, index);
    case ScalarType::uint32:
      return put_as<std::uint32_t>(out, path, value, column, index);
    case ScalarType::float32:
      return put_as<float>(out, path, value, column, index);
    case ScalarType::float64:
      return put_as<double>(out, path, value, column, index);
  }
}

// A property name in a PLY header: one token.
void check_ply_name(const std::string& path, const std::string& name) {
  if (name.empty() || name.find_first_of(" \t\r\n") != std::string::npos) {
    throw FileError(path, 0, "property name '" + name.substr(0, 40) + "' cannot be written in PLY");
  }
}

// Whether every corner of face f has a texture coordinate: MeshLab's per-face texcoord list has
// u v for every corner of a face, or nothing.
bool face_has_texcoords(const PolygonMesh& mesh, FaceId f) {
  const std::size_t first = first_corner(mesh, f);
  for (std::size_t k = first; k < first + mesh.arity(f); ++k) {
    if (mesh.attributes.corner_texcoord[k] == kNoAttribute) return false;
  }
  return true;
}

// What the faces need: the largest arity (for the list count types), and of their corner texture
// coordinates, whether all are floats, whether any has a w, how many cannot be written.
struct PlyFaceSurvey {
  std::uint32_t max_arity = 0;
  bool texcoords = false;  // the mesh has corner texture coordinates
  bool all_float = true, any_w = false;
  std::size_t partial_corners = 0;  // with one, in a face with a corner without one

  explicit PlyFaceSurvey(const PolygonMesh& mesh)
      : max_arity(mesh.face_count() > 0 ? 3 : 0),
        texcoords(!mesh.attributes.corner_texcoord.empty()) {
    const MeshAttributes& a = mesh.attributes;
    for (FaceId f = 0; f < mesh.face_count(); ++f) {
      max_arity = std::max(max_arity, mesh.arity(f));
      if (!texcoords) continue;
      const std::size_t first = first_corner(mesh, f);
      if (!face_has_texcoords(mesh, f)) {
        for (std::size_t k = first; k < first + mesh.arity(f); ++k) {
          partial_corners += a.corner_texcoord[k] != kNoAttribute;
        }
        continue;
      }
      for (std::size_t k = first; k < first + mesh.arity(f); ++k) {
        const std::array<double, 3>& t = a.texcoords[a.corner_texcoord[k]];
        all_float = all_float && double(float(t[0])) == t[0] && double(float(t[1])) == t[1];
        any_w = any_w || t[2] != 0;
      }
    }
  }
  bool wide() const { return max_arity > 255; }
  bool wide_texcoords() const { return 2 * max_arity > 255; }
  ScalarType texcoord_type() const { return all_float ? ScalarType::float32 : ScalarType::float64; }

  void report(const MeshAttributes& a, std::vector<std::string>& dropped) const {
    if (!texcoords && !a.texcoords.empty()) {
      dropped.push_back("texture coordinates (vt) no corner uses: PLY has no place for them");
    }
    if (partial_corners > 0) {
      dropped.push_back("texture coordinates of " + std::to_string(partial_corners) +
                        " corners of faces with a corner without one: PLY's per-face texcoord "
                        "list has no place for them");
    }
    if (any_w) dropped.push_back("third texture coordinates (w): PLY's texcoord list holds u v");
  }
};

// The header, with the bytes a vertex record takes.
std::string ply_header(const PolygonMesh& mesh, ScalarType position_type,
                       const std::vector<const PropertyColumn*>& vertex_columns,
                       const PlyFaceSurvey& faces) {
  std::string header = "ply\nformat binary_little_endian 1.0\ncomment written by petersen\n";
  header += "element vertex " + std::to_string(mesh.positions.size()) + "\n";
  for (const char* axis : {"x", "y", "z"}) {
    header += std::string("property ") + ply::type_name(position_type) + " " + axis + "\n";
  }
  for (const PropertyColumn* column : vertex_columns) {
    header += std::string("property ") + ply::type_name(column->type) + " " + column->name + "\n";
  }
  header += "element face " + std::to_string(mesh.face_count()) + "\nproperty list " +
            (faces.wide() ? "uint" : "uchar") + " uint vertex_indices\n";
  for (const PropertyColumn& column : mesh.attributes.face_properties) {
    header += std::string("property ") + ply::type_name(column.type) + " " + column.name + "\n";
  }
  if (faces.texcoords) {
    header += std::string("property list ") + (faces.wide_texcoords() ? "uint " : "uchar ") +
              ply::type_name(faces.texcoord_type()) + " texcoord\n";
  }
  return header + "end_header\n";
}

// The body's size: every record at its declared size.
std::size_t ply_body_bytes(const PolygonMesh& mesh, ScalarType position_type,
                           const std::vector<const PropertyColumn*>& vertex_columns,
                           const PlyFaceSurvey& faces) {
  std::size_t vertex_bytes = 3 * ply::size_of(position_type);
  for (const PropertyColumn* column : vertex_columns) vertex_bytes += ply::size_of(column->type);
  std::size_t face_bytes = faces.wide() ? 4 : 1;
  for (const PropertyColumn& column : mesh.attributes.face_properties) {
    face_bytes += ply::size_of(column.type);
  }
  std::size_t texcoord_bytes = 0;
  if (faces.texcoords) {
    texcoord_bytes = mesh.face_count() * (faces.wide_texcoords() ? 4 : 1) +
                     2 * mesh.corners.size() * ply::size_of(faces.texcoord_type());
  }
  return mesh.positions.size() * vertex_bytes + mesh.face_count() * face_bytes +
         mesh.corners.size() * 4 + texcoord_bytes;
}

void put_ply_vertices(Buffer& out, const std::string& path, const PolygonMesh& mesh,
                      ScalarType position_type,
                      const std::vector<const PropertyColumn*>& vertex_columns) {
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    if (position_type == ScalarType::float32) {
      const float p[3] = {float(mesh.positions[v][0]), float(mesh.positions[v][1]),
                          float(mesh.positions[v][2])};
      out.binary(p, 3);
    } else {
      out.binary(mesh.positions[v].data(), 3);
    }
    for (const PropertyColumn* column : vertex_columns) put_typed(out, path, *column, v);
  }
}

void put_ply_count(Buffer& out, std::uint32_t count, bool wide) {
  if (wide) {
    out.binary(&count, 1);
  } else {
    out.put(static_cast<char>(count));
  }
}

// The face's texcoord list: u v per corner, or empty when a corner has none.
void put_ply_texcoords(Buffer& out, const PolygonMesh& mesh, FaceId f, const PlyFaceSurvey& faces) {
  if (!face_has_texcoords(mesh, f)) {
    put_ply_count(out, 0, faces.wide_texcoords());
    return;
  }
  put_ply_count(out, 2 * mesh.arity(f), faces.wide_texcoords());
  const std::size_t first = first_corner(mesh, f);
  for (std::size_t k = first; k < first + mesh.arity(f); ++k) {
    const std::array<double, 3>& t = mesh.attributes.texcoords[mesh.attributes.corner_texcoord[k]];
    if (faces.all_float) {
      const float uv[2] = {float(t[0]), float(t[1])};
      out.binary(uv, 2);
    } else {
      out.binary(t.data(), 2);
    }
  }
}

void put_ply_faces(Buffer& out, const std::string& path, const PolygonMesh& mesh,
                   const PlyFaceSurvey& faces) {
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    const std::span<const VertexId> corners = mesh.face(f);
    put_ply_count(out, static_cast<std::uint32_t>(corners.size()), faces.wide());
    out.binary(corners.data(), corners.size());
    for (const PropertyColumn& column : mesh.attributes.face_properties) {
      put_typed(out, path, column, f);
    }
    if (faces.texcoords) put_ply_texcoords(out, mesh, f, faces);
  }
}

}  // namespace

Buffer ply_with_attributes(const PolygonMesh& mesh, const std::string& path,
                           std::vector<std::string>& dropped) {
  const MeshAttributes& a = mesh.attributes;
  const std::vector<PropertyColumn> corner_normal =
      vertex_columns_of(mesh, a.corner_normal, a.normals, {"nx", "ny", "nz"});
  drop_obj_attributes(a, "PLY", true, !corner_normal.empty(), dropped);
  std::vector<const PropertyColumn*> vertex_columns;
  for (const auto* columns : {&a.vertex_properties, &corner_normal}) {
    for (const PropertyColumn& column : *columns) vertex_columns.push_back(&column);
  }
  const PlyFaceSurvey faces(mesh);
  faces.report(a, dropped);
  for (const auto* columns : {&a.vertex_properties, &a.face_properties}) {
    for (const PropertyColumn& column : *columns) check_ply_name(path, column.name);
  }
  const ScalarType position_type =
      a.position_type == ScalarType::float32 ? ScalarType::float32 : ScalarType::float64;
  const std::string header = ply_header(mesh, position_type, vertex_columns, faces);
  Buffer out(header.size() + ply_body_bytes(mesh, position_type, vertex_columns, faces));
  out.word(header);
  put_ply_vertices(out, path, mesh, position_type, vertex_columns);
  put_ply_faces(out, path, mesh, faces);
  return out;
}

}  // namespace petersen
