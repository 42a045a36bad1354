// The repair step (partition.hpp): augmenting paths in the band graph, which crosses the cuts.

#include <algorithm>
#include <stdexcept>
#include <string>

#include "petersen/graph/stopwatch.hpp"
#include "petersen/matching/augment.hpp"
#include "petersen/matching/tutte_berge.hpp"
#include "petersen/partition/partition.hpp"

namespace petersen {

namespace {

constexpr std::uint32_t kAbsent = 0xFFFFFFFFu;  // a partner outside the band
constexpr std::uint32_t kFree = 0xFFFFFFFEu;    // no partner

// Band indices by face id, for lookups. Throws std::invalid_argument for a face given twice.
struct BandIndex {
  std::vector<std::uint32_t> by_face;  // band indices in ascending order of face
  std::span<const BandFace> band;

  explicit BandIndex(std::span<const BandFace> faces) : band(faces) {
    by_face.resize(band.size());
    for (std::uint32_t i = 0; i < band.size(); ++i) by_face[i] = i;
    std::sort(by_face.begin(), by_face.end(),
              [&](std::uint32_t x, std::uint32_t y) { return band[x].face < band[y].face; });
    for (std::size_t i = 1; i < by_face.size(); ++i) {
      if (band[by_face[i]].face == band[by_face[i - 1]].face) {
        throw std::invalid_argument("repair_cuts: face " + std::to_string(band[by_face[i]].face) +
                                    " is twice in the band");
      }
    }
  }
  std::uint32_t find(FaceId face) const {
    const auto it = std::lower_bound(by_face.begin(), by_face.end(), face,
                                     [&](std::uint32_t i, FaceId f) { return band[i].face < f; });
    return it != by_face.end() && band[*it].face == face ? *it : kAbsent;
  }
};

// The band index of each face's partner, kFree or kAbsent; checks that partners name each other.
std::vector<std::uint32_t> partner_indices(const BandIndex& index,
                                           std::span<const FaceId> partner) {
  std::vector<std::uint32_t> of(partner.size());
  for (std::uint32_t i = 0; i < partner.size(); ++i) {
    of[i] = partner[i] == kNoFace ? kFree : index.find(partner[i]);
    if (of[i] < kFree && partner[of[i]] != index.band[i].face) {
      throw std::invalid_argument("repair_cuts: face " + std::to_string(index.band[i].face) +
                                  " names partner " + std::to_string(partner[i]) +
                                  ", which names another");
    }
  }
  return of;
}

// A side of a band graph node that may be crossed: its edge's ends, the node, and whether it is
// an open edge of its part (crossed only by a cut adjacency).
struct Side {
  VertexId low, high;
  NodeId node;
  bool open;
};

struct BandGraph {
  std::vector<std::uint32_t> band_of;  // band index of each node
  CsrGraph graph;
};

bool is_adjacency(std::span<const CutAdjacency> adjacencies, FaceId a, FaceId b) {
  const CutAdjacency key{std::min(a, b), std::max(a, b), 0, 0};
  return std::binary_search(adjacencies.begin(), adjacencies.end(), key,
                            [](const CutAdjacency& x, const CutAdjacency& y) {
                              return x.first != y.first ? x.first < y.first : x.second < y.second;
                            });
}

// The nodes: band faces within `radius` that are free or paired inside the band, with their
// partners. Edges: an edge's two sides, both pairable in their part, or both open and a cut
// adjacency. O(b log b).
BandGraph band_graph(const RepairInput& input, std::span<const std::uint32_t> partner_of,
                     std::uint32_t radius) {
  const std::span<const BandFace> band = input.band;
  std::vector<std::uint8_t> in(band.size(), 0);
  for (std::uint32_t i = 0; i < band.size(); ++i) {
    if (band[i].distance > radius || partner_of[i] == kAbsent) continue;
    in[i] = 1;
    if (partner_of[i] != kFree) in[partner_of[i]] = 1;
  }
  BandGraph result;
  std::vector<std::uint32_t> node_of(band.size(), kAbsent);
  std::vector<Side> sides;
  for (std::uint32_t i = 0; i < band.size(); ++i) {
    if (!in[i]) continue;
    const NodeId v = node_of[i] = static_cast<NodeId>(result.band_of.size());
    result.band_of.push_back(i);
    for (int k = 0; k < 3; ++k) {
      if (band[i].sides[k] == SideState::cut) continue;
      const VertexId a = band[i].corners[k], b = band[i].corners[(k + 1) % 3];
      sides.push_back({std::min(a, b), std::max(a, b), v, band[i].sides[k] == SideState::open});
    }
  }
  std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) {
    return x.low != y.low ? x.low < y.low : x.high != y.high ? x.high < y.high : x.node < y.node;
  });
  std::vector<std::array<NodeId, 2>> edges;
  for (std::size_t i = 0, j; i < sides.size(); i = j) {
    for (j = i + 1;
         j < sides.size() && sides[j].low == sides[i].low && sides[j].high == sides[i].high; ++j) {
    }
    if (j - i != 2 || sides[i].open != sides[i + 1].open) continue;
    const NodeId a = sides[i].node, b = sides[i + 1].node;
    if (sides[i].open && !is_adjacency(input.adjacencies, band[result.band_of[a]].face,
                                       band[result.band_of[b]].face)) {
      continue;
    }
    edges.push_back({a, b});
  }
  result.graph = CsrGraph::from_edges(static_cast<std::uint32_t>(result.band_of.size()), edges);
  return result;
}

// The current pairs of the band graph's nodes as its initial matching: a pair whose edge is not
// in the graph (its edge turned out to be no pairable edge of the whole mesh) starts free.
Matching initial_matching(const BandGraph& g, std::span<const std::uint32_t> partner_of) {
  Matching matching(g.graph.node_count());
  for (NodeId v = 0; v < g.graph.node_count(); ++v) {
    const std::uint32_t p = partner_of[g.band_of[v]];
    if (p == kFree || matching.is_matched(v)) continue;
    for (EdgeId e : g.graph.incident_edges(v)) {
      const NodeId w = g.graph.other_end(e, v);
      if (g.band_of[w] == p && !matching.is_matched(w)) {
        matching.mate_edge[v] = matching.mate_edge[w] = e;
        break;
      }
    }
  }
  return matching;
}

// One round at `radius`: the band graph's maximum matching from the current pairs, certified,
// written into result.partner and partner_of.
void repair_round(const RepairInput& input, std::vector<std::uint32_t>& partner_of,
                  std::uint32_t radius, const RepairOptions& options, RepairResult& result) {
  const BandGraph g = band_graph(input, partner_of, radius);
  MaximumMatchingResult maximum =
      maximum_matching(g.graph, initial_matching(g, partner_of), options.augment);
  if (MatchingCheck check = verify_maximum_matching(g.graph, maximum.matching, maximum.tutte_set);
      !check.ok()) {
    throw std::logic_error("internal error: the band graph's matching fails its witness: " +
                           check.message);
  }
  for (NodeId v = 0; v < g.graph.node_count(); ++v) {
    const std::uint32_t i = g.band_of[v];
    const EdgeId e = maximum.matching.mate_edge[v];
    partner_of[i] = e == kNoEdge ? kFree : g.band_of[g.graph.other_end(e, v)];
    result.partner[i] = e == kNoEdge ? kNoFace : input.band[partner_of[i]].face;
  }
  result.augmenting_paths += maximum.stats.augmenting_paths;
  result.band_graph_faces = g.graph.node_count();
  result.radius = radius;
  result.maximum_in_band_certified = true;
}

}  // namespace

RepairResult repair_cuts(const RepairInput& input, const RepairOptions& options) {
  const Stopwatch clock;
  if (input.partner.size() != input.band.size()) {
    throw std::invalid_argument("repair_cuts: " + std::to_string(input.partner.size()) +
                                " partners for " + std::to_string(input.band.size()) +
                                " band faces");
  }
  const BandIndex index(input.band);
  std::vector<std::uint32_t> partner_of = partner_indices(index, input.partner);
  RepairResult result;
  result.partner.assign(input.partner.begin(), input.partner.end());
  result.unpaired_before = std::count(result.partner.begin(), result.partner.end(), kNoFace);
  std::uint32_t widest = 0;
  for (const BandFace& face : input.band) widest = std::max(widest, face.distance);
  result.unpaired_after = result.unpaired_before;
  for (std::uint32_t radius = std::min(std::max(options.first_radius, 1u), widest);
       result.unpaired_after > 0; radius = std::min(2 * radius, widest)) {
    repair_round(input, partner_of, radius, options, result);
    result.unpaired_after = std::count(result.partner.begin(), result.partner.end(), kNoFace);
    if (radius == widest) break;
  }
  result.seconds = clock.seconds();
  return result;
}

}  // namespace petersen
