#pragma once
// A mutable triangulation of a closed orientable surface in flat halfedge arrays: the structure
// the contraction and expansion steps of LRS (paper §3.3) work on.

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "petersen/graph/cubic_graph.hpp"
#include "petersen/graph/memory.hpp"
#include "petersen/mesh/mesh.hpp"

namespace petersen::lrs {

/// Halfedge ids: edge e is halfedges 2e and 2e+1, so the twin of h is h ^ 1. Ids of vertices,
/// edges and halfedges never change; contraction kills elements and a vertex split revives exactly
/// those, an edge flip keeps every id. Faces are the next cycles and have no stored id: to_mesh
/// and into_dual_rows number them in order of their smallest halfedge.
using Halfedge = std::uint32_t;
inline constexpr Halfedge kNoHalfedge = 0xFFFFFFFFu;

class Triangulation;
struct DualRows;
struct ExpansionResult;
struct ContractionRecord;
ContractionRecord contract(Triangulation& tri, Halfedge h);
void split(Triangulation& tri, const ContractionRecord& record);
void flip(Triangulation& tri, Halfedge h);
DualRows into_dual_rows(Triangulation&& tri, ExpansionResult&& expansion);

/// A simplicial triangulation of a closed, connected, orientable surface. Each halfedge stores its
/// origin and the next halfedge of its face (counter-clockwise); each vertex one outgoing halfedge
/// and its degree. No per-halfedge face id (12 bytes per face at lrs's peak, the end of the
/// expansion): nothing in contraction or expansion reads one. Dead elements
/// (removed by contract) keep their last values, which is what split reads to revive them.
class Triangulation {
 public:
  Triangulation() = default;

  /// What from_dual knows of the triangles' components.
  enum class Connectivity {
    unknown,  ///< counted there (a disjoint-set pass over the edges), several refused
    /// the caller has found them connected (quadrangulate counts the pairable graph's components
    /// to choose lrs's path): the same pass is not made twice
    connected,
  };

  /// How from_mesh numbers the elements.
  enum class Numbering {
    as_given,  ///< vertex ids are the mesh's
    /// vertices and triangles along a space-filling curve, for the cache (src/spatial_order.hpp);
    /// input_vertex() and to_mesh give the mesh's vertex ids back
    spatial,
  };

  /// Builds the triangulation of `mesh` (every face a triangle), edges numbered as the pairable
  /// graph's of the mesh as numbered, by (min, max) vertex, side 0 in the triangle with the smaller
  /// corner slot. Throws MeshError naming the element (by the input's ids) if the mesh is not a
  /// closed, connected, orientable manifold surface of triangles (pinched vertices and several
  /// components are refused). Unreferenced vertices are dead from the start. O(F log d).
  static Triangulation from_mesh(const PolygonMesh& mesh,
                                 Numbering numbering = Numbering::as_given);

  /// Builds the triangulation of a closed, connected, consistently oriented triangle mesh from its
  /// dual, taking the dual's arrays over instead of grouping the mesh's halfedges again: triangle t
  /// has corners corners[3t], corners[3t + 1], corners[3t + 2] over `positions`;
  /// node_edges[3t + k] is the edge across its corners k and k + 1, and edge e joins triangles
  /// edge_ends[2e] and edge_ends[2e + 1] (a PairableGraph with `cubic` set and no inconsistent
  /// edge, or build_dual's graph). Numbered spatially: vertices by Morton cell, edges by their
  /// smaller vertex; input_vertex() gives the mesh's
  /// ids back. Throws MeshError naming the input vertex when a vertex is pinched (its triangles
  /// form several fans) or orientation is inconsistent around it, and when the triangles form
  /// several components (unless `connectivity` says the caller has counted one);
  /// std::invalid_argument when the arrays are not a dual of the triangles, all of it before
  /// `corners_read` is called. `corners_read`, when given, is called as soon as `corners` is read
  /// no more (before the links are complete), so that a caller done with them frees them there:
  /// once it is called, from_dual refuses nothing. The fans are checked on up to `threads`
  /// threads (two at most; 0: as many as the machine has). Each array is freed once the next is
  /// made: beside the caller's positions, at most the corners, the slots (12 bytes per triangle),
  /// half the links (12) and one vertex array (2) at a time, then the slots, all the links (24) and
  /// their nexts (12) without the corners if the caller has freed them, where from_mesh holds two
  /// copies of the mesh, its own dual and the surface check's scratch. O(V + F).
  static Triangulation from_dual(const Positions& positions, std::span<const VertexId> corners,
                                 std::pmr::vector<EdgeId> node_edges,
                                 std::pmr::vector<NodeId> edge_ends,
                                 Connectivity connectivity = Connectivity::unknown,
                                 const std::function<void()>& corners_read = {},
                                 std::uint32_t threads = 1);

  /// The input mesh's id of vertex v.
  VertexId input_vertex(VertexId v) const { return input_vertex_.empty() ? v : input_vertex_[v]; }

  std::uint32_t vertex_capacity() const { return static_cast<std::uint32_t>(out_.size()); }
  std::uint32_t edge_capacity() const { return static_cast<std::uint32_t>(edge_alive_.size()); }
  std::uint32_t face_capacity() const { return face_capacity_; }
  std::uint32_t live_vertices() const { return live_vertices_; }
  std::uint32_t live_edges() const { return live_edges_; }
  std::uint32_t live_faces() const { return live_faces_; }

  bool vertex_alive(VertexId v) const { return out_[v] != kNoHalfedge; }
  bool edge_alive(EdgeId e) const { return edge_alive_[e] != 0; }

  static EdgeId edge(Halfedge h) { return h >> 1; }
  static Halfedge twin(Halfedge h) { return h ^ 1u; }
  VertexId origin(Halfedge h) const { return links_[h].origin; }
  VertexId destination(Halfedge h) const { return links_[h ^ 1u].origin; }
  Halfedge next(Halfedge h) const { return links_[h].next; }
  Halfedge prev(Halfedge h) const { return next(next(h)); }
  /// Whether h is the smallest halfedge of its face: the face's name in the numberings below.
  bool smallest_of_face(Halfedge h) const {
    const Halfedge n = next(h);
    return h < n && h < next(n);
  }
  /// The vertex of h's face opposite h.
  VertexId apex(Halfedge h) const { return origin(prev(h)); }
  /// The next outgoing halfedge around origin(h), counter-clockwise.
  Halfedge rotate(Halfedge h) const { return twin(prev(h)); }
  /// The next outgoing halfedge around origin(h), clockwise: the inverse of rotate, and one load
  /// (twins share a cache line), so walks where the order does not matter go this way.
  Halfedge rotate_cw(Halfedge h) const { return links_[h ^ 1u].next; }
  Halfedge out(VertexId v) const { return out_[v]; }
  /// Cache hints for a halfedge's record (its link) and a vertex's (out and degree): the
  /// records are scattered over tens of megabytes, so a caller that knows its future accesses
  /// (the expansion reads them from the contraction stack) asks for them ahead.
  void prefetch(Halfedge h) const { __builtin_prefetch(&links_[h]); }
  void prefetch_vertex(VertexId v) const {
    __builtin_prefetch(&out_[v]);
    __builtin_prefetch(&degree_[v]);
  }
  std::uint32_t degree(VertexId v) const { return degree_[v]; }

  /// Euler genus of the live part: (2 - V + E - F) / 2.
  std::uint32_t genus() const {
    return static_cast<std::uint32_t>(
        (2 - std::int64_t{live_vertices_} + live_edges_ - std::int64_t{live_faces_}) / 2);
  }

  /// The live faces as a mesh of triangles over `positions` (the input's), in order of their
  /// smallest halfedge, with the input's vertex ids; each triangle starts at the smallest halfedge
  /// id of its face, so edge k of the triangle is that halfedge's k-th successor. Dead vertices
  /// stay in `positions`, unreferenced. O(V + F).
  PolygonMesh to_mesh(const Positions& positions) const;

  /// Checks the structure: next cycles of length 3, origins consistent with
  /// twins, out[] outgoing, degrees equal to rotation lengths, live counts, no vertex pair joined
  /// twice (simplicial). Returns the first problem or an empty string. O(V + E) with marks.
  std::string check() const;

 private:
  friend ContractionRecord contract(Triangulation&, Halfedge);
  friend void split(Triangulation&, const ContractionRecord&);
  friend void flip(Triangulation&, Halfedge);
  friend DualRows into_dual_rows(Triangulation&&, ExpansionResult&&);

  // from_dual's last two steps: the links from each corner's halfedge (the slots, taken over) with
  // `out`, then the vertices renumbered in the links with their degrees, and the live counts.
  void link_halfedges(std::span<const VertexId> corners,
                      std::pmr::vector<Halfedge> halfedge_of_corner,
                      const std::function<void()>& corners_read);
  void count_from_links(std::uint32_t edges, std::uint32_t faces);
  // from_mesh after the surface check.
  static Triangulation build(const PolygonMesh& mesh);

  // Per halfedge, origin and next side by side: a twin pair fills 16 bytes of one cache line.
  struct Link {
    VertexId origin;
    Halfedge next;
  };
  // The links in an uninitialised array (copied whole with the triangulation): from_dual fills it
  // a half at a time, and into_dual_rows gives its second half back early, so that neither phase
  // holds all of it beside its other arrays.
  class Links {
   public:
    Links() = default;
    explicit Links(std::size_t size) : data_(make_raw_array<Link>(size)), size_(size) {}
    Links(const Links& other) : Links(other.size_) {
      std::copy_n(other.data_.get(), size_, data_.get());
    }
    Links(Links&& other) noexcept
        : data_(std::move(other.data_)), size_(std::exchange(other.size_, 0)) {}
    Links& operator=(Links other) noexcept {
      std::swap(data_, other.data_);
      std::swap(size_, other.size_);
      return *this;
    }
    Link& operator[](std::size_t h) { return data_[h]; }
    const Link& operator[](std::size_t h) const { return data_[h]; }
    std::size_t size() const { return size_; }
    /// Keeps the first `size` links (shrink_raw_array).
    void shrink(std::size_t size) {
      shrink_raw_array(data_, size);
      size_ = size;
    }

   private:
    RawArray<Link> data_;
    std::size_t size_ = 0;
  };
  Links links_;
  std::pmr::vector<std::uint8_t> edge_alive_;
  std::pmr::vector<Halfedge> out_;  // per vertex, kNoHalfedge when dead
  std::pmr::vector<std::uint32_t> degree_;
  std::pmr::vector<VertexId> input_vertex_;  // empty when the numbering is the input's
  std::uint32_t face_capacity_ = 0;
  std::uint32_t live_vertices_ = 0, live_edges_ = 0, live_faces_ = 0;
};

/// Per-vertex marks for O(degree) neighbourhood tests without hashing: clear() is O(1) (a new
/// stamp), except once every 2^32 clears.
class VertexMarks {
 public:
  explicit VertexMarks(std::uint32_t vertex_count) : stamp_(vertex_count, 0) {}
  void clear() {
    if (++current_ == 0) {
      std::fill(stamp_.begin(), stamp_.end(), 0);
      current_ = 1;
    }
  }
  void mark(VertexId v) { stamp_[v] = current_; }
  void unmark(VertexId v) { stamp_[v] = 0; }
  bool marked(VertexId v) const { return stamp_[v] == current_; }

 private:
  std::vector<std::uint32_t> stamp_;
  std::uint32_t current_ = 1;
};

}  // namespace petersen::lrs
