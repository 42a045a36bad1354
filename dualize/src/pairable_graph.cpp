#include "petersen/dualize/pairable_graph.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "petersen/graph/parallel.hpp"
#include "petersen/mesh/edge_groups.hpp"

namespace petersen {

namespace {

constexpr std::string_view kCauseNames[kCutCauses] = {
    "boundary", "non_manifold", "polygon",   "degenerate",    "duplicate",
    "user",     "sharp",        "uv_seam",   "normal_seam",   "material",
    "group",    "object",       "smoothing", "face_property", "shape"};

}  // namespace

std::string_view to_string(CutCause cause) {
  return kCauseNames[static_cast<int>(cause)];
}

std::optional<CutCause> parse_cut_cause(std::string_view name) {
  for (int c = 0; c < kCutCauses; ++c)
    if (kCauseNames[c] == name) return CutCause(c);
  return std::nullopt;
}

namespace {

// Corners in range, three or more per face, ids that fit: checked once at the door.
void check_faces(const PolygonMesh& mesh) {
  const std::size_t faces = mesh.face_count();
  // Halfedges (one per corner) and nodes are 32-bit; 3 per triangle and 3/2 edges per triangle.
  if (mesh.corners.size() > 0xFFFFFFF0u) {
    throw MeshError("mesh has " + std::to_string(mesh.corners.size()) +
                    " face corners; at most 4294967280 are supported");
  }
  const std::size_t vertex_count = mesh.positions.size();
  // Vertex ids below 2^32 - 1, so that the grouping can mark entries with 0xFFFFFFFF.
  if (vertex_count > 0xFFFFFFFFu) {
    throw MeshError("mesh has " + std::to_string(vertex_count) +
                    " vertices; at most 4294967295 are supported");
  }
  if (mesh.all_triangles()) {
    // One branch-free sweep over the corners; the face is looked for only when one is bad.
    bool bad = false;
    for (VertexId v : mesh.corners) bad |= v >= vertex_count;
    if (!bad) return;
  }
  for (std::size_t f = 0; f < faces; ++f) {
    const auto corners = mesh.face(static_cast<FaceId>(f));
    if (corners.size() < 3) {
      throw MeshError("face " + std::to_string(f) + " has " + std::to_string(corners.size()) +
                      " corners; a face needs at least 3");
    }
    for (VertexId v : corners) {
      if (v >= vertex_count) {
        throw MeshError("face " + std::to_string(f) + " has corner " + std::to_string(v) +
                        " out of range (" + std::to_string(vertex_count) + " vertices)");
      }
    }
  }
}

bool repeats_a_vertex(std::span<const VertexId> corners) {
  for (std::size_t i = 0; i < corners.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (corners[i] == corners[j]) return true;
  return false;
}

void check_sizes(const PolygonMesh& mesh, const CutOptions& cuts) {
  auto check = [](std::span<const std::uint32_t> ids, std::size_t expected, const char* name) {
    if (!ids.empty() && ids.size() != expected) {
      throw MeshError(std::string(name) + " has " + std::to_string(ids.size()) + " entries for " +
                      std::to_string(expected));
    }
  };
  check(cuts.corner_uv, mesh.corners.size(), "texture coordinate ids per corner");
  check(cuts.corner_normal, mesh.corners.size(), "normal ids per corner");
  check(cuts.face_material, mesh.face_count(), "materials per face");
  check(cuts.face_group, mesh.face_count(), "groups per face");
  check(cuts.face_object, mesh.face_count(), "objects per face");
  check(cuts.face_smoothing, mesh.face_count(), "smoothing groups per face");
  check(cuts.face_property, mesh.face_count(), "face properties per face");
  if (!cuts.face_flat.empty() && cuts.face_flat.size() != mesh.face_count()) {
    throw MeshError("flat-shading flags per face has " + std::to_string(cuts.face_flat.size()) +
                    " entries for " + std::to_string(mesh.face_count()));
  }
  for (const auto& [a, b] : cuts.user_edges) {
    if (a >= mesh.positions.size() || b >= mesh.positions.size()) {
      throw MeshError("cut edge (" + std::to_string(a) + ", " + std::to_string(b) +
                      ") names a vertex out of range (" + std::to_string(mesh.positions.size()) +
                      " vertices)");
    }
  }
}

std::array<double, 3> normal_of(const PolygonMesh& mesh, std::span<const VertexId> t) {
  const auto& p = mesh.positions;
  std::array<double, 3> u, v;
  for (int d = 0; d < 3; ++d) {
    u[d] = p[t[1]][d] - p[t[0]][d];
    v[d] = p[t[2]][d] - p[t[0]][d];
  }
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

// The user's cut edges as sorted keys (min << 32 | max), for a binary search per edge.
std::vector<std::uint64_t> sorted_user_edges(const CutOptions& cuts) {
  std::vector<std::uint64_t> keys;
  for (const auto& [a, b] : cuts.user_edges) {
    keys.push_back(std::uint64_t{std::min(a, b)} << 32 | std::max(a, b));
  }
  std::sort(keys.begin(), keys.end());
  return keys;
}

// Whether any attribute array can cut an edge: tested once, not per edge.
bool has_attribute_cuts(const CutOptions& cuts) {
  return !cuts.corner_uv.empty() || !cuts.corner_normal.empty() || !cuts.face_material.empty() ||
         !cuts.face_group.empty() || !cuts.face_object.empty() || !cuts.face_smoothing.empty() ||
         !cuts.face_property.empty();
}

// A pairable edge's first entry has its larger vertex, which nothing reads once the edge is
// classified, overwritten by kPairable (no vertex id: ids are below the vertex count): no flag
// array per slice to clear and fill (520 KB per slice on armadillo-sub2, fresh pages at first).
constexpr std::uint32_t kPairable = 0xFFFFFFFFu;

// What one slice of the vertices found: its groups of halfedges (pairable edges marked), its
// counts and its chosen cuts.
struct Slice {
  EdgeGroups groups;
  std::vector<NodeId> chosen_cut_ends;
  CutCounts cuts;
  std::uint64_t mesh_edges = 0, inconsistent_edges = 0, inconsistent_chosen_cuts = 0;
  std::uint32_t edges = 0;

  // Empties the slice for the next wave, its lists keeping their memory; the groups go back to
  // the pool first, for the next ones to reuse: assigned over, they would be freed only after the
  // new ones were built, two waves' scratch at once (8 bytes per triangle of the run's peak on
  // armadillo-sub2).
  void reset() {
    cuts = {};
    mesh_edges = inconsistent_edges = inconsistent_chosen_cuts = 0;
    chosen_cut_ends.clear();
    edges = 0;
    groups = {};
  }
  void cut(CutCause cause) { ++cuts.by_cause[static_cast<int>(cause)]; }
  // A cut where the surface joins the two nodes: a choice, kept as one.
  void choose_cut(CutCause cause, NodeId v, NodeId w, bool same_way) {
    chosen_cut_ends.push_back(v);
    chosen_cut_ends.push_back(w);
    inconsistent_chosen_cuts += same_way;
    cut(cause);
  }
};

// An edge of exactly two halfedges: h1 in face f1, h2 in face f2.
struct TwoSides {
  std::uint32_t h1, h2;
  FaceId f1, f2;
};

// The mesh's triangles as nodes, and the classification of its edges: each a cut, by cause, or a
// pairable edge of the graph.
class PairableGraphBuilder {
 public:
  // Numbers the triangles of `mesh` as the nodes of `graph`, in face order, and makes room for its
  // edges.
  PairableGraphBuilder(const PolygonMesh& mesh, const CutOptions& cuts, PairableGraph& graph)
      : mesh_(mesh),
        cuts_(cuts),
        user_edges_(sorted_user_edges(cuts)),
        attribute_cuts_(has_attribute_cuts(cuts)),
        triangles_only_(mesh.all_triangles()),
        half_(mesh) {
    if (!triangles_only_) mark_degenerate_polygons();
    number_nodes(graph);
    graph.node_edges.assign(3 * std::size_t{graph.node_count}, kNoEdge);
    graph.edge_ends.reserve(triangles_only_ ? mesh.corners.size() : 0);
  }

  const PolygonHalfedges& halfedges() const { return half_; }

  // Decides each edge of the slice's groups: a cut (counted by cause) or pairable (marked).
  void classify(Slice& slice) const {
    for_each_edge_group(slice.groups, [&](std::uint32_t first, std::uint32_t end) {
      classify_edge(slice, first, end);
    });
  }

  // Numbers the slice's pairable edges from `first_edge` on, in entry order, into `graph`.
  void number(const Slice& slice, EdgeId first_edge, PairableGraph& graph) const {
    const auto& entries = slice.groups.entries;
    const std::uint32_t entry_count = static_cast<std::uint32_t>(entries.size());
    EdgeId* const node_edges = graph.node_edges.data();
    NodeId* const edge_ends = graph.edge_ends.data();
    EdgeId e = first_edge;
    for (std::uint32_t i = 0; i < entry_count; ++i) {
      // The two slots are random writes (an edge's triangles are anywhere in the face order);
      // their lines are fetched for writing a few entries ahead, as the store buffer otherwise
      // fills with misses. Only a pairable edge's first entry is a triangle's halfedge for sure:
      // another may be a polygon's, which has no slot (its address would lie outside node_edges,
      // undefined even unread).
      if (constexpr std::uint32_t kAhead = 16;
          i + kAhead < entry_count && entries[i + kAhead][0] == kPairable) {
        __builtin_prefetch(node_edges + slot(entries[i + kAhead][1]), 1);
        __builtin_prefetch(node_edges + slot(entries[i + kAhead + 1][1]), 1);
      }
      if (entries[i][0] != kPairable) continue;
      const std::uint32_t h1 = entries[i][1], h2 = entries[i + 1][1];
      node_edges[slot(h1)] = e;
      node_edges[slot(h2)] = e;
      edge_ends[2 * std::size_t{e}] = node_of(half_.face(h1));
      edge_ends[2 * std::size_t{e} + 1] = node_of(half_.face(h2));
      ++e;
    }
  }

 private:
  // Per face only for polygons, where the test is quadratic in the arity; a triangle's is three
  // comparisons on corners the edge visit reads anyway (degenerate).
  void mark_degenerate_polygons() {
    const auto face_count = static_cast<FaceId>(mesh_.face_count());
    degenerate_face_.resize(face_count);
    for (FaceId f = 0; f < face_count; ++f) degenerate_face_[f] = repeats_a_vertex(mesh_.face(f));
  }

  // Triangles become nodes in face order.
  void number_nodes(PairableGraph& graph) {
    const auto face_count = static_cast<FaceId>(mesh_.face_count());
    if (triangles_only_) {
      graph.node_count = face_count;
      return;
    }
    face_node_.assign(face_count, kNoNode);
    for (FaceId f = 0; f < face_count; ++f) {
      if (mesh_.arity(f) != 3) continue;
      face_node_[f] = graph.node_count++;
      graph.node_face.push_back(f);
    }
  }

  NodeId node_of(FaceId f) const { return triangles_only_ ? f : face_node_[f]; }

  // Halfedge h's slot in node_edges: side h - first(f) of its face f's node.
  std::size_t slot(std::uint32_t h) const {
    const FaceId f = half_.face(h);
    return 3 * std::size_t{node_of(f)} + (h - half_.first(f));
  }

  bool degenerate(FaceId f) const {
    if (!triangles_only_) return bool(degenerate_face_[f]);
    // Three comparisons, not repeats_a_vertex's loops over a span of unknown size: those would be
    // a sixth of the graph's instructions on a large triangle mesh.
    const VertexId* c = mesh_.corners.data() + 3 * std::size_t{f};
    return c[0] == c[1] || c[1] == c[2] || c[2] == c[0];
  }

  // One edge: the entries first..end of its group.
  void classify_edge(Slice& slice, std::uint32_t first, std::uint32_t end) const {
    auto& entries = slice.groups.entries;
    // The visit reads the corners of both faces of an edge: random accesses that the loop's
    // branches keep from overlapping, so they are fetched ahead, two entries per edge.
    constexpr std::uint32_t kAhead = 16;
    const std::uint32_t entry_count = static_cast<std::uint32_t>(entries.size());
    for (std::uint32_t i = first + kAhead; i < first + kAhead + 2 && i < entry_count; ++i) {
      __builtin_prefetch(mesh_.corners.data() + entries[i][1]);
    }
    ++slice.mesh_edges;
    const std::uint32_t copies = end - first;
    if (copies == 1) return slice.cut(CutCause::boundary);
    if (copies > 2) return slice.cut(CutCause::non_manifold);
    const std::uint32_t h1 = entries[first][1], h2 = entries[first + 1][1];
    const TwoSides sides{h1, h2, half_.face(h1), half_.face(h2)};
    if (const auto cause = structural_cut(sides)) return slice.cut(*cause);
    const bool same_way = half_.from(h2) == half_.from(h1);
    if (const auto cause = chosen_cut(sides, same_way)) {
      return slice.choose_cut(*cause, node_of(sides.f1), node_of(sides.f2), same_way);
    }
    slice.inconsistent_edges += same_way;
    entries[first][0] = kPairable;  // its group is behind the visit: nothing compares it again
    ++slice.edges;
  }

  // Where the surface itself keeps the two faces from making a quad.
  std::optional<CutCause> structural_cut(const TwoSides& e) const {
    if (e.f1 == e.f2 || degenerate(e.f1) || degenerate(e.f2)) return CutCause::degenerate;
    if (mesh_.arity(e.f1) != 3 || mesh_.arity(e.f2) != 3) return CutCause::polygon;
    // The corner of each triangle opposite the shared edge: after its end.
    const std::uint32_t k1 = e.h1 - half_.first(e.f1), k2 = e.h2 - half_.first(e.f2);
    const VertexId opposite1 = mesh_.corners[half_.first(e.f1) + (k1 + 2) % 3];
    const VertexId opposite2 = mesh_.corners[half_.first(e.f2) + (k2 + 2) % 3];
    if (opposite1 == opposite2) return CutCause::duplicate;
    return std::nullopt;
  }

  // The cuts of the caller and of the data, in the order of CutCause.
  std::optional<CutCause> chosen_cut(const TwoSides& e, bool same_way) const {
    if (!user_edges_.empty()) {
      const VertexId a = half_.from(e.h1), b = half_.to(e.h1);
      if (std::binary_search(user_edges_.begin(), user_edges_.end(),
                             std::uint64_t{std::min(a, b)} << 32 | std::max(a, b))) {
        return CutCause::user;
      }
    }
    if (cuts_.sharp_angle_degrees && folds_sharply(e, same_way)) return CutCause::sharp;
    if (attribute_cuts_) return attribute_cut(e, same_way);
    return std::nullopt;
  }

  bool folds_sharply(const TwoSides& e, bool same_way) const {
    const auto n1 = normal_of(mesh_, mesh_.face(e.f1));
    auto n2 = normal_of(mesh_, mesh_.face(e.f2));
    if (same_way)
      for (double& x : n2) x = -x;  // orient f2 as f1
    const double dot = n1[0] * n2[0] + n1[1] * n2[1] + n1[2] * n2[2];
    const double norms = std::sqrt((n1[0] * n1[0] + n1[1] * n1[1] + n1[2] * n1[2]) *
                                   (n2[0] * n2[0] + n2[1] * n2[1] + n2[2] * n2[2]));
    // A zero-area triangle has no normal: its fold is unknown, so the edge is cut.
    if (!(norms > 0)) return true;
    // The fold in degrees, compared as the option says ("more than DEG"): comparing cosines would
    // cut a cube's exact 90-degree edges at DEG = 90, since cos(90°) is 6e-17, not 0.
    const double fold = std::acos(std::clamp(dot / norms, -1.0, 1.0)) * 180.0 / std::numbers::pi;
    return fold > *cuts_.sharp_angle_degrees + kFoldToleranceDegrees;
  }

  // A seam (the two triangles give an end of the edge different ids) or a border (the faces
  // have different ids), first in the order of CutCause.
  std::optional<CutCause> attribute_cut(const TwoSides& e, bool same_way) const {
    // The corners of a and b in each face: h1 is a's corner in f1; in f2, a's corner is h2 when
    // f2 runs along the edge the same way, else the next one.
    const std::uint32_t a2 = same_way ? e.h2 : half_.next(e.h2);
    const std::uint32_t b2 = same_way ? half_.next(e.h2) : e.h2;
    auto seam = [&](std::span<const std::uint32_t> id) {
      return !id.empty() && (id[e.h1] != id[a2] || id[half_.next(e.h1)] != id[b2]);
    };
    if (seam(cuts_.corner_uv)) return CutCause::uv_seam;
    const bool both_flat =
        !cuts_.face_flat.empty() && cuts_.face_flat[e.f1] && cuts_.face_flat[e.f2];
    if (!both_flat && seam(cuts_.corner_normal)) return CutCause::normal_seam;
    auto border = [&](std::span<const std::uint32_t> id) {
      return !id.empty() && id[e.f1] != id[e.f2];
    };
    if (border(cuts_.face_material)) return CutCause::material;
    if (border(cuts_.face_group)) return CutCause::group;
    if (border(cuts_.face_object)) return CutCause::object;
    if (border(cuts_.face_smoothing)) return CutCause::smoothing;
    if (border(cuts_.face_property)) return CutCause::face_property;
    return std::nullopt;
  }

  const PolygonMesh& mesh_;
  const CutOptions& cuts_;
  const std::vector<std::uint64_t> user_edges_;
  const bool attribute_cuts_;
  const bool triangles_only_;
  const PolygonHalfedges half_;
  std::vector<std::uint8_t> degenerate_face_;  // per polygon face; empty for a triangle mesh
  std::pmr::vector<NodeId> face_node_;         // per face; empty for a triangle mesh
};

// The vertices cut into slices of about kSliceEntries halfedges, at least one per thread: each
// slice groups only its own halfedges, so the grouping's scratch is a slice's, not the whole
// mesh's. slice_start[k] is slice k's first vertex; the last entry is the vertex count.
std::vector<std::size_t> slice_starts(std::span<const std::uint32_t> starts,
                                      std::size_t vertex_count, std::uint32_t threads) {
  constexpr std::uint64_t kSliceEntries = std::uint64_t{1} << 25;
  std::uint64_t slices =
      std::max<std::uint64_t>(threads, (starts.back() + kSliceEntries - 1) / kSliceEntries);
  // A large mesh gets four slices per thread, so that a wave's scratch (8 bytes per entry) is a
  // quarter of the whole mesh's: the grouping is the front door's peak, beside the mesh and the
  // graph. Each slice reads every halfedge once more; two slices per thread would read them half
  // as often but double the scratch, with no wall time to gain.
  constexpr std::uint64_t kLargeEntries = std::uint64_t{1} << 20;
  if (starts.back() >= kLargeEntries) {
    slices = std::max<std::uint64_t>(slices, std::uint64_t{4} * threads);
  }
  std::vector<std::size_t> slice_start(slices + 1, vertex_count);
  slice_start[0] = 0;
  for (std::uint64_t k = 1; k < slices; ++k) {
    // The first vertex whose bucket starts at or past the k-th share of the entries.
    const std::uint64_t target = starts.back() * k / slices;
    slice_start[k] =
        std::size_t(std::lower_bound(starts.begin(), starts.end() - 1, target) - starts.begin());
  }
  return slice_start;
}

// Adds the counts and chosen cuts of a wave's slices to `graph`, in slice order, and makes room
// for their edges. Returns each slice's first edge.
std::vector<EdgeId> add_wave(PairableGraph& graph, std::span<const Slice> slices) {
  std::vector<EdgeId> first_edge(slices.size());
  for (std::size_t i = 0; i < slices.size(); ++i) {
    const Slice& slice = slices[i];
    first_edge[i] = graph.edge_count();
    graph.edge_ends.resize(graph.edge_ends.size() + 2 * std::size_t{slice.edges});
    graph.mesh_edges += slice.mesh_edges;
    graph.inconsistent_edges += slice.inconsistent_edges;
    graph.inconsistent_chosen_cuts += slice.inconsistent_chosen_cuts;
    graph.chosen_cut_ends.insert(graph.chosen_cut_ends.end(), slice.chosen_cut_ends.begin(),
                                 slice.chosen_cut_ends.end());
    for (int c = 0; c < kCutCauses; ++c) graph.cuts.by_cause[c] += slice.cuts.by_cause[c];
  }
  return first_edge;
}

}  // namespace

PairableGraph build_pairable_graph(const PolygonMesh& mesh, const CutOptions& cuts,
                                   std::uint32_t threads_wanted,
                                   std::pmr::memory_resource* memory) {
  check_faces(mesh);
  check_sizes(mesh, cuts);
  PairableGraph graph{.node_face = std::pmr::vector<FaceId>(memory),
                      .node_edges = std::pmr::vector<EdgeId>(memory),
                      .edge_ends = std::pmr::vector<NodeId>(memory),
                      .chosen_cut_ends = std::pmr::vector<NodeId>(memory)};
  const PairableGraphBuilder builder(mesh, cuts, graph);
  const auto halfedges = [&](auto visit) { builder.halfedges().for_each(visit); };
  const std::pmr::vector<std::uint32_t> starts = bucket_starts(mesh.positions.size(), halfedges);
  const std::uint32_t threads = resolve_threads(threads_wanted);
  const std::vector<std::size_t> slice_start = slice_starts(starts, mesh.positions.size(), threads);
  const std::uint64_t slices = slice_start.size() - 1;
  // A wave of slices, one per thread, is grouped and classified in parallel, then numbered in
  // order, so that edges keep the order of their mesh edge (min, max). The slices are kept from
  // wave to wave, so that their lists reuse the previous wave's memory.
  std::vector<Slice> wave_slices(std::min<std::uint64_t>(threads, slices));
  for (std::uint64_t wave = 0; wave < slices; wave += threads) {
    const std::uint32_t count =
        static_cast<std::uint32_t>(std::min<std::uint64_t>(threads, slices - wave));
    run_parallel(threads, count, [&](std::uint32_t i) {
      Slice& slice = wave_slices[i];
      slice.reset();
      slice.groups =
          group_halfedges_in(starts, slice_start[wave + i], slice_start[wave + i + 1], halfedges);
      builder.classify(slice);
    });
    const std::vector<EdgeId> first_edge = add_wave(graph, {wave_slices.data(), count});
    run_parallel(threads, count,
                 [&](std::uint32_t i) { builder.number(wave_slices[i], first_edge[i], graph); });
  }
  graph.cubic = 2 * std::size_t{graph.edge_count()} == graph.node_edges.size();
  return graph;
}

}  // namespace petersen
