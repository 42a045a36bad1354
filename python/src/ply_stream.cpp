// The binary PLY triangle stream for petersen.distributed: each call maps the file and reads its
// header (O(header)), so a task on any worker needs only the path; ids as int64, the GIL released
// while the file is read. FileError (bad header, a face that is not a triangle, a vertex out of
// range) reaches Python as ValueError naming the file and the face.

#include "ply_stream.hpp"

#include <pybind11/numpy.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "petersen/io/file_error.hpp"
#include "petersen/io/ply_stream.hpp"

namespace py = pybind11;

namespace petersen::python {
namespace {

using Int64Array = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;

py::dict layout_py(const std::string& path) {
  const PlyTriangleStream in(path);
  py::dict layout;
  layout["vertex_count"] = in.vertex_count();
  layout["face_count"] = in.face_count();
  layout["vertex_offset"] = in.vertex_offset();
  layout["face_offset"] = in.face_offset();
  layout["vertex_declaration"] = in.vertex_declaration();
  return layout;
}

// Faces lo..hi-1 as an (hi - lo, 3) int64 array of vertex ids.
py::array_t<std::int64_t> read_triangles_py(const std::string& path, std::uint64_t lo,
                                            std::uint64_t hi) {
  std::vector<VertexId> corners;
  {
    py::gil_scoped_release release;
    const PlyTriangleStream in(path);
    if (lo > hi || hi > in.face_count()) {
      throw FileError(path, 0,
                      "faces " + std::to_string(lo) + ".." + std::to_string(hi) + " beyond its " +
                          std::to_string(in.face_count()));
    }
    corners.resize(3 * (hi - lo));
    in.read_faces(lo, hi - lo, corners);
  }
  py::array_t<std::int64_t> out({static_cast<py::ssize_t>(hi - lo), py::ssize_t{3}});
  std::copy(corners.begin(), corners.end(), out.mutable_data());
  return out;
}

// The positions of the corners of faces F ((m, k) vertex ids: triangles, quads), (m, k, 3)
// float64: the values the in-memory reader gives, read only where F names them.
py::array_t<double> read_corner_positions_py(const std::string& path, const Int64Array& faces) {
  if (faces.ndim() != 2 || faces.shape(1) < 1) throw py::value_error("F: an (m, k) array");
  const std::size_t m = static_cast<std::size_t>(faces.shape(0));
  const std::size_t k = static_cast<std::size_t>(faces.shape(1));
  py::array_t<double> out(
      {static_cast<py::ssize_t>(m), static_cast<py::ssize_t>(k), py::ssize_t{3}});
  const std::int64_t* ids = faces.data();
  auto* positions = reinterpret_cast<std::array<double, 3>*>(out.mutable_data());
  py::gil_scoped_release release;
  const PlyTriangleStream in(path);
  std::vector<VertexId> corners(k * m);
  for (std::size_t i = 0; i < k * m; ++i) {
    if (ids[i] < 0 || static_cast<std::uint64_t>(ids[i]) >= in.vertex_count()) {
      throw FileError(path, 0,
                      "vertex " + std::to_string(ids[i]) + " out of range (" +
                          std::to_string(in.vertex_count()) + " vertices)");
    }
    corners[i] = static_cast<VertexId>(ids[i]);
  }
  in.read_positions(corners, {positions, k * m});
  return out;
}

}  // namespace

void add_ply_stream(py::module_& m) {
  m.def("ply_triangle_layout", &layout_py, py::arg("path"));
  m.def("read_triangles", &read_triangles_py, py::arg("path"), py::arg("lo"), py::arg("hi"));
  m.def("read_corner_positions", &read_corner_positions_py, py::arg("path"), py::arg("F"));
}

}  // namespace petersen::python
