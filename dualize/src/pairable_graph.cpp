#include "petersen/dualize/pairable_graph.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "petersen/mesh/edge_groups.hpp"
#include "petersen/graph/parallel.hpp"

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

}  // namespace

PairableGraph build_pairable_graph(const PolygonMesh& mesh, const CutOptions& cuts,
                                   std::uint32_t threads_wanted) {
  check_faces(mesh);
  check_sizes(mesh, cuts);
  std::vector<std::uint64_t> user_edges;
  for (const auto& [a, b] : cuts.user_edges) {
    user_edges.push_back(std::uint64_t{std::min(a, b)} << 32 | std::max(a, b));
  }
  std::sort(user_edges.begin(), user_edges.end());
  const bool triangles_only = mesh.all_triangles();
  const std::uint32_t face_count = static_cast<std::uint32_t>(mesh.face_count());
  const std::uint32_t halfedge_count = static_cast<std::uint32_t>(mesh.corners.size());

  const PolygonHalfedges half(mesh);

  // Triangles become nodes in face order; a face repeating a vertex is degenerate.
  PairableGraph graph;
  HugeVector<NodeId> face_node;
  // Per face only for polygons, where the test is quadratic in the arity; a triangle's is three
  // comparisons on corners the edge visit reads anyway.
  std::vector<std::uint8_t> degenerate_face;
  if (!triangles_only) {
    degenerate_face.resize(face_count);
    for (FaceId f = 0; f < face_count; ++f) degenerate_face[f] = repeats_a_vertex(mesh.face(f));
  }
  auto degenerate = [&](FaceId f) {
    if (!triangles_only) return bool(degenerate_face[f]);
    // Three comparisons, not repeats_a_vertex's loops over a span of unknown size: those were a
    // sixth of the pairable graph's instructions on armadillo-sub2 (callgrind).
    const VertexId* c = mesh.corners.data() + 3 * std::size_t{f};
    return c[0] == c[1] || c[1] == c[2] || c[2] == c[0];
  };
  if (triangles_only) {
    graph.node_count = face_count;
  } else {
    face_node.assign(face_count, kNoNode);
    for (FaceId f = 0; f < face_count; ++f) {
      if (mesh.arity(f) != 3) continue;
      face_node[f] = graph.node_count++;
      graph.node_face.push_back(f);
    }
  }
  auto node_of = [&](FaceId f) { return triangles_only ? f : face_node[f]; };

  graph.node_edges.assign(3 * std::size_t{graph.node_count}, kNoEdge);
  HugeVector<NodeId>& ends = graph.edge_ends;
  ends.reserve(triangles_only ? halfedge_count : 0);

  // What one slice of the vertices found: its counts, and which of its groups are pairable edges.
  // A pairable edge's first entry has its larger vertex, which nothing reads once the edge is
  // classified, overwritten by kPairable (no vertex id: ids are below the vertex count): no flag
  // array per slice to clear and fill (520 KB per slice on armadillo-sub2, fresh pages at first).
  constexpr std::uint32_t kPairable = 0xFFFFFFFFu;
  struct Slice {
    EdgeGroups groups;
    std::vector<NodeId> chosen_cut_ends;
    CutCounts cuts;
    std::uint64_t mesh_edges = 0, inconsistent_edges = 0, inconsistent_chosen_cuts = 0;
    std::uint32_t edges = 0;
  };
  // Whether any attribute array can cut an edge: tested once, not per edge.
  const bool attribute_cuts = !cuts.corner_uv.empty() || !cuts.corner_normal.empty() ||
                              !cuts.face_material.empty() || !cuts.face_group.empty() ||
                              !cuts.face_object.empty() || !cuts.face_smoothing.empty() ||
                              !cuts.face_property.empty();
  // Decides each edge of the slice's groups: a cut (counted by cause) or pairable (marked).
  auto classify = [&](Slice& slice) {
    auto& entries = slice.groups.entries;
    auto cut = [&](CutCause cause) { ++slice.cuts.by_cause[static_cast<int>(cause)]; };
    // The visit reads the corners of both faces of an edge: random accesses that the loop's
    // branches keep from overlapping, so they are fetched ahead.
    constexpr std::uint32_t kAhead = 16;
    const std::uint32_t entry_count = static_cast<std::uint32_t>(entries.size());
    for_each_edge_group(slice.groups, [&](std::uint32_t first, std::uint32_t end) {
      // An edge has two entries, so two are fetched per visit.
      for (std::uint32_t i = first + kAhead; i < first + kAhead + 2 && i < entry_count; ++i) {
        __builtin_prefetch(mesh.corners.data() + entries[i][1]);
      }
      ++slice.mesh_edges;
      const std::uint32_t copies = end - first;
      const std::uint32_t h1 = entries[first][1];
      const std::uint32_t h2 = copies == 2 ? entries[first + 1][1] : 0;
      if (copies == 1) return cut(CutCause::boundary);
      if (copies > 2) return cut(CutCause::non_manifold);
      const FaceId f1 = half.face(h1), f2 = half.face(h2);
      if (f1 == f2 || degenerate(f1) || degenerate(f2)) return cut(CutCause::degenerate);
      if (mesh.arity(f1) != 3 || mesh.arity(f2) != 3) return cut(CutCause::polygon);
      // The corner of each triangle opposite the shared edge: after its end.
      const std::uint32_t k1 = h1 - half.first(f1), k2 = h2 - half.first(f2);
      const VertexId opposite1 = mesh.corners[half.first(f1) + (k1 + 2) % 3];
      const VertexId opposite2 = mesh.corners[half.first(f2) + (k2 + 2) % 3];
      if (opposite1 == opposite2) return cut(CutCause::duplicate);
      const VertexId a = half.from(h1), b = half.to(h1);
      const bool same_way = half.from(h2) == a;
      // Past this point the surface joins f1 and f2 here; a cut is a choice, kept as one.
      auto choose_cut = [&](CutCause cause) {
        slice.chosen_cut_ends.push_back(node_of(f1));
        slice.chosen_cut_ends.push_back(node_of(f2));
        slice.inconsistent_chosen_cuts += same_way;
        cut(cause);
      };
      if (!user_edges.empty() &&
          std::binary_search(user_edges.begin(), user_edges.end(),
                             std::uint64_t{std::min(a, b)} << 32 | std::max(a, b))) {
        return choose_cut(CutCause::user);
      }
      if (cuts.sharp_angle_degrees) {
        const auto n1 = normal_of(mesh, mesh.face(f1));
        auto n2 = normal_of(mesh, mesh.face(f2));
        if (same_way)
          for (double& x : n2) x = -x;  // orient f2 as f1
        const double dot = n1[0] * n2[0] + n1[1] * n2[1] + n1[2] * n2[2];
        const double norms = std::sqrt((n1[0] * n1[0] + n1[1] * n1[1] + n1[2] * n1[2]) *
                                       (n2[0] * n2[0] + n2[1] * n2[1] + n2[2] * n2[2]));
        // A zero-area triangle has no normal: its fold is unknown, so the edge is cut.
        if (!(norms > 0)) return choose_cut(CutCause::sharp);
        // The fold in degrees, compared as the option says ("more than DEG"): comparing cosines
        // instead cut a cube's exact 90-degree edges at DEG = 90, since cos(90°) is 6e-17, not 0.
        const double fold =
            std::acos(std::clamp(dot / norms, -1.0, 1.0)) * 180.0 / std::numbers::pi;
        if (fold > *cuts.sharp_angle_degrees) return choose_cut(CutCause::sharp);
      }
      // The corners of a and b in each face: h1 is a's corner in f1; in f2, a's corner is h2 when
      // f2 runs along the edge the same way, else the next one.
      const std::uint32_t a2 = same_way ? h2 : half.next(h2), b2 = same_way ? half.next(h2) : h2;
      if (attribute_cuts) {
        auto seam = [&](std::span<const std::uint32_t> id) {
          return !id.empty() && (id[h1] != id[a2] || id[half.next(h1)] != id[b2]);
        };
        if (seam(cuts.corner_uv)) return choose_cut(CutCause::uv_seam);
        if (seam(cuts.corner_normal)) return choose_cut(CutCause::normal_seam);
        auto border = [&](std::span<const std::uint32_t> id) {
          return !id.empty() && id[f1] != id[f2];
        };
        if (border(cuts.face_material)) return choose_cut(CutCause::material);
        if (border(cuts.face_group)) return choose_cut(CutCause::group);
        if (border(cuts.face_object)) return choose_cut(CutCause::object);
        if (border(cuts.face_smoothing)) return choose_cut(CutCause::smoothing);
        if (border(cuts.face_property)) return choose_cut(CutCause::face_property);
      }
      slice.inconsistent_edges += same_way;
      entries[first][0] = kPairable;  // its group is behind the visit: nothing compares it again
      ++slice.edges;
    });
  };
  // Halfedge h's slot in node_edges: side h - first(f) of its face f's node.
  auto slot = [&](std::uint32_t h) {
    const FaceId f = half.face(h);
    return 3 * std::size_t{node_of(f)} + (h - half.first(f));
  };
  // Numbers the slice's pairable edges from `first_edge` on, in entry order.
  auto number = [&](const Slice& slice, EdgeId first_edge) {
    const auto& entries = slice.groups.entries;
    const std::uint32_t entry_count = static_cast<std::uint32_t>(entries.size());
    EdgeId* const node_edges = graph.node_edges.data();
    NodeId* const edge_ends = ends.data();
    EdgeId e = first_edge;
    for (std::uint32_t i = 0; i < entry_count; ++i) {
      // The two slots are random writes (an edge's triangles are anywhere in the face order);
      // their lines are fetched for writing a few entries ahead, as the store buffer otherwise
      // fills with misses (armadillo-sub2: this loop was 6 % of the run's CPU samples). Only a
      // pairable edge's first entry is a triangle's halfedge for sure: another may be a polygon's,
      // which has no slot (its address would lie outside node_edges, undefined even unread).
      if (constexpr std::uint32_t kAhead = 16;
          i + kAhead < entry_count && entries[i + kAhead][0] == kPairable) {
        __builtin_prefetch(node_edges + slot(entries[i + kAhead][1]), 1);
        __builtin_prefetch(node_edges + slot(entries[i + kAhead + 1][1]), 1);
      }
      if (entries[i][0] != kPairable) continue;
      const std::uint32_t h1 = entries[i][1], h2 = entries[i + 1][1];
      node_edges[slot(h1)] = e;
      node_edges[slot(h2)] = e;
      edge_ends[2 * std::size_t{e}] = node_of(half.face(h1));
      edge_ends[2 * std::size_t{e} + 1] = node_of(half.face(h2));
      ++e;
    }
  };

  // The vertices in slices of about kSliceEntries halfedges (at least one per thread): each slice
  // groups only its own halfedges, so the grouping's scratch is a slice's, not the whole mesh's,
  // and slices are classified in parallel. A wave of slices, one per thread, is classified, then
  // numbered in order, so edges keep the order of their mesh edge (min, max).
  const auto halfedges = [&](auto visit) { half.for_each(visit); };
  const HugeVector<std::uint32_t> starts = bucket_starts(mesh.positions.size(), halfedges);
  const std::uint32_t threads = resolve_threads(threads_wanted);
  constexpr std::uint64_t kSliceEntries = std::uint64_t{1} << 25;
  std::uint64_t slices =
      std::max<std::uint64_t>(threads, (starts.back() + kSliceEntries - 1) / kSliceEntries);
  // A large mesh gets four slices per thread, so that a wave's scratch (8 bytes per entry) is
  // a quarter of the whole mesh's: the grouping was the front door's peak, beside the mesh and
  // the graph (7M triangles: 88 bytes per triangle), and is again now that the matching runs on
  // one adjacency. Each slice reads every halfedge once more: two per thread read them 4 times
  // instead of 8 at 2 threads (0.2G fewer instructions on armadillo-sub2, callgrind) but took
  // 13.5 bytes of scratch per triangle instead of 6.7, and the run's peak RSS from 95.3 to
  // 113.4 MB, with no wall time to show for it (3 alternated runs each, load 0.8).
  constexpr std::uint64_t kLargeEntries = std::uint64_t{1} << 20;
  if (starts.back() >= kLargeEntries) {
    slices = std::max<std::uint64_t>(slices, std::uint64_t{4} * threads);
  }
  std::vector<std::size_t> slice_start(slices + 1, mesh.positions.size());
  slice_start[0] = 0;
  for (std::uint64_t k = 1; k < slices; ++k) {
    // The first vertex whose bucket starts at or past the k-th share of the entries.
    const std::uint64_t target = starts.back() * k / slices;
    slice_start[k] =
        std::size_t(std::lower_bound(starts.begin(), starts.end() - 1, target) - starts.begin());
  }
  // Kept from wave to wave, so that each slice's flags reuse the previous wave's memory.
  std::vector<Slice> wave_slices(std::min<std::uint64_t>(threads, slices));
  for (std::uint64_t wave = 0; wave < slices; wave += threads) {
    const std::uint32_t count =
        static_cast<std::uint32_t>(std::min<std::uint64_t>(threads, slices - wave));
    run_parallel(threads, count, [&](std::uint32_t i) {
      Slice& slice = wave_slices[i];
      slice.cuts = {};
      slice.mesh_edges = slice.inconsistent_edges = slice.inconsistent_chosen_cuts = 0;
      slice.chosen_cut_ends.clear();
      slice.edges = 0;
      // The previous wave's groups go back to the pool first, for these to reuse: assigned over,
      // they were freed only after the new ones were built, two waves' scratch at once (the
      // run's peak on armadillo-sub2: 95.1 -> 87.1 MB, 69 -> 63 bytes per triangle).
      slice.groups = {};
      slice.groups =
          group_halfedges_in(starts, slice_start[wave + i], slice_start[wave + i + 1], halfedges);
      classify(slice);
    });
    std::vector<EdgeId> first_edge(count);
    for (std::uint32_t i = 0; i < count; ++i) {
      const Slice& slice = wave_slices[i];
      first_edge[i] = graph.edge_count();
      ends.resize(ends.size() + 2 * std::size_t{slice.edges});
      graph.mesh_edges += slice.mesh_edges;
      graph.inconsistent_edges += slice.inconsistent_edges;
      graph.inconsistent_chosen_cuts += slice.inconsistent_chosen_cuts;
      graph.chosen_cut_ends.insert(graph.chosen_cut_ends.end(), slice.chosen_cut_ends.begin(),
                                   slice.chosen_cut_ends.end());
      for (int c = 0; c < kCutCauses; ++c) graph.cuts.by_cause[c] += slice.cuts.by_cause[c];
    }
    run_parallel(threads, count, [&](std::uint32_t i) { number(wave_slices[i], first_edge[i]); });
  }
  graph.cubic = 2 * std::size_t{graph.edge_count()} == graph.node_edges.size();
  return graph;
}

}  // namespace petersen
