#include "arrays.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace petersen::python {

py::array_t<std::int64_t, py::array::c_style> integer_array(const py::handle& obj,
                                                            const char* what) {
  py::array array = py::array::ensure(obj);
  if (!array) throw py::type_error(std::string(what) + " is not array-like");
  const char kind = array.dtype().kind();
  if (array.size() > 0 && kind != 'i' && kind != 'u') {
    throw py::type_error(std::string(what) + " must hold integers, not dtype " +
                         std::string(py::str(array.dtype())));
  }
  return py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(array);
}

namespace {

VertexId vertex_id(std::int64_t v, std::size_t face) {
  if (v < 0 || v >= std::int64_t{std::numeric_limits<VertexId>::max()}) {
    throw py::value_error("face " + std::to_string(face) + ": vertex index " + std::to_string(v) +
                          " is out of range");
  }
  return static_cast<VertexId>(v);
}

}  // namespace

Positions positions_from(const py::handle& V) {
  auto array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(V);
  if (!array) throw py::type_error("V is not an array of numbers");
  if (array.ndim() != 2 || array.shape(1) != 3) {
    throw py::value_error("V must have shape (n, 3)");
  }
  Positions positions(static_cast<std::size_t>(array.shape(0)));
  const double* data = array.data();
  for (std::size_t i = 0; i < positions.size(); ++i) {
    positions[i] = {data[3 * i], data[3 * i + 1], data[3 * i + 2]};
    if (!std::isfinite(data[3 * i]) || !std::isfinite(data[3 * i + 1]) ||
        !std::isfinite(data[3 * i + 2])) {
      const py::tuple xyz = py::make_tuple(data[3 * i], data[3 * i + 1], data[3 * i + 2]);
      throw py::value_error(
          "V: vertex " + std::to_string(i) +
          " has a coordinate that is not finite: " + py::repr(xyz).cast<std::string>());
    }
  }
  return positions;
}

void add_faces_from(const py::handle& F, PolygonMesh& mesh) {
  if (py::isinstance<py::array>(F)) {
    auto array = integer_array(F, "F");
    if (array.ndim() != 2 || array.shape(1) < 3) {
      throw py::value_error("F must have shape (m, k) with k >= 3, or be a list of faces");
    }
    const std::size_t m = array.shape(0), k = array.shape(1);
    const std::int64_t* data = array.data();
    if (k == 3) {  // the flat all-triangle layout, filled directly
      mesh.corners.resize(mesh.corners.size() + 3 * m);
      VertexId* out = mesh.corners.data() + mesh.corners.size() - 3 * m;
      for (std::size_t i = 0; i < 3 * m; ++i) out[i] = vertex_id(data[i], i / 3);
      return;
    }
    std::vector<VertexId> face(k);
    for (std::size_t f = 0; f < m; ++f) {
      for (std::size_t c = 0; c < k; ++c) face[c] = vertex_id(data[f * k + c], f);
      mesh.add_face(face);
    }
    return;
  }
  if (!py::isinstance<py::sequence>(F)) {
    throw py::type_error("F must be an (m, k) integer array or a sequence of faces");
  }
  std::vector<VertexId> face;
  std::size_t f = 0;
  for (py::handle item : py::reinterpret_borrow<py::sequence>(F)) {
    auto array = integer_array(item, "a face");
    if (array.ndim() != 1 || array.shape(0) < 3) {
      throw py::value_error("face " + std::to_string(f) +
                            " must be a sequence of at least three vertex indices");
    }
    face.resize(array.shape(0));
    for (std::size_t c = 0; c < face.size(); ++c) face[c] = vertex_id(array.data()[c], f);
    mesh.add_face(face);
    ++f;
  }
}

std::vector<std::array<std::int64_t, 2>> pairs_from(const py::handle& obj, const char* what) {
  auto array = integer_array(obj, what);
  if (array.size() == 0) return {};
  if (array.ndim() != 2 || array.shape(1) != 2) {
    throw py::value_error(std::string(what) + " must have shape (e, 2)");
  }
  std::vector<std::array<std::int64_t, 2>> pairs(array.shape(0));
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    pairs[i] = {array.data()[2 * i], array.data()[2 * i + 1]};
  }
  return pairs;
}

py::array_t<double> positions_array(const Positions& positions) {
  py::array_t<double> out({positions.size(), std::size_t{3}});
  double* data = out.mutable_data();
  for (std::size_t i = 0; i < positions.size(); ++i) {
    for (int k = 0; k < 3; ++k) data[3 * i + k] = positions[i][k];
  }
  return out;
}

py::object faces_object(const PolygonMesh& mesh) {
  if (mesh.all_triangles()) {
    return rows_array(mesh.face_count(), 3, [&](std::size_t f, std::int64_t* row) {
      for (int c = 0; c < 3; ++c) row[c] = mesh.corners[3 * f + c];
    });
  }
  py::list faces;
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    const auto face = mesh.face(f);
    py::array_t<std::int64_t> row(face.size());
    for (std::size_t c = 0; c < face.size(); ++c) row.mutable_data()[c] = face[c];
    faces.append(std::move(row));
  }
  return faces;
}

std::vector<std::array<NodeId, 2>> node_pairs(std::uint32_t n, const py::handle& edges) {
  const std::vector<std::array<std::int64_t, 2>> pairs = pairs_from(edges, "edges");
  std::vector<std::array<NodeId, 2>> list(pairs.size());
  for (std::size_t e = 0; e < list.size(); ++e) {
    for (int k = 0; k < 2; ++k) {
      const std::int64_t v = pairs[e][k];
      if (v < 0 || v >= std::int64_t{n}) {
        throw py::value_error("edge " + std::to_string(e) + ": node " + std::to_string(v) +
                              " is out of range (" + std::to_string(n) + " nodes)");
      }
      list[e][k] = static_cast<NodeId>(v);
    }
  }
  return list;
}

std::vector<std::int64_t> matched_edges(const std::vector<std::array<NodeId, 2>>& list,
                                        std::span<const EdgeId> mate_edge) {
  std::vector<std::int64_t> matched;
  for (NodeId v = 0; v < mate_edge.size(); ++v) {
    const EdgeId e = mate_edge[v];
    if (e != kNoEdge && list[e][0] == v) matched.push_back(e);
  }
  std::sort(matched.begin(), matched.end());
  return matched;
}

}  // namespace petersen::python
