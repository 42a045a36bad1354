#include "pair_whole_mesh_by_lrs.hpp"

#include <algorithm>
#include <stdexcept>

#include "petersen/lrs/contraction_step.hpp"
#include "petersen/lrs/expansion_step.hpp"
#include "petersen/matching/augment.hpp"

namespace petersen::quad_detail {

namespace {

// The input's triangles bucketed by their smallest corner (a counting sort), to find the one with
// a given vertex set: a triangle of K that no flip made is one of them. The buckets hold a few
// triangles each.
class TrianglesByCorner {
 public:
  explicit TrianglesByCorner(const PolygonMesh& mesh)
      : mesh_(mesh), start_(mesh.positions.size() + 1, 0), face_(mesh.face_count()) {
    const auto faces = static_cast<FaceId>(mesh.face_count());
    for (FaceId t = 0; t < faces; ++t) ++start_[smallest(mesh.face(t)) + 1];
    for (std::size_t v = 0; v + 1 < start_.size(); ++v) start_[v + 1] += start_[v];
    for (FaceId t = 0; t < faces; ++t) face_[start_[smallest(mesh.face(t))]++] = t;
    // Each start moved to the next bucket's: shifted back by one bucket.
    for (std::size_t v = start_.size() - 1; v > 0; --v) start_[v] = start_[v - 1];
    start_[0] = 0;
  }

  /// The input triangle with corners {a, b, c}, or kNoFace.
  FaceId find(VertexId a, VertexId b, VertexId c) const {
    const VertexId low = std::min({a, b, c});
    for (std::uint32_t j = start_[low]; j < start_[low + 1]; ++j) {
      const auto t = mesh_.face(face_[j]);
      const auto has = [&](VertexId v) { return v == t[0] || v == t[1] || v == t[2]; };
      if (has(a) && has(b) && has(c)) return face_[j];
    }
    return kNoFace;
  }

 private:
  static VertexId smallest(std::span<const VertexId> t) { return std::min({t[0], t[1], t[2]}); }

  const PolygonMesh& mesh_;
  HugeVector<std::uint32_t> start_;
  HugeVector<FaceId> face_;
};

}  // namespace

void pair_whole_mesh_by_lrs(PairableGraph& graph, const PolygonMesh& mesh,
                            const QuadOptions& options, TrianglePairing& pairing, QuadStats& stats,
                            LapClock& clock) {
  lrs::Triangulation tri = lrs::Triangulation::from_dual(
      mesh.positions, mesh.corners, std::move(graph.node_edges), std::move(graph.edge_ends));
  stats.dual_seconds += clock.lap();

  // The contraction's stack dies once the expansion has undone it; the expansion's edge states
  // once M is on K's dual, which takes the triangulation's face array over.
  lrs::ExpansionResult expansion;
  {
    const lrs::ContractionResult contraction = lrs::contract_to_irreducible(tri);
    stats.irreducible_vertices += tri.live_vertices();
    expansion = lrs::expand_and_match(tri, contraction.stack);
  }
  stats.flipped_edges += expansion.flipped_edges;
  CubicGraph dual = std::move(tri).dual_graph();
  Matching matching = lrs::matching_of(dual, expansion);
  expansion.edge_state = HugeVector<std::uint8_t>();
  stats.matching.unpaired_after_initial += matching.unmatched_count();
  stats.matching.initial_seconds += clock.lap();

  stats.matching.augmenting_paths +=
      augment_matching(dual, matching, options.augment).augmenting_paths;
  stats.matching.augment_seconds += clock.lap();
  if (MatchingCheck check = verify_perfect_matching(dual, matching); !check.ok()) {
    throw std::logic_error("internal error: lrs returned a matching that is not perfect: " +
                           check.message);
  }
  stats.verify_seconds += clock.lap();

  // The quads need only K's links and which edges are matched: the dual and the matching go first.
  HugeVector<std::uint8_t> matched(dual.edge_count(), 0);
  for (NodeId f = 0; f < dual.node_count(); ++f) matched[matching.mate_edge[f]] = 1;
  const EdgeId edges = dual.edge_count();
  dual = CubicGraph();
  matching = Matching();
  const TrianglesByCorner input(mesh);
  pairing.lrs_quads.reserve(mesh.face_count() / 2);
  for (EdgeId e = 0; e < edges; ++e) {
    if (!matched[e]) continue;
    // Halfedge h = 2e runs a -> b in triangle (a, b, c), its twin b -> a in (b, a, d): the quad
    // (a, d, b, c) keeps their orientation.
    const lrs::Halfedge h = 2 * e, g = h + 1;
    const VertexId a = tri.input_vertex(tri.origin(h)), b = tri.input_vertex(tri.origin(g));
    const VertexId c = tri.input_vertex(tri.apex(h)), d = tri.input_vertex(tri.apex(g));
    pairing.lrs_quads.push_back({{a, d, b, c}, {input.find(a, b, c), input.find(b, a, d)}});
  }
  tri = lrs::Triangulation();
  pairing.partner.assign(graph.node_count, kLrsNode);
  stats.dual_seconds += clock.lap();
}

}  // namespace petersen::quad_detail
