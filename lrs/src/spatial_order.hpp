#pragma once
// A mesh renumbered along a space-filling curve, for lrs::Triangulation::from_mesh (and the
// vertex order alone, for from_dual).
//
// Why: the contraction step (paper §3.3) walks around vertices all over the surface, and the
// expansion replays it backwards; their cost is the cache and TLB misses of those walks through
// tens of megabytes of halfedges. Meshes bring no locality of their own (in armadillo-sub2,
// consecutive triangles share 0.008 vertices on average, and build_dual numbers edges by vertex
// id), so the walks jump at every step. Numbered along a Morton curve over the bounding box,
// the vertices, faces and edges around a vertex sit in a few neighbouring lines and pages.
// Two counting sorts, O(V + F).

#include <vector>

#include "petersen/mesh/mesh.hpp"

namespace petersen::lrs {

struct SpatialMesh {
  PolygonMesh mesh;  ///< the input renumbered: same surface, same orientation
  std::pmr::vector<VertexId>
      input_vertex;  ///< vertex v of `mesh` is vertex input_vertex[v] of the input
};

/// The vertices ordered by Morton cell of their position, for a surface of `face_count` faces (a
/// few hundred faces per cell; ties in input order): new vertex v is input vertex order[v]. On the
/// default memory resource, as its scratch.
std::pmr::vector<VertexId> spatial_vertex_order(const Positions& positions, std::size_t face_count);

/// `mesh` (every face a triangle) with its vertices ordered by Morton cell (a few hundred faces per
/// cell; ties in input order) and its triangles by the cell of their first corner; each triangle
/// keeps its corners' cyclic order.
SpatialMesh spatially_ordered(const PolygonMesh& mesh);

}  // namespace petersen::lrs
