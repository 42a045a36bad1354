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
                                              const HugeVector<std::uint32_t>& corner_index,
                                              const HugeVector<std::array<double, 3>>& values,
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

}  // namespace

Buffer obj_with_attributes(const PolygonMesh& mesh, const std::string& path,
                           std::vector<std::string>& dropped) {
  const MeshAttributes& a = mesh.attributes;
  // OBJ colours are reals from 0 to 1; a byte colour (PLY's usual uchar) is scaled to that.
  const std::vector<const PropertyColumn*> colour = colour_of(a.vertex_properties, false);
  // PLY's and OFF's vertex normals and texture coordinates, when the mesh has no corner ones:
  // a vn and a vt per vertex, each corner naming its vertex's (read back as corner attributes).
  const std::vector<const PropertyColumn*> vertex_normal =
      a.normals.empty() ? all_of(a.vertex_properties, {"nx", "ny", "nz"})
                        : std::vector<const PropertyColumn*>{};
  std::vector<const PropertyColumn*> vertex_texcoord;
  for (auto [u, v] :
       {std::pair{"s", "t"}, {"u", "v"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}}) {
    if (!a.texcoords.empty()) break;
    vertex_texcoord = all_of(a.vertex_properties, {u, v});
    if (!vertex_texcoord.empty()) break;
  }
  std::vector<const PropertyColumn*> written = colour;
  written.insert(written.end(), vertex_normal.begin(), vertex_normal.end());
  written.insert(written.end(), vertex_texcoord.begin(), vertex_texcoord.end());
  drop_columns_but(a.vertex_properties, written, "vertex", "OBJ", dropped);
  drop_columns_but(a.face_properties, {}, "face", "OBJ", dropped);
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

  Buffer out(mesh.positions.size() * (2 + 3 * kNumber) + mesh.face_count() * 2 +
             mesh.corners.size() * kNumber + 64);
  for (const std::string& library : a.material_libraries) {
    out.ensure(library.size() + 8);
    out.word("mtllib ");
    out.word(library);
    out.put('\n');
  }
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
  auto put_line = [&](const char* keyword, const double* value, int components) {
    out.ensure(3 + 3 * kNumber);
    out.word(keyword);
    for (int k = 0; k < components; ++k) {
      if (k > 0) out.put(' ');
      if (!std::isfinite(value[k])) {
        throw FileError(path, 0,
                        "a texture coordinate or normal is not finite (" +
                            std::to_string(value[k]) + "); OBJ cannot hold it");
      }
      out.number(value[k]);
    }
    out.put('\n');
  };
  struct Lines {
    const decltype(a.texcoords)* values;
    const std::vector<const PropertyColumn*>* columns;
    const char* keyword;
  };
  for (const auto& [values, columns, keyword] :
       {Lines{&a.texcoords, &vertex_texcoord, "vt "}, Lines{&a.normals, &vertex_normal, "vn "}}) {
    const int components = values == &a.texcoords ? a.texcoord_components : 3;
    for (const std::array<double, 3>& value : *values) put_line(keyword, value.data(), components);
    if (columns->empty()) continue;
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      double value[3];
      for (std::size_t k = 0; k < columns->size(); ++k) value[k] = (*columns)[k]->values[v];
      put_line(keyword, value, static_cast<int>(columns->size()));
    }
  }
  // The statements that set a face attribute, written where the value changes from the face
  // before (none before the first face); a bare statement goes back to none.
  struct FaceState {
    const HugeVector<std::uint32_t>* values;
    const std::vector<std::string>* names;  // null: a number (smoothing groups)
    const char* keyword;
    std::uint32_t none, current;
  };
  FaceState states[4] = {
      {&a.face_object, &a.object_names, "o", kNoAttribute, kNoAttribute},
      {&a.face_group, &a.group_names, "g", kNoAttribute, kNoAttribute},
      {&a.face_material, &a.material_names, "usemtl", kNoAttribute, kNoAttribute},
      {&a.face_smoothing, nullptr, "s", 0, 0}};
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    for (FaceState& state : states) {
      const std::uint32_t value = state.values->empty() ? state.none : (*state.values)[f];
      if (value == state.current) continue;
      state.current = value;
      out.ensure(longest_name + kNumber + 8);
      out.word(state.keyword);
      if (!state.names) {
        out.put(' ');
        if (value == 0) {
          out.word("off");
        } else {
          out.number(value);
        }
      } else if (value != kNoAttribute) {
        out.put(' ');
        out.word((*state.names)[value]);
      }
      out.put('\n');
    }
    const std::size_t first = first_corner(mesh, f);
    const std::span<const VertexId> corners = mesh.face(f);
    out.ensure(2 + corners.size() * (3 * kNumber));
    out.put('f');
    for (std::size_t k = 0; k < corners.size(); ++k) {
      out.put(' ');
      out.number(std::uint64_t{corners[k]} + 1);  // OBJ counts from 1
      const std::uint32_t texcoord = !vertex_texcoord.empty()    ? corners[k]
                                     : a.corner_texcoord.empty() ? kNoAttribute
                                                                 : a.corner_texcoord[first + k];
      const std::uint32_t normal = !vertex_normal.empty()    ? corners[k]
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
  const std::size_t faces = mesh.face_count();
  // MeshLab's per-corner texcoord list: u v for every corner of a face, or nothing for a face
  // with a corner that has none.
  const bool texcoords = !a.corner_texcoord.empty();
  if (!texcoords && !a.texcoords.empty()) {
    dropped.push_back("texture coordinates (vt) no corner uses: PLY has no place for them");
  }
  std::uint32_t max_arity = faces > 0 ? 3 : 0;
  std::size_t partial_faces = 0;
  bool all_float = true, any_w = false;
  auto face_texcoords = [&](FaceId f) {
    const std::size_t first = first_corner(mesh, f);
    for (std::size_t k = first; k < first + mesh.arity(f); ++k) {
      if (a.corner_texcoord[k] == kNoAttribute) return false;
    }
    return true;
  };
  for (FaceId f = 0; f < faces; ++f) {
    max_arity = std::max(max_arity, mesh.arity(f));
    if (!texcoords) continue;
    if (!face_texcoords(f)) {
      const std::size_t first = first_corner(mesh, f);
      for (std::size_t k = first; k < first + mesh.arity(f); ++k) {
        partial_faces += a.corner_texcoord[k] != kNoAttribute;
      }
      continue;
    }
    const std::size_t first = first_corner(mesh, f);
    for (std::size_t k = first; k < first + mesh.arity(f); ++k) {
      const std::array<double, 3>& t = a.texcoords[a.corner_texcoord[k]];
      all_float = all_float && double(float(t[0])) == t[0] && double(float(t[1])) == t[1];
      any_w = any_w || t[2] != 0;
    }
  }
  if (partial_faces > 0) {
    dropped.push_back("texture coordinates of " + std::to_string(partial_faces) +
                      " corners of faces with a corner without one: PLY's per-face texcoord list "
                      "has no place for them");
  }
  if (any_w) dropped.push_back("third texture coordinates (w): PLY's texcoord list holds u v");
  for (const auto* columns : {&a.vertex_properties, &a.face_properties}) {
    for (const PropertyColumn& column : *columns) check_ply_name(path, column.name);
  }

  const bool wide = max_arity > 255, wide_texcoords = 2 * max_arity > 255;
  const ScalarType position_type =
      a.position_type == ScalarType::float32 ? ScalarType::float32 : ScalarType::float64;
  const ScalarType texcoord_type = all_float ? ScalarType::float32 : ScalarType::float64;
  std::string header = "ply\nformat binary_little_endian 1.0\ncomment written by petersen\n";
  header += "element vertex " + std::to_string(mesh.positions.size()) + "\n";
  std::size_t vertex_bytes = 3 * ply::size_of(position_type);
  for (const char* axis : {"x", "y", "z"}) {
    header += std::string("property ") + ply::type_name(position_type) + " " + axis + "\n";
  }
  for (const PropertyColumn* column : vertex_columns) {
    header += std::string("property ") + ply::type_name(column->type) + " " + column->name + "\n";
    vertex_bytes += ply::size_of(column->type);
  }
  header += "element face " + std::to_string(faces) + "\nproperty list " +
            (wide ? "uint" : "uchar") + " uint vertex_indices\n";
  std::size_t face_bytes = 0;
  for (const PropertyColumn& column : a.face_properties) {
    header += std::string("property ") + ply::type_name(column.type) + " " + column.name + "\n";
    face_bytes += ply::size_of(column.type);
  }
  if (texcoords) {
    header += std::string("property list ") + (wide_texcoords ? "uint " : "uchar ") +
              ply::type_name(texcoord_type) + " texcoord\n";
  }
  header += "end_header\n";
  const std::size_t count_bytes = wide ? 4 : 1, texcoord_count_bytes = wide_texcoords ? 4 : 1;
  std::size_t texcoord_bytes = 0;
  if (texcoords) {
    texcoord_bytes =
        faces * texcoord_count_bytes + 2 * mesh.corners.size() * ply::size_of(texcoord_type);
  }
  Buffer out(header.size() + mesh.positions.size() * vertex_bytes +
             faces * (count_bytes + face_bytes) + mesh.corners.size() * 4 + texcoord_bytes);
  out.word(header);
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
  auto put_count = [&](std::uint32_t count, bool wide_count) {
    if (wide_count) {
      out.binary(&count, 1);
    } else {
      out.put(static_cast<char>(count));
    }
  };
  for (FaceId f = 0; f < faces; ++f) {
    const std::span<const VertexId> corners = mesh.face(f);
    put_count(static_cast<std::uint32_t>(corners.size()), wide);
    out.binary(corners.data(), corners.size());
    for (const PropertyColumn& column : a.face_properties) put_typed(out, path, column, f);
    if (!texcoords) continue;
    if (!face_texcoords(f)) {
      put_count(0, wide_texcoords);
      continue;
    }
    put_count(static_cast<std::uint32_t>(2 * corners.size()), wide_texcoords);
    const std::size_t first = first_corner(mesh, f);
    for (std::size_t k = first; k < first + corners.size(); ++k) {
      const std::array<double, 3>& t = a.texcoords[a.corner_texcoord[k]];
      if (all_float) {
        const float uv[2] = {float(t[0]), float(t[1])};
        out.binary(uv, 2);
      } else {
        out.binary(t.data(), 2);
      }
    }
  }
  return out;
}

}  // namespace petersen
