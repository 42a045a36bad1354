#pragma once
// numpy arrays and Python sequences to the library's flat arrays and back: inputs of any integer
// or float dtype and memory order (copied only when the dtype or order differs), outputs owned
// numpy arrays.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "petersen/graph/cubic_graph.hpp"
#include "petersen/mesh/mesh.hpp"

namespace petersen::python {

namespace py = pybind11;

/// A C-contiguous int64 view of an integer array-like, copying only when dtype or order differ;
/// `what` names it in the TypeError for another dtype.
py::array_t<std::int64_t, py::array::c_style> integer_array(const py::handle& obj,
                                                            const char* what);

/// V, an (n, 3) array-like of numbers, as positions. Throws ValueError for another shape, and
/// naming the vertex for a coordinate that is not finite (NaN, ±inf): the one check of the
/// module's every entry that takes positions.
Positions positions_from(const py::handle& V);

/// F, an (m, k) integer array (every face k corners, k >= 3) or a sequence of faces (each a
/// sequence of integers), as faces over `vertex_count` vertices. Throws ValueError for a negative
/// or too large index, TypeError for a non-integer dtype. Ranges against vertex_count are the
/// library's check.
void add_faces_from(const py::handle& F, PolygonMesh& mesh);

/// An (e, 2) integer array-like as pairs; `what` names it in the ValueError or TypeError.
std::vector<std::array<std::int64_t, 2>> pairs_from(const py::handle& obj, const char* what);

/// The (e, 2) array of node pairs `edges` over nodes 0..n-1; ValueError naming the edge otherwise.
std::vector<std::array<NodeId, 2>> node_pairs(std::uint32_t n, const py::handle& edges);

/// The indices of the edges matched in mate_edge (by node, kNoEdge when free), sorted: each edge
/// once, at its first end in `list`.
std::vector<std::int64_t> matched_edges(const std::vector<std::array<NodeId, 2>>& list,
                                        std::span<const EdgeId> mate_edge);

/// The mesh's positions as an owned (n, 3) float64 array.
py::array_t<double> positions_array(const Positions& positions);

/// The mesh's faces: an owned (m, 3) int64 array when every face is a triangle, else a list of
/// int64 arrays, one per face.
py::object faces_object(const PolygonMesh& mesh);

/// An owned (count, k) int64 array filled by fill(row, out) for each row.
template <class Fill>
py::array_t<std::int64_t> rows_array(std::size_t count, std::size_t k, Fill fill) {
  py::array_t<std::int64_t> out({count, k});
  std::int64_t* data = out.mutable_data();
  for (std::size_t i = 0; i < count; ++i) fill(i, data + i * k);
  return out;
}

}  // namespace petersen::python
