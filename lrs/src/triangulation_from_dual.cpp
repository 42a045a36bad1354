#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>

#include "petersen/graph/component_forest.hpp"
#include "petersen/lrs/triangulation.hpp"
#include "spatial_order.hpp"

namespace petersen::lrs {

Triangulation Triangulation::from_dual(const Positions& positions,
                                       std::span<const VertexId> corners,
                                       HugeVector<EdgeId> node_edges, HugeVector<NodeId> edge_ends,
                                       Connectivity connectivity) {
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
  Triangulation tri;
  {
    const HugeVector<VertexId> order = spatial_vertex_order(positions, faces);
    HugeVector<VertexId> new_id(vertices);
    for (VertexId v = 0; v < vertices; ++v) new_id[order[v]] = v;

    // Edges by their smaller vertex (new ids), a stable counting sort: the edges around a vertex
    // get neighbouring ids, as build_dual's (min, max) order gives them on the spatial copy. Each
    // edge's key, then its new id, is written over its second end, which nothing reads after it
    // is checked: a triangle is the edge's first or its second end (no array of new edge ids,
    // 6 bytes per triangle at this pass's peak).
    std::optional<ComponentForest> forest;
    if (connectivity == Connectivity::unknown) forest.emplace(faces, std::span<const NodeId>());
    HugeVector<std::uint32_t> start(std::size_t{vertices} + 1, 0);
    const auto names = [&](NodeId t, EdgeId e) {
      const std::size_t c = 3 * std::size_t{t};
      return node_edges[c] == e || node_edges[c + 1] == e || node_edges[c + 2] == e;
    };
    for (EdgeId e = 0; e < edges; ++e) {
      const NodeId t = edge_ends[2 * e], u = edge_ends[2 * e + 1];
      // Both ends name the edge among their sides: with 3 sides per triangle and 2 ends per edge,
      // every side then names an edge that ends at its triangle, once.
      if (t >= faces || u >= faces || u == t || !names(t, e) || !names(u, e)) {
        throw std::invalid_argument("lrs::Triangulation::from_dual: edge " + std::to_string(e) +
                                    " is not a side of its triangles");
      }
      if (forest) forest->join(std::span<const NodeId>(edge_ends.data() + 2 * e, 2));
      const std::size_t c = 3 * std::size_t{t};
      const std::size_t k = node_edges[c] == e ? 0 : node_edges[c + 1] == e ? 1 : 2;
      const VertexId a = corners[c + k], b = corners[c + (k + 1) % 3];
      if (a >= vertices || b >= vertices) {
        throw std::invalid_argument("lrs::Triangulation::from_dual: triangle " + std::to_string(t) +
                                    " has a corner out of range");
      }
      edge_ends[2 * e + 1] = std::min(new_id[a], new_id[b]);
      ++start[edge_ends[2 * e + 1] + 1];
    }
    // Counted once the arrays are known to be a dual (every end in range), unless the caller has.
    if (forest) {
      if (const std::uint32_t components = forest->root_count(); components > 1) {
        throw MeshError(std::to_string(components) +
                        " components (triangles joined through edges)");
      }
      forest.reset();
    }
    for (VertexId v = 0; v < vertices; ++v) start[v + 1] += start[v];
    for (EdgeId e = 0; e < edges; ++e) edge_ends[2 * e + 1] = start[edge_ends[2 * e + 1]]++;
  }
  // Side k of triangle t becomes halfedge 2e' + s, written over its slot: s = 0 in the edge's
  // first triangle.
  for (FaceId t = 0; t < faces; ++t) {
    for (std::size_t k = 0; k < 3; ++k) {
      EdgeId& slot = node_edges[3 * std::size_t{t} + k];
      slot = 2 * edge_ends[2 * slot + 1] + (edge_ends[2 * slot] == t ? 0u : 1u);
    }
  }
  edge_ends = HugeVector<NodeId>();

  // The links with the input's vertex ids, and each input vertex's halfedge in the last triangle
  // that has it (what `out` was before, so the contraction walks as it did). The vertex order and
  // its inverse are not held through this pass, where the slots, the links and the input's corners
  // are all alive (the peak of lrs in quadrangulate, issue 15: 2 of 64 bytes per triangle); the
  // order is made again from the positions once the slots are freed.
  tri.links_.resize(2 * std::size_t{edges});
  {
    HugeVector<Halfedge> last_out(vertices, kNoHalfedge);
    for (FaceId t = 0; t < faces; ++t) {
      const Halfedge* h = node_edges.data() + 3 * std::size_t{t};
      for (std::size_t k = 0; k < 3; ++k) {
        const VertexId v = corners[3 * std::size_t{t} + k];
        tri.links_[h[k]] = {v, h[(k + 1) % 3]};
        last_out[v] = h[k];
      }
    }
    node_edges = HugeVector<EdgeId>();

    tri.input_vertex_ = spatial_vertex_order(positions, faces);
    tri.out_.resize(vertices);
    for (VertexId v = 0; v < vertices; ++v) tri.out_[v] = last_out[tri.input_vertex_[v]];
  }
  {
    HugeVector<VertexId> new_id(vertices);
    for (VertexId v = 0; v < vertices; ++v) new_id[tri.input_vertex_[v]] = v;
    tri.degree_.assign(vertices, 0);
    for (Link& link : tri.links_) {
      link.origin = new_id[link.origin];
      ++tri.degree_[link.origin];
    }
  }

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
