#include <algorithm>
#include <stdexcept>
#include <string>

#include "petersen/graph/component_forest.hpp"
#include "petersen/lrs/triangulation.hpp"
#include "spatial_order.hpp"

namespace petersen::lrs {

Triangulation Triangulation::from_dual(const Positions& positions,
                                       std::span<const VertexId> corners,
                                       HugeVector<EdgeId> node_edges,
                                       HugeVector<NodeId> edge_ends) {
  const auto faces = static_cast<std::uint32_t>(corners.size() / 3);
  const auto edges = static_cast<std::uint32_t>(edge_ends.size() / 2);
  const auto vertices = static_cast<std::uint32_t>(positions.size());
  if (corners.size() % 3 != 0 || node_edges.size() != corners.size() ||
      edge_ends.size() != 2 * std::size_t{faces} * 3 / 2 || faces == 0) {
    throw std::invalid_argument("lrs::Triangulation::from_dual: " + std::to_string(faces) +
                                " triangles, " + std::to_string(node_edges.size()) +
                                " edge slots and " + std::to_string(edges) +
                                " edges are not a closed mesh's dual");
  }
  if (const std::uint32_t components = ComponentForest(faces, edge_ends).root_count();
      components > 1) {
    throw MeshError(std::to_string(components) + " components (triangles joined through edges)");
  }
  Triangulation tri;
  tri.input_vertex_ = spatial_vertex_order(positions, faces);
  HugeVector<VertexId> new_id(vertices);
  for (VertexId v = 0; v < vertices; ++v) new_id[tri.input_vertex_[v]] = v;

  // Edges by their smaller vertex (new ids), a stable counting sort: the edges around a vertex
  // get neighbouring ids, as build_dual's (min, max) order gives them on the spatial copy.
  HugeVector<EdgeId> new_edge(edges);
  {
    HugeVector<std::uint32_t> start(std::size_t{vertices} + 1, 0);
    for (EdgeId e = 0; e < edges; ++e) {
      const NodeId t = edge_ends[2 * e];
      const std::size_t c = 3 * std::size_t{t};
      if (t >= faces || edge_ends[2 * e + 1] >= faces || edge_ends[2 * e + 1] == t ||
          (node_edges[c] != e && node_edges[c + 1] != e && node_edges[c + 2] != e)) {
        throw std::invalid_argument("lrs::Triangulation::from_dual: edge " + std::to_string(e) +
                                    " is not a side of its triangles");
      }
      const std::size_t k = node_edges[c] == e ? 0 : node_edges[c + 1] == e ? 1 : 2;
      const VertexId a = corners[c + k], b = corners[c + (k + 1) % 3];
      if (a >= vertices || b >= vertices) {
        throw std::invalid_argument("lrs::Triangulation::from_dual: triangle " + std::to_string(t) +
                                    " has a corner out of range");
      }
      new_edge[e] = std::min(new_id[a], new_id[b]);
      ++start[new_edge[e] + 1];
    }
    for (VertexId v = 0; v < vertices; ++v) start[v + 1] += start[v];
    for (EdgeId e = 0; e < edges; ++e) new_edge[e] = start[new_edge[e]]++;
  }
  // Side k of triangle t becomes halfedge 2e' + s, written over its slot: s = 0 in the edge's
  // first triangle. The dual's edge list is then done with.
  for (FaceId t = 0; t < faces; ++t) {
    for (std::size_t k = 0; k < 3; ++k) {
      EdgeId& slot = node_edges[3 * std::size_t{t} + k];
      if (slot >= edges || (edge_ends[2 * slot] != t && edge_ends[2 * slot + 1] != t)) {
        throw std::invalid_argument("lrs::Triangulation::from_dual: side " + std::to_string(k) +
                                    " of triangle " + std::to_string(t) + " names edge " +
                                    std::to_string(slot) + ", which does not end at it");
      }
      slot = 2 * new_edge[slot] + (edge_ends[2 * slot] == t ? 0u : 1u);
    }
  }
  new_edge = HugeVector<EdgeId>();
  edge_ends = HugeVector<NodeId>();

  tri.links_.resize(2 * std::size_t{edges});
  tri.out_.assign(vertices, kNoHalfedge);
  tri.degree_.assign(vertices, 0);
  for (FaceId t = 0; t < faces; ++t) {
    const Halfedge* h = node_edges.data() + 3 * std::size_t{t};
    for (std::size_t k = 0; k < 3; ++k) {
      const VertexId v = new_id[corners[3 * std::size_t{t} + k]];
      tri.links_[h[k]] = {v, h[(k + 1) % 3]};
      tri.out_[v] = h[k];
      ++tri.degree_[v];
    }
  }
  node_edges = HugeVector<EdgeId>();
  new_id = HugeVector<VertexId>();

  tri.edge_alive_.assign(edges, 1);
  tri.face_capacity_ = faces;
  tri.live_edges_ = edges;
  tri.live_faces_ = faces;

  // Each vertex's outgoing halfedges must form one rotation: the turn h -> next(twin(h)) stays at
  // the vertex when the two triangles of every edge run along it in opposite directions, and
  // visits all of them when the vertex is not pinched.
  for (VertexId v = 0; v < vertices; ++v) {
    const Halfedge first = tri.out_[v];
    if (first == kNoHalfedge) continue;
    ++tri.live_vertices_;
    std::uint32_t around = 0;
    Halfedge h = first;
    do {
      if (tri.origin(h) != v) {
        throw MeshError("inconsistent orientation at vertex " +
                        std::to_string(tri.input_vertex(v)));
      }
      ++around;
      h = tri.rotate_cw(h);
    } while (h != first);
    if (around != tri.degree_[v]) {
      throw MeshError("pinched vertex " + std::to_string(tri.input_vertex(v)) +
                      " (its triangles form more than one fan)");
    }
  }
  return tri;
}

}  // namespace petersen::lrs
