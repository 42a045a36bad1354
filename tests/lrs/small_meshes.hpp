#pragma once
// Hand-made closed triangulations and comparisons for the LRS tests.

#include <algorithm>
#include <array>
#include <stdexcept>
#include <utility>
#include <vector>

#include "expansion_step.hpp"
#include "petersen/dualize/dual.hpp"
#include "petersen/matching/matching.hpp"
#include "petersen/mesh/mesh.hpp"
#include "triangulation.hpp"

namespace petersen::lrs::testing {

inline PolygonMesh mesh_of(std::uint32_t vertices,
                           const std::vector<std::array<VertexId, 3>>& faces) {
  PolygonMesh mesh;
  for (std::uint32_t v = 0; v < vertices; ++v) mesh.positions.push_back({double(v), 0, 0});
  for (const auto& t : faces) mesh.add_face(t);
  return mesh;
}

inline PolygonMesh tetrahedron() {
  return mesh_of(4, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}});
}

/// Vertices 0/1, 2/3, 4/5 are antipodal pairs.
inline PolygonMesh octahedron() {
  return mesh_of(
      6, {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}});
}

/// The tetrahedron with face (0, 1, 3) split at a new vertex 4: the 3-cycle 0-1-3 bounds no face
/// and separates 2 from 4.
inline PolygonMesh stacked_tetrahedron() {
  return mesh_of(5, {{0, 2, 1}, {1, 2, 3}, {0, 3, 2}, {0, 1, 4}, {1, 3, 4}, {3, 0, 4}});
}

/// Triangulation::from_mesh, its numbering as given unless asked.
inline Triangulation from_triangles(
    const PolygonMesh& mesh,
    Triangulation::Numbering numbering = Triangulation::Numbering::as_given) {
  return Triangulation::from_mesh(mesh, numbering);
}

/// The mesh's corners, three per triangle.
inline std::vector<VertexId> flat_corners(const PolygonMesh& mesh) {
  return {mesh.corners.begin(), mesh.corners.end()};
}

/// Triangulation::from_dual on the mesh's build_dual graph (copies of its arrays).
inline Triangulation from_dual_of(const PolygonMesh& mesh) {
  const CubicGraph dual = build_dual(mesh).graph;
  const std::span<const EdgeId> slots = dual.node_edges();
  const std::span<const NodeId> ends = dual.edge_ends();
  return Triangulation::from_dual(mesh.positions, flat_corners(mesh), {slots.begin(), slots.end()},
                                  {ends.begin(), ends.end()});
}

/// The oriented faces as vertex triples rotated to start at their smallest vertex, sorted.
inline std::vector<std::array<VertexId, 3>> oriented_faces(const PolygonMesh& mesh) {
  std::vector<std::array<VertexId, 3>> faces;
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    const auto c = mesh.face(f);
    std::array<VertexId, 3> t = {c[0], c[1], c[2]};
    while (t[0] > t[1] || t[0] > t[2]) t = {t[1], t[2], t[0]};
    faces.push_back(t);
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}

/// K's dual as a CubicGraph, an oracle for into_dual_rows: node f is to_mesh's triangle f, dual
/// edge e crosses edge e, and node f's k-th edge is edge k of to_mesh's triangle f. Every face
/// alive.
inline CubicGraph dual_graph_of(const Triangulation& tri) {
  std::pmr::vector<EdgeId> node_edges(3 * std::size_t{tri.live_faces()});
  std::pmr::vector<NodeId> edge_ends(2 * std::size_t{tri.edge_capacity()});
  FaceId f = 0;
  for (Halfedge h = 0; h < 2 * tri.edge_capacity(); ++h) {
    if (!tri.smallest_of_face(h)) continue;
    const Halfedge n = tri.next(h), p = tri.next(n);
    for (const auto& [k, side] : {std::pair{0, h}, std::pair{1, n}, std::pair{2, p}}) {
      node_edges[3 * std::size_t{f} + k] = Triangulation::edge(side);
      edge_ends[side] = f;
    }
    ++f;
  }
  return CubicGraph::from_incidence(std::move(node_edges), std::move(edge_ends));
}

/// M (the expansion's matched edges) as a matching of dual_graph_of(K), whose edge ids are K's.
inline Matching matching_of(const CubicGraph& dual, const ExpansionResult& expansion) {
  Matching matching(dual.node_count());
  for (EdgeId e = 0; e < dual.edge_count(); ++e) {
    if (!(expansion.edge_state[e] & kMatched)) continue;
    const auto [a, b] = dual.endpoints(e);
    if (matching.is_matched(a) || matching.is_matched(b)) {
      throw std::logic_error("two edges of M pair one face");
    }
    matching.match(dual, e);
  }
  return matching;
}

/// Identical arrays for every live element (ids, origins, next, faces, degrees, liveness).
inline bool identical(const Triangulation& a, const Triangulation& b) {
  if (a.edge_capacity() != b.edge_capacity() || a.vertex_capacity() != b.vertex_capacity() ||
      a.live_vertices() != b.live_vertices() || a.live_edges() != b.live_edges() ||
      a.live_faces() != b.live_faces()) {
    return false;
  }
  for (EdgeId e = 0; e < a.edge_capacity(); ++e) {
    if (a.edge_alive(e) != b.edge_alive(e)) return false;
    if (!a.edge_alive(e)) continue;
    for (Halfedge h = 2 * e; h < 2 * e + 2; ++h) {
      if (a.origin(h) != b.origin(h) || a.next(h) != b.next(h)) {
        return false;
      }
    }
  }
  for (VertexId v = 0; v < a.vertex_capacity(); ++v) {
    if (a.vertex_alive(v) != b.vertex_alive(v)) return false;
    if (a.vertex_alive(v) && a.degree(v) != b.degree(v)) return false;
  }
  return true;
}

}  // namespace petersen::lrs::testing
