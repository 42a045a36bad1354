#include "attributes.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <string>
#include <vector>

#include "arrays.hpp"

namespace petersen::python {

namespace {

// The numpy dtype of each ScalarType (in the enum's order) and the name position_type uses.
constexpr const char* kDtypeNames[] = {"int8",  "uint8",  "int16",   "uint16",
                                       "int32", "uint32", "float32", "float64"};

template <class Index>
py::array_t<std::int64_t> index_array(const std::pmr::vector<Index>& values) {
  py::array_t<std::int64_t> out(values.size());
  std::int64_t* data = out.mutable_data();
  for (std::size_t i = 0; i < values.size(); ++i) {
    data[i] = values[i] == kNoAttribute ? std::int64_t{-1} : std::int64_t{values[i]};
  }
  return out;
}

py::array_t<double> rows_of(const std::pmr::vector<std::array<double, 3>>& values, std::size_t k) {
  py::array_t<double> out({values.size(), k});
  double* data = out.mutable_data();
  for (std::size_t i = 0; i < values.size(); ++i) {
    for (std::size_t c = 0; c < k; ++c) data[i * k + c] = values[i][c];
  }
  return out;
}

template <class T>
py::array column_as(const std::pmr::vector<double>& values) {
  py::array_t<T> out(values.size());
  T* data = out.mutable_data();
  for (std::size_t i = 0; i < values.size(); ++i) data[i] = static_cast<T>(values[i]);
  return out;
}

py::array column_array(const PropertyColumn& column) {
  switch (column.type) {
    case ScalarType::int8:
      return column_as<std::int8_t>(column.values);
    case ScalarType::uint8:
      return column_as<std::uint8_t>(column.values);
    case ScalarType::int16:
      return column_as<std::int16_t>(column.values);
    case ScalarType::uint16:
      return column_as<std::uint16_t>(column.values);
    case ScalarType::int32:
      return column_as<std::int32_t>(column.values);
    case ScalarType::uint32:
      return column_as<std::uint32_t>(column.values);
    case ScalarType::float32:
      return column_as<float>(column.values);
    case ScalarType::float64:
      break;
  }
  return column_as<double>(column.values);
}

py::dict columns_dict(const std::vector<PropertyColumn>& columns) {
  py::dict out;
  for (const PropertyColumn& column : columns) out[py::str(column.name)] = column_array(column);
  return out;
}

// The PLY type a numpy column is written with: its own, or the nearest PLY has (64-bit integers
// as 32-bit, whose range the writer checks; booleans as uint8).
ScalarType scalar_type_of(const py::array& array, const std::string& what) {
  const char kind = array.dtype().kind();
  const auto size = array.dtype().itemsize();
  if (kind == 'f') return size <= 4 ? ScalarType::float32 : ScalarType::float64;
  if (kind == 'b') return ScalarType::uint8;
  if (kind == 'i') {
    return size == 1 ? ScalarType::int8 : size == 2 ? ScalarType::int16 : ScalarType::int32;
  }
  if (kind == 'u') {
    return size == 1 ? ScalarType::uint8 : size == 2 ? ScalarType::uint16 : ScalarType::uint32;
  }
  throw py::type_error(what + " must hold numbers, not dtype " +
                       std::string(py::str(array.dtype())));
}

std::vector<PropertyColumn> columns_from(const py::handle& obj, const std::string& what) {
  if (!py::isinstance<py::dict>(obj)) throw py::type_error(what + " must be a dict {name: array}");
  std::vector<PropertyColumn> columns;
  for (const auto& [key, value] : py::reinterpret_borrow<py::dict>(obj)) {
    if (!py::isinstance<py::str>(key)) throw py::type_error(what + ": a name is not a str");
    PropertyColumn column;
    column.name = py::cast<std::string>(key);
    const std::string name = what + "['" + column.name + "']";
    py::array array = py::array::ensure(value);
    if (!array) throw py::type_error(name + " is not array-like");
    if (array.ndim() != 1) throw py::value_error(name + " must be one-dimensional");
    column.type = scalar_type_of(array, name);
    auto doubles = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
    column.values.assign(doubles.data(), doubles.data() + doubles.size());
    columns.push_back(std::move(column));
  }
  return columns;
}

// A list of str; anything else is a TypeError naming `what` rather than pybind11's bare cast error.
std::vector<std::string> names_from(const py::handle& obj, const std::string& what) {
  if (py::isinstance<py::str>(obj) || !py::isinstance<py::sequence>(obj)) {
    throw py::type_error(what + " must be a list of str");
  }
  std::vector<std::string> names;
  for (py::handle item : py::reinterpret_borrow<py::sequence>(obj)) {
    if (!py::isinstance<py::str>(item)) {
      throw py::type_error(what + "[" + std::to_string(names.size()) + "] is not a str");
    }
    names.push_back(py::cast<std::string>(item));
  }
  return names;
}

std::pmr::vector<std::uint32_t> indices_from(const py::handle& obj, const std::string& what) {
  auto array = integer_array(obj, what.c_str());
  if (array.ndim() != 1) throw py::value_error(what + " must be one-dimensional");
  std::pmr::vector<std::uint32_t> out(static_cast<std::size_t>(array.size()));
  for (std::size_t i = 0; i < out.size(); ++i) {
    const std::int64_t v = array.data()[i];
    if (v < -1 || v >= std::int64_t{kNoAttribute}) {
      throw py::value_error(what + "[" + std::to_string(i) + "] = " + std::to_string(v) +
                            " is out of range (-1 means none)");
    }
    out[i] = v == -1 ? kNoAttribute : static_cast<std::uint32_t>(v);
  }
  return out;
}

std::pmr::vector<std::array<double, 3>> rows_from(const py::handle& obj, const std::string& what,
                                                  std::size_t min_k, std::size_t max_k) {
  auto array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(obj);
  if (!array) throw py::type_error(what + " is not an array of numbers");
  const std::size_t k = array.ndim() == 2 ? array.shape(1) : 0;
  if (k < min_k || k > max_k) {
    throw py::value_error(what + " must have shape (n, " + std::to_string(min_k) +
                          (min_k == max_k ? "" : " or " + std::to_string(max_k)) + ")");
  }
  std::pmr::vector<std::array<double, 3>> out(static_cast<std::size_t>(array.shape(0)), {0, 0, 0});
  for (std::size_t i = 0; i < out.size(); ++i) {
    for (std::size_t c = 0; c < k; ++c) out[i][c] = array.data()[i * k + c];
  }
  return out;
}

}  // namespace

py::dict attributes_dict(const MeshAttributes& a) {
  py::dict d;
  if (!a.texcoords.empty()) d["texcoords"] = rows_of(a.texcoords, a.texcoord_components);
  if (!a.normals.empty()) d["normals"] = rows_of(a.normals, 3);
  if (!a.corner_texcoord.empty()) d["corner_texcoord"] = index_array(a.corner_texcoord);
  if (!a.corner_normal.empty()) d["corner_normal"] = index_array(a.corner_normal);
  if (!a.material_names.empty()) d["material_names"] = a.material_names;
  if (!a.group_names.empty()) d["group_names"] = a.group_names;
  if (!a.object_names.empty()) d["object_names"] = a.object_names;
  if (!a.face_material.empty()) d["face_material"] = index_array(a.face_material);
  if (!a.face_group.empty()) d["face_group"] = index_array(a.face_group);
  if (!a.face_object.empty()) d["face_object"] = index_array(a.face_object);
  if (!a.face_smoothing.empty()) d["face_smoothing"] = index_array(a.face_smoothing);
  if (!a.material_libraries.empty()) d["material_libraries"] = a.material_libraries;
  if (!a.vertex_properties.empty()) d["vertex_properties"] = columns_dict(a.vertex_properties);
  if (!a.face_properties.empty()) d["face_properties"] = columns_dict(a.face_properties);
  if (a.position_type != ScalarType::float64) {
    d["position_type"] = kDtypeNames[static_cast<int>(a.position_type)];
  }
  return d;
}

void attributes_from(const py::handle& obj, PolygonMesh& mesh) {
  if (obj.is_none()) return;
  if (!py::isinstance<py::dict>(obj)) throw py::type_error("attributes must be a dict");
  MeshAttributes& a = mesh.attributes;
  for (const auto& [key_object, value] : py::reinterpret_borrow<py::dict>(obj)) {
    if (!py::isinstance<py::str>(key_object))
      throw py::type_error("an attribute name is not a str");
    const std::string key = py::cast<std::string>(key_object);
    const std::string what = "attributes['" + key + "']";
    if (key == "texcoords") {
      a.texcoords = rows_from(value, what, 2, 3);
      a.texcoord_components = static_cast<std::uint8_t>(py::array::ensure(value).shape(1));
    } else if (key == "normals") {
      a.normals = rows_from(value, what, 3, 3);
    } else if (key == "corner_texcoord") {
      a.corner_texcoord = indices_from(value, what);
    } else if (key == "corner_normal") {
      a.corner_normal = indices_from(value, what);
    } else if (key == "material_names") {
      a.material_names = names_from(value, what);
    } else if (key == "group_names") {
      a.group_names = names_from(value, what);
    } else if (key == "object_names") {
      a.object_names = names_from(value, what);
    } else if (key == "face_material") {
      a.face_material = indices_from(value, what);
    } else if (key == "face_group") {
      a.face_group = indices_from(value, what);
    } else if (key == "face_object") {
      a.face_object = indices_from(value, what);
    } else if (key == "face_smoothing") {
      a.face_smoothing = indices_from(value, what);
    } else if (key == "material_libraries") {
      a.material_libraries = names_from(value, what);
    } else if (key == "vertex_properties") {
      a.vertex_properties = columns_from(value, what);
    } else if (key == "face_properties") {
      a.face_properties = columns_from(value, what);
    } else if (key == "position_type") {
      const std::string name = py::str(value);
      int type = 0;
      while (type < 8 && name != kDtypeNames[type]) ++type;
      if (type == 8) throw py::value_error(what + ": unknown type '" + name + "'");
      a.position_type = static_cast<ScalarType>(type);
    } else {
      throw py::value_error("unknown attribute '" + key + "'");
    }
  }
  check_attributes(mesh);
}

MeshAttributes attributes_in_order(const PolygonMesh& mesh, std::span<const FaceId> order) {
  MeshAttributes a = mesh.attributes;
  auto per_corner = [&](std::pmr::vector<std::uint32_t>& values,
                        const std::pmr::vector<std::uint32_t>& in) {
    if (in.empty()) return;
    values.clear();
    for (FaceId f : order) {
      const std::size_t first = mesh.face(f).data() - mesh.corners.data();
      values.insert(values.end(), in.begin() + first, in.begin() + first + mesh.arity(f));
    }
  };
  per_corner(a.corner_texcoord, mesh.attributes.corner_texcoord);
  per_corner(a.corner_normal, mesh.attributes.corner_normal);
  auto per_face = [&](auto& values, const auto& in) {
    if (in.empty()) return;
    for (std::size_t i = 0; i < order.size(); ++i) values[i] = in[order[i]];
  };
  per_face(a.face_material, mesh.attributes.face_material);
  per_face(a.face_group, mesh.attributes.face_group);
  per_face(a.face_object, mesh.attributes.face_object);
  per_face(a.face_smoothing, mesh.attributes.face_smoothing);
  for (std::size_t c = 0; c < a.face_properties.size(); ++c) {
    per_face(a.face_properties[c].values, mesh.attributes.face_properties[c].values);
  }
  return a;
}

}  // namespace petersen::python
