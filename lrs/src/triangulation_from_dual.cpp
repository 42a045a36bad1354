#include <algorithm>
#include <functional>
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
                                       Connectivity connectivity,
                                       const std::function<void()>& corners_read) {
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
  const std::size_t kept = huge_pages::retained_bytes();
  Triangulation tri;
  {
    tri.input_vertex_ = spatial_vertex_order(positions, faces);
    HugeVector<VertexId> new_id(vertices);
    for (VertexId v = 0; v < vertices; ++v) new_id[tri.input_vertex_[v]] = v;

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
  // that has it (what `out` was before, so the contraction walks as it did). Made in three steps
  // so that the slots, the input's corners and all of the links are never alive at once (the
  // peak of lrs in quadrangulate, issue 15: 62 bytes per triangle with the positions, 52 so):
  // each halfedge's origin into the links' first half (halfedge h's word is field h & 1 of link
  // h / 2; the second half's pages are not touched yet), after which the corners are done with;
  // each halfedge's next into an array of its own, after which the slots are; then the pairs
  // spread out in place from the back (link h is written after link h / 2 < h is read). The
  // vertex order (2 bytes per triangle) is held through these passes, whose peak is now below
  // the augmentation's: it was made again from the positions when the links were made in one
  // pass beside the slots and corners (its cells' pass: 3.1 -> 1.4 % of the run's samples on the
  // 8M plate, about 0.1 s).
  const std::size_t halfedges = 2 * std::size_t{edges};
  tri.links_ = Links(halfedges);
  const auto half_word = [&tri](std::size_t h) -> std::uint32_t& {
    Link& link = tri.links_[h / 2];
    return h % 2 == 0 ? link.origin : link.next;
  };
  {
    HugeVector<Halfedge> last_out(vertices, kNoHalfedge);
    for (std::size_t c = 0; c < corners.size(); ++c) {
      const VertexId v = corners[c];
      half_word(node_edges[c]) = v;
      last_out[v] = node_edges[c];
    }
    if (corners_read) corners_read();
    {
      const HugeArray<Halfedge> next = make_huge_array<Halfedge>(halfedges);
      for (FaceId t = 0; t < faces; ++t) {
        const Halfedge* h = node_edges.data() + 3 * std::size_t{t};
        for (std::size_t k = 0; k < 3; ++k) next[h[k]] = h[(k + 1) % 3];
      }
      // The slots, then the nexts (12 bytes per triangle each), go back to the kernel: kept by the
      // huge-page pool, they stayed resident while the links' second half is filled and beside
      // the arrays made after them, none of which takes them again whole (armadillo-sub2: peak
      // 94-95 MB against 89 MB with the pool off).
      node_edges = HugeVector<EdgeId>();
      huge_pages::trim_retained(kept);
      for (std::size_t h = halfedges; h-- > 0;) tri.links_[h] = {half_word(h), next[h]};
    }
    huge_pages::trim_retained(kept);

    tri.out_.resize(vertices);
    for (VertexId v = 0; v < vertices; ++v) tri.out_[v] = last_out[tri.input_vertex_[v]];
  }
  {
    HugeVector<VertexId> new_id(vertices);
    for (VertexId v = 0; v < vertices; ++v) new_id[tri.input_vertex_[v]] = v;
    tri.degree_.assign(vertices, 0);
    for (std::size_t h = 0; h < halfedges; ++h) {
      Link& link = tri.links_[h];
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
