#include "petersen/lrs/lrs.hpp"

#include <stdexcept>
#include <string>

#include "contraction_step.hpp"
#include "dual_rows.hpp"
#include "expansion_step.hpp"
#include "petersen/dualize/quad_of.hpp"
#include "petersen/graph/stopwatch.hpp"
#include "petersen/matching/perfect_partners.hpp"
#include "triangles_by_corner.hpp"
#include "triangulation.hpp"

namespace petersen {

namespace {

// Contraction to T′ and expansion to K with M (paper §3.3, Algorithms 3.1–3.4), then K as its
// dual's rows, M's partners and its triangles, the triangulation freed on the way. The
// contraction's stack dies once the expansion has undone it.
lrs::DualRows contract_and_expand(lrs::Triangulation tri, LrsStats& stats) {
  stats.genus = tri.genus();
  stats.vertices = tri.live_vertices();
  stats.edges = tri.live_edges();
  stats.faces = tri.live_faces();
  lrs::ExpansionResult expansion;
  {
    auto start = Stopwatch();
    const lrs::ContractionResult contraction = lrs::contract_to_irreducible(tri);
    stats.contraction_seconds = start.seconds();
    stats.contractions = contraction.stack.size();
    stats.irreducible_vertices = tri.live_vertices();
    stats.irreducible_faces = tri.live_faces();
    start = Stopwatch();
    expansion = lrs::expand_and_match(tri, contraction.stack);
    stats.expansion_seconds = start.seconds();
  }
  const auto start = Stopwatch();
  stats.flipped_edges = expansion.flipped_edges;
  stats.unflips = expansion.unflips;
  for (int c = 0; c < 4; ++c) stats.expansion_cases[c] = expansion.cases[c];
  lrs::DualRows k = lrs::into_dual_rows(std::move(tri), std::move(expansion));
  stats.unpaired_after_expansion = k.unpaired;
  stats.expansion_seconds += start.seconds();
  return k;
}

// Tarjan's augmenting paths pair the ℓ faces M leaves (§3.4); the matching is then verified
// perfect on K's dual.
void augment_and_verify(lrs::DualRows& k, Augment augment, LrsStats& stats) {
  auto start = Stopwatch();
  const AugmentStats augmented = augment_partners(k.rows, k.partner, augment);
  stats.augmenting_paths = augmented.augmenting_paths;
  stats.blossoms = augmented.blossoms;
  stats.nodes_labelled = augmented.nodes_labelled;
  stats.augment_seconds = start.seconds();
  start = Stopwatch();
  if (MatchingCheck check = verify_perfect_partners(k.rows, k.partner); !check.ok()) {
    throw std::logic_error("internal error: lrs returned a matching that is not perfect: " +
                           check.message);
  }
  stats.verify_seconds = start.seconds();
}

// One quad per pair of K's triangles, by quad_of: K is simplicial, so two of its triangles share
// at most one side, the one the pair is across. K's rows are freed before the list is made beside
// its triangles, and K once it is made.
std::pmr::vector<LrsQuad> quads_of(lrs::DualRows&& k, std::pmr::memory_resource* memory) {
  free_storage(k.rows);  // `= {}` would keep the buffer
  const auto faces = static_cast<FaceId>(k.triangles.size());
  std::pmr::vector<LrsQuad> quads(memory);
  quads.reserve(faces / 2);
  for (FaceId f = 0; f < faces; ++f) {
    const NodeId g = k.partner[f];
    if (g < f) continue;
    quads.push_back({quad_of(k.triangles[f], k.triangles[g]), {kNoFace, kNoFace}});
  }
  k = lrs::DualRows();
  return quads;
}

// The input triangle behind each of a quad's two triangles, in a sweep that reads ahead: the
// lookups are random reads of the buckets, two per quad, and the read-ahead hides them. Each quad
// (a, d, b, c) is the triangles {a, b, c} and {a, b, d}; their buckets are those of their smallest
// corners. Reading ahead cuts the sweep by a fifth on the 16M plate against probing in the quads'
// loop.
void find_sources(std::span<const VertexId> corners, std::size_t vertex_count,
                  std::pmr::vector<LrsQuad>& quads) {
  const lrs::TrianglesByCorner input(corners, vertex_count);
  const std::size_t count = quads.size();
  const auto lows = [&](std::size_t i) {
    const auto& q = quads[i].corners;
    const VertexId ab = std::min(q[0], q[2]);
    return std::array<VertexId, 2>{std::min(ab, q[3]), std::min(ab, q[1])};
  };
  constexpr std::size_t kReadAhead = 16;
  for (std::size_t i = 0; i < count; ++i) {
    if (i + 2 * kReadAhead < count) {
      for (const VertexId low : lows(i + 2 * kReadAhead)) input.prefetch_start(low);
    }
    if (i + kReadAhead < count) {
      for (const VertexId low : lows(i + kReadAhead)) input.prefetch_bucket(low);
    }
    LrsQuad& quad = quads[i];
    const auto [a, d, b, c] = quad.corners;
    quad.sources = {input.find(a, b, c), input.find(b, a, d)};
  }
}

// Everything after the triangulation, for both inputs: `corners` are the input's triangles, read
// again for the sources only.
std::pmr::vector<LrsQuad> pair_triangulation(lrs::Triangulation tri,
                                             std::span<const VertexId> corners,
                                             std::size_t vertex_count, const LrsOptions& options,
                                             LrsStats& stats) {
  lrs::DualRows k = contract_and_expand(std::move(tri), stats);
  augment_and_verify(k, options.augment, stats);
  const auto start = Stopwatch();
  std::pmr::vector<LrsQuad> quads = quads_of(std::move(k), options.memory);
  if (options.sources) find_sources(corners, vertex_count, quads);
  stats.quads_seconds = start.seconds();
  return quads;
}

}  // namespace

LrsPairing pair_closed_component_by_lrs(const PolygonMesh& component, const LrsOptions& options) {
  const auto begin = Stopwatch();
  LrsPairing pairing{.quads = std::pmr::vector<LrsQuad>(options.memory)};
  lrs::Triangulation tri =
      lrs::Triangulation::from_mesh(component, lrs::Triangulation::Numbering::spatial);
  pairing.stats.setup_seconds = begin.seconds();
  pairing.quads = pair_triangulation(std::move(tri), component.corners, component.positions.size(),
                                     options, pairing.stats);
  pairing.stats.total_seconds = begin.seconds();
  return pairing;
}

LrsPairing pair_closed_component_by_lrs(LrsDualInput input, const LrsOptions& options) {
  const auto begin = Stopwatch();
  LrsPairing pairing{.quads = std::pmr::vector<LrsQuad>(options.memory)};
  lrs::Triangulation tri = lrs::Triangulation::from_dual(
      input.positions, input.corners, std::move(input.node_edges), std::move(input.edge_ends),
      input.connected ? lrs::Triangulation::Connectivity::connected
                      : lrs::Triangulation::Connectivity::unknown,
      options.sources ? std::function<void()>() : input.corners_read, options.threads);
  pairing.stats.setup_seconds = begin.seconds();
  pairing.quads = pair_triangulation(std::move(tri), input.corners, input.positions.size(), options,
                                     pairing.stats);
  if (options.sources && input.corners_read) input.corners_read();
  pairing.stats.total_seconds = begin.seconds();
  return pairing;
}

}  // namespace petersen
