#include "pair_whole_mesh_by_lrs.hpp"

#include <algorithm>
#include <array>
#include <functional>
#include <span>
#include <stdexcept>

#include "petersen/lrs/contraction_step.hpp"
#include "petersen/lrs/dual_rows.hpp"
#include "petersen/matching/perfect_partners.hpp"

namespace petersen::quad_detail {

namespace {

// The input's triangles bucketed by their smallest corner (a counting sort), to find the one with
// a given vertex set: a triangle of K that no flip made is one of them. The buckets hold a few
// triangles each, stored with their other two corners so that a probe reads its bucket and not the
// mesh's corners (one random read per candidate fewer).
class TrianglesByCorner {
 public:
  explicit TrianglesByCorner(const PolygonMesh& mesh)
      : start_(mesh.positions.size() + 1, 0), entry_(mesh.face_count()) {
    const auto faces = static_cast<FaceId>(mesh.face_count());
    for (FaceId t = 0; t < faces; ++t) ++start_[smallest(mesh.face(t)) + 1];
    for (std::size_t v = 0; v + 1 < start_.size(); ++v) start_[v + 1] += start_[v];
    for (FaceId t = 0; t < faces; ++t) {
      const auto c = mesh.face(t);
      const VertexId low = smallest(c);
      const VertexId u = c[0] == low ? c[1] : c[0];
      const VertexId w = c[2] == low ? c[1] : c[2];
      entry_[start_[low]++] = {t, u, w};
    }
    // Each start moved to the next bucket's: shifted back by one bucket.
    for (std::size_t v = start_.size() - 1; v > 0; --v) start_[v] = start_[v - 1];
    start_[0] = 0;
  }

  /// Hints the caches at the buckets a later find(a, b, c) reads: first the bucket's start, then,
  /// once that is in cache, the bucket itself.
  void prefetch_start(VertexId low) const { __builtin_prefetch(&start_[low]); }
  void prefetch_bucket(VertexId low) const { __builtin_prefetch(entry_.data() + start_[low]); }

  /// The input triangle with corners {a, b, c} (distinct), or kNoFace.
  FaceId find(VertexId a, VertexId b, VertexId c) const {
    const VertexId low = std::min({a, b, c});
    const VertexId x = a == low ? b : a, y = c == low ? b : c;
    for (std::uint32_t j = start_[low]; j < start_[low + 1]; ++j) {
      const Entry& t = entry_[j];
      if ((t.u == x && t.w == y) || (t.u == y && t.w == x)) return t.face;
    }
    return kNoFace;
  }

 private:
  struct Entry {
    FaceId face;
    VertexId u, w;  // the corners other than the smallest
  };

  static VertexId smallest(std::span<const VertexId> t) { return std::min({t[0], t[1], t[2]}); }

  HugeVector<std::uint32_t> start_;
  HugeVector<Entry> entry_;
};

}  // namespace

void pair_whole_mesh_by_lrs(PairableGraph& graph, const PolygonMesh& mesh,
                            HugeVector<VertexId>* releasable_corners, const QuadOptions& options,
                            TrianglePairing& pairing, QuadStats& stats, LapClock& clock) {
  // The input's corners are read once more only to find the quads' sources: without those, the
  // consuming door's are freed as soon as from_dual is done with them (before it completes the
  // links: 12 bytes per triangle through the rest of from_dual, the contraction, the expansion
  // and K's rows; armadillo-sub2's peak 103.5 -> 88 MB), and given back to the kernel: the pool
  // would keep them resident beside those phases' arrays (4M plate: peak 263 -> 252 MB), while
  // what it kept before is what they reuse (emptying the pool instead cost 0.1-0.25 s of fresh
  // pages in those phases at 4M). from_dual refuses a mesh (a pinched vertex: the caller then
  // pairs it from these corners) only before it calls corners_read.
  const bool free_corners = !options.sources && releasable_corners != nullptr;
  const auto corners_read = [&] {
    const std::size_t kept = huge_pages::retained_bytes();
    *releasable_corners = HugeVector<VertexId>();  // `= {}` would keep the buffer
    huge_pages::trim_retained(kept);
  };
  // The caller has counted one component (the choice of this path).
  lrs::Triangulation tri = lrs::Triangulation::from_dual(
      mesh.positions, mesh.corners, std::move(graph.node_edges), std::move(graph.edge_ends),
      lrs::Triangulation::Connectivity::connected,
      free_corners ? std::function<void()>(corners_read) : std::function<void()>(),
      options.threads);
  stats.dual_seconds += clock.lap();

  // The contraction's stack dies once the expansion has undone it; K then becomes its dual's
  // rows, M's partners and its triangles, the triangulation freed on the way.
  lrs::ExpansionResult expansion;
  {
    const lrs::ContractionResult contraction = lrs::contract_to_irreducible(tri);
    stats.irreducible_vertices += tri.live_vertices();
    expansion = lrs::expand_and_match(tri, contraction.stack);
  }
  stats.flipped_edges += expansion.flipped_edges;
  lrs::DualRows k = lrs::into_dual_rows(std::move(tri), std::move(expansion));
  stats.matching.unpaired_after_initial += k.unpaired;
  stats.matching.initial_seconds += clock.lap();

  const AugmentStats augmented = augment_partners(k.rows, k.partner, options.augment);
  stats.matching.augmenting_paths += augmented.augmenting_paths;
  stats.matching.blossoms += augmented.blossoms;
  stats.matching.nodes_labelled += augmented.nodes_labelled;
  stats.matching.augment_seconds += clock.lap();
  if (MatchingCheck check = verify_perfect_partners(k.rows, k.partner); !check.ok()) {
    throw std::logic_error("internal error: lrs returned a matching that is not perfect: " +
                           check.message);
  }
  stats.verify_seconds += clock.lap();

  // A pair's quad: its first triangle turned so that side 0 faces the second (the rows name the
  // side), then the rows freed before the quads' list is made beside the triangles.
  const auto faces = static_cast<FaceId>(k.triangles.size());
  for (FaceId f = 0; f < faces; ++f) {
    const NodeId g = k.partner[f];
    if (g < f) continue;
    const NodeId* row = k.rows.data() + 3 * std::size_t{f};
    auto& t = k.triangles[f];
    if (row[1] == g) {
      t = {t[1], t[2], t[0]};
    } else if (row[2] == g) {
      t = {t[2], t[0], t[1]};
    }
  }
  k.rows = HugeVector<NodeId>();
  // K's face count: the mesh's corners may be freed by now (its face_count() would be 0, and the
  // list would grow by doubling, copying itself to fresh pages).
  pairing.lrs_quads.reserve(faces / 2);
  for (FaceId f = 0; f < faces; ++f) {
    const NodeId g = k.partner[f];
    if (g < f) continue;
    // Triangle (a, b, c) runs a -> b along the shared side, its partner b -> a with apex d: the
    // quad (a, d, b, c) keeps their orientation.
    const auto [a, b, c] = k.triangles[f];
    const auto& u = k.triangles[g];
    const VertexId d = u[0] != a && u[0] != b ? u[0] : u[1] != a && u[1] != b ? u[1] : u[2];
    pairing.lrs_quads.push_back({{a, d, b, c}, {kNoFace, kNoFace}});
  }
  k = lrs::DualRows();
  pairing.partner.assign(graph.node_count, kLrsNode);
  if (!options.sources) {
    stats.dual_seconds += clock.lap();
    return;
  }

  // The sources once K is freed, in a sweep over the quads that reads ahead: the lookups are random
  // reads of the buckets, two per quad, and the read-ahead hides them. Each quad (a, d, b, c) is
  // the triangles {a, b, c} and {a, b, d}; their buckets are those of their smallest corners.
  // Measured on the 16M plate (CPU busy, load 3.7-4.9), from freeing the rows to the sources done:
  // 1.07, 1.07, 0.86 s probing the mesh's corners inside the quads' loop; 0.86, 0.87, 0.77 s so.
  const TrianglesByCorner input(mesh);
  const std::size_t quads = pairing.lrs_quads.size();
  const auto lows = [&](std::size_t i) {
    const auto& q = pairing.lrs_quads[i].corners;
    const VertexId ab = std::min(q[0], q[2]);
    return std::array<VertexId, 2>{std::min(ab, q[3]), std::min(ab, q[1])};
  };
  constexpr std::size_t kReadAhead = 16;
  for (std::size_t i = 0; i < quads; ++i) {
    if (i + 2 * kReadAhead < quads) {
      for (const VertexId low : lows(i + 2 * kReadAhead)) input.prefetch_start(low);
    }
    if (i + kReadAhead < quads) {
      for (const VertexId low : lows(i + kReadAhead)) input.prefetch_bucket(low);
    }
    LrsQuad& quad = pairing.lrs_quads[i];
    const auto [a, d, b, c] = quad.corners;
    quad.sources = {input.find(a, b, c), input.find(b, a, d)};
  }
  stats.dual_seconds += clock.lap();
}

}  // namespace petersen::quad_detail
