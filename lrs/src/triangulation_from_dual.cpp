#include <algorithm>
#include <array>
#include <bit>
#include <exception>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "petersen/graph/component_forest.hpp"
#include "petersen/graph/parallel.hpp"
#include "spatial_order.hpp"
#include "triangulation.hpp"

namespace petersen::lrs {

namespace {

// Each vertex's triangles must form one fan whose triangles all turn the same way: walked from a
// corner at v, the side that enters v (from the corner before it) is an edge whose other triangle
// leaves v along it, and the walk from corner to corner comes back to its start having visited
// every corner at v. Checked before anything is built, so that from_dual refuses a mesh before
// the caller's corners_read: a caller that falls back to another method reads the corners again.
// The arrays are not yet known to be a dual: every read is checked. Each vertex is walked once,
// from its first corner; a corner that no walk reached is then on a second fan. walk_fans walks
// the vertices of one parity, setting their corners' bits in `visited` (a bit per corner and, its
// own, per vertex: 0.8 bytes per triangle for both parities).
//
// A walk is a chain of dependent random reads (the edge's ends, then the next triangle's corners
// and slots) in the input's order, not yet the spatial one. So kLanes walks advance in turn, in
// two rounds per step: each lane's edge ends are read and the next triangle fetched ahead, then
// each lane turns, without a branch on which corner is v (taken at random, its mispredictions
// would throw the other lanes' reads away). Sixteen lanes cut the check's time to a third of one
// walk at a time on large meshes (about 100 instructions a corner).
void walk_fans(std::span<const VertexId> corners, std::span<const EdgeId> node_edges,
               std::span<const NodeId> edge_ends, std::uint32_t vertices, std::uint32_t parity,
               std::vector<std::uint64_t>& visited, std::vector<std::uint64_t>& has_fan) {
  const std::size_t corner_count = corners.size();
  const auto faces = static_cast<NodeId>(corner_count / 3);
  const std::size_t edges = edge_ends.size() / 2;
  const auto is_set = [](const std::vector<std::uint64_t>& bits, std::size_t i) {
    return (bits[i / 64] >> (i % 64) & 1) != 0;
  };
  const auto set = [](std::vector<std::uint64_t>& bits, std::size_t i) {
    bits[i / 64] |= std::uint64_t{1} << (i % 64);
  };
  const auto not_a_dual = [](const std::string& what) {
    return std::invalid_argument("lrs::Triangulation::from_dual: " + what);
  };

  constexpr std::size_t kLanes = 16;
  constexpr std::array<std::size_t, 3> kSlotBefore = {2, 0, 1};  // (k + 2) % 3, without a division
  struct Walk {
    std::size_t first;  // the corner it started from
    std::size_t enter;  // the slot of the side entering the vertex at the current corner
    NodeId face;        // the current corner's triangle
    VertexId vertex;
    EdgeId edge;  // that side's edge
    NodeId next;  // the triangle across it
  };
  std::array<Walk, kLanes> walks;
  std::size_t live = 0, scan = 0;
  while (true) {
    for (; live < kLanes && scan < corner_count; ++scan) {
      const VertexId v = corners[scan];
      if (v >= vertices) {
        throw not_a_dual("triangle " + std::to_string(scan / 3) + " has a corner out of range");
      }
      if (v % 2 != parity || is_set(has_fan, v)) continue;
      set(has_fan, v);
      set(visited, scan);
      const std::size_t k = scan % 3;
      walks[live++] = {scan, scan - k + kSlotBefore[k], static_cast<NodeId>(scan / 3), v, 0, 0};
    }
    if (live == 0) break;
    for (std::size_t i = 0; i < live; ++i) {
      Walk& w = walks[i];
      w.edge = node_edges[w.enter];
      if (w.edge >= edges) {
        throw not_a_dual("triangle " + std::to_string(w.face) + " has a side out of range");
      }
      const NodeId a = edge_ends[2 * std::size_t{w.edge}];
      const NodeId b = edge_ends[2 * std::size_t{w.edge} + 1];
      w.next = a ^ b ^ w.face;
      if ((a != w.face && b != w.face) || w.next >= faces || w.next == w.face) {
        throw not_a_dual("edge " + std::to_string(w.edge) + " is not a side of triangle " +
                         std::to_string(w.face) + " and another");
      }
      __builtin_prefetch(corners.data() + 3 * std::size_t{w.next});
      __builtin_prefetch(node_edges.data() + 3 * std::size_t{w.next});
    }
    for (std::size_t i = 0; i < live;) {
      Walk& w = walks[i];
      const std::size_t c = 3 * std::size_t{w.next};
      const VertexId v = w.vertex;
      const unsigned at0 = corners[c] == v, at1 = corners[c + 1] == v, at2 = corners[c + 2] == v;
      const std::size_t j = at1 + 2 * at2;
      if (at0 + at1 + at2 != 1 || node_edges[c + j] != w.edge) {
        if (at0 + at1 + at2 == 1 && node_edges[c + kSlotBefore[j]] == w.edge) {
          throw MeshError("inconsistent orientation at vertex " + std::to_string(v));
        }
        throw not_a_dual("edge " + std::to_string(w.edge) + " does not leave vertex " +
                         std::to_string(v) + " in triangle " + std::to_string(w.next));
      }
      if (c + j == w.first) {
        w = walks[--live];  // done: the last lane takes its place, and its step
        continue;
      }
      if (is_set(visited, c + j)) {
        throw not_a_dual("the triangles around vertex " + std::to_string(v) + " do not form fans");
      }
      set(visited, c + j);
      w.face = w.next;
      w.enter = c + kSlotBefore[j];
      __builtin_prefetch(edge_ends.data() + 2 * std::size_t{node_edges[w.enter]});
      ++i;
    }
  }
}

// The even and the odd vertices' walks on up to two threads, each setting bits of its own. Each
// parity's first error is kept and the even one's is reported first: the same error for any
// number of threads.
void check_fans(std::span<const VertexId> corners, std::span<const EdgeId> node_edges,
                std::span<const NodeId> edge_ends, std::uint32_t vertices, std::uint32_t threads) {
  const std::size_t words = (corners.size() + 63) / 64;
  // Made here, not on the walks' threads: a second thread's heap would keep its blocks resident
  // after the check.
  std::array<std::vector<std::uint64_t>, 2> visited = {std::vector<std::uint64_t>(words, 0),
                                                       std::vector<std::uint64_t>(words, 0)};
  std::array<std::vector<std::uint64_t>, 2> has_fan = {
      std::vector<std::uint64_t>((vertices + 63) / 64, 0),
      std::vector<std::uint64_t>((vertices + 63) / 64, 0)};
  std::array<std::exception_ptr, 2> errors;
  run_parallel(threads, 2, [&](std::uint32_t parity) {
    try {
      walk_fans(corners, node_edges, edge_ends, vertices, parity, visited[parity], has_fan[parity]);
    } catch (...) {
      errors[parity] = std::current_exception();
    }
  });
  for (const std::exception_ptr& error : errors) {
    if (error) std::rethrow_exception(error);
  }
  // A word at a time: the corners past the end count as reached.
  std::vector<std::uint64_t>& reached = visited[0];
  if (corners.size() % 64 != 0) reached.back() |= ~std::uint64_t{0} << (corners.size() % 64);
  for (std::size_t word = 0; word < words; ++word) {
    reached[word] |= visited[1][word];
    if (reached[word] != ~std::uint64_t{0}) {
      const std::size_t c = 64 * word + static_cast<std::size_t>(std::countr_one(reached[word]));
      throw MeshError("pinched vertex " + std::to_string(corners[c]) +
                      " (its triangles form more than one fan)");
    }
  }
}

// Edges by their smaller vertex (new ids), a stable counting sort: the edges around a vertex get
// neighbouring ids, as build_dual's (min, max) order gives them on the spatial copy. Each edge's
// key, then its new id, is written over its second end, which nothing reads after it is checked:
// a triangle is the edge's first or its second end (no array of new edge ids, 6 bytes per
// triangle at this pass's peak). The components are counted here too, once the arrays are known
// to be a dual (every end in range), unless the caller has counted them.
void renumber_edges(std::span<const VertexId> corners, std::span<const EdgeId> node_edges,
                    std::span<NodeId> edge_ends, std::span<const VertexId> new_id,
                    Triangulation::Connectivity connectivity) {
  const auto faces = static_cast<std::uint32_t>(corners.size() / 3);
  const auto edges = static_cast<std::uint32_t>(edge_ends.size() / 2);
  const auto vertices = static_cast<std::uint32_t>(new_id.size());
  std::optional<ComponentForest> forest;
  if (connectivity == Triangulation::Connectivity::unknown) {
    forest.emplace(faces, std::span<const NodeId>());
  }
  std::pmr::vector<std::uint32_t> start(std::size_t{vertices} + 1, 0);
  const auto names = [&](NodeId t, EdgeId e) {
    const std::size_t c = 3 * std::size_t{t};
    return node_edges[c] == e || node_edges[c + 1] == e || node_edges[c + 2] == e;
  };
  for (EdgeId e = 0; e < edges; ++e) {
    const NodeId t = edge_ends[2 * e], u = edge_ends[2 * e + 1];
    // The first end names the edge among its sides. check_fans has seen every side's edge end
    // at the side's triangle and be named by its other end too, so an edge named by three sides
    // or more would leave another edge named by none, whose first end fails here: every edge is
    // then named by its two ends once (u's sides are not read again: a random read per edge).
    if (t >= faces || u >= faces || u == t || !names(t, e)) {
      throw std::invalid_argument("lrs::Triangulation::from_dual: edge " + std::to_string(e) +
                                  " is not a side of its triangles");
    }
    if (forest) forest->join(edge_ends.subspan(2 * std::size_t{e}, 2));
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
  if (forest) {
    if (const std::uint32_t components = forest->root_count(); components > 1) {
      throw MeshError(std::to_string(components) + " components (triangles joined through edges)");
    }
    forest.reset();
  }
  for (VertexId v = 0; v < vertices; ++v) start[v + 1] += start[v];
  for (EdgeId e = 0; e < edges; ++e) edge_ends[2 * e + 1] = start[edge_ends[2 * e + 1]]++;
}

// Side k of triangle t becomes halfedge 2e' + s, written over its slot: s = 0 in the edge's first
// triangle, e' the new id renumber_edges left in the edge's second end.
void halfedges_over_slots(std::span<EdgeId> node_edges, std::span<const NodeId> edge_ends) {
  const auto faces = static_cast<FaceId>(node_edges.size() / 3);
  for (FaceId t = 0; t < faces; ++t) {
    for (std::size_t k = 0; k < 3; ++k) {
      EdgeId& slot = node_edges[3 * std::size_t{t} + k];
      slot = 2 * edge_ends[2 * slot + 1] + (edge_ends[2 * slot] == t ? 0u : 1u);
    }
  }
}

}  // namespace

Triangulation Triangulation::from_dual(
    const Positions& positions, std::span<const VertexId> corners,
    std::pmr::vector<EdgeId> node_edges, std::pmr::vector<NodeId> edge_ends,
    Connectivity connectivity, const std::function<void()>& corners_read, std::uint32_t threads) {
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
  check_fans(corners, node_edges, edge_ends, vertices, threads);
  Triangulation tri;
  tri.input_vertex_ = spatial_vertex_order(positions, faces);
  {
    std::pmr::vector<VertexId> new_id(vertices);
    for (VertexId v = 0; v < vertices; ++v) new_id[tri.input_vertex_[v]] = v;
    renumber_edges(corners, node_edges, edge_ends, new_id, connectivity);
  }
  halfedges_over_slots(node_edges, edge_ends);
  free_storage(edge_ends);
  tri.link_halfedges(corners, std::move(node_edges), corners_read);
  tri.count_from_links(edges, faces);
  return tri;
}

void Triangulation::link_halfedges(std::span<const VertexId> corners,
                                   std::pmr::vector<Halfedge> halfedge_of_corner,
                                   const std::function<void()>& corners_read) {
  // The links with the input's vertex ids, and each input vertex's halfedge in the last triangle
  // that has it (so that the contraction walks from the same halfedge as on from_mesh's input
  // order). Made in three steps so that the slots, the input's corners and all of the links are
  // never alive at once (at most 52 bytes per triangle with the positions, against 62 in one
  // pass): each halfedge's origin into the links' first half (halfedge h's word is field h & 1 of
  // link h / 2; the second half's pages are not touched yet), after which the corners are done
  // with; each halfedge's next into an array of its own, after which the slots are; then the
  // pairs spread out in place from the back (link h is written after link h / 2 < h is read). The
  // vertex order (2 bytes per triangle) is held through these passes, below the augmentation's
  // peak, rather than made again from the positions.
  const auto faces = static_cast<FaceId>(corners.size() / 3);
  const auto vertices = static_cast<std::uint32_t>(input_vertex_.size());
  const std::size_t halfedges = corners.size();
  links_ = Links(halfedges);
  const auto half_word = [this](std::size_t h) -> std::uint32_t& {
    Link& link = links_[h / 2];
    return h % 2 == 0 ? link.origin : link.next;
  };
  std::pmr::vector<Halfedge> last_out(vertices, kNoHalfedge);
  for (std::size_t c = 0; c < corners.size(); ++c) {
    const VertexId v = corners[c];
    half_word(halfedge_of_corner[c]) = v;
    last_out[v] = halfedge_of_corner[c];
  }
  if (corners_read) corners_read();
  {
    const RawArray<Halfedge> next = make_raw_array<Halfedge>(halfedges);
    for (FaceId t = 0; t < faces; ++t) {
      const Halfedge* h = halfedge_of_corner.data() + 3 * std::size_t{t};
      for (std::size_t k = 0; k < 3; ++k) next[h[k]] = h[(k + 1) % 3];
    }
    free_storage(halfedge_of_corner);  // `= {}` would keep the buffer
    for (std::size_t h = halfedges; h-- > 0;) links_[h] = {half_word(h), next[h]};
  }
  out_.resize(vertices);
  for (VertexId v = 0; v < vertices; ++v) out_[v] = last_out[input_vertex_[v]];
}

void Triangulation::count_from_links(std::uint32_t edges, std::uint32_t faces) {
  const auto vertices = static_cast<std::uint32_t>(input_vertex_.size());
  std::pmr::vector<VertexId> new_id(vertices);
  for (VertexId v = 0; v < vertices; ++v) new_id[input_vertex_[v]] = v;
  degree_.assign(vertices, 0);
  for (std::size_t h = 0; h < links_.size(); ++h) {
    Link& link = links_[h];
    link.origin = new_id[link.origin];
    ++degree_[link.origin];
  }
  edge_alive_.assign(edges, 1);
  face_capacity_ = faces;
  live_edges_ = edges;
  live_faces_ = faces;
  // Each vertex with a corner is alive (check_fans has walked its one fan).
  for (VertexId v = 0; v < vertices; ++v) live_vertices_ += out_[v] != kNoHalfedge;
}

}  // namespace petersen::lrs
