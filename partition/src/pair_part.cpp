// The part step (partition.hpp): a certified maximum matching of the part's pairable graph, its
// unpaired triangles moved to the border, its open edges and its band.

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "local_vertices.hpp"
#include "move_to_border.hpp"
#include "petersen/dualize/quad_quality.hpp"
#include "petersen/graph/stopwatch.hpp"
#include "petersen/matching/augment.hpp"
#include "petersen/matching/tutte_berge.hpp"
#include "petersen/matching/verify_min_cost.hpp"
#include "petersen/partition/partition.hpp"
#include "petersen/quadrangulate/triangle_prices.hpp"

namespace petersen {

namespace {

using partition_detail::local_corners;
using partition_detail::move_to_border;

// A cut side of a triangle: its edge's global ends (low < high), the node and the side.
struct CutSide {
  VertexId low, high;
  NodeId node;
  std::uint32_t side;
};

bool is_degenerate(std::span<const VertexId> t) {
  return t[0] == t[1] || t[1] == t[2] || t[2] == t[0];
}

// The part's sides by node: bit k of `open` when side k is an edge with no other triangle in the
// window, bit k of `own_border` when, for an own triangle, side k is open for the own triangles
// alone (open in the window, or across to a carried triangle).
struct Borders {
  std::vector<std::uint8_t> open, own_border;
};

VertexId apex_of(std::span<const VertexId> t, std::uint32_t side, VertexId low) {
  // A degenerate triangle's record names one of the edge's ends as its apex: pair_open_edges
  // never pairs it.
  return is_degenerate(t) ? low : t[(side + 2) % 3];
}

// The window's cut sides with one triangle, sorted: O(s log s) for s cut sides, which on a part
// of a surface are O(√m) for m triangles.
std::vector<CutSide> single_cut_sides(const PartTriangles& part, const PairableGraph& graph) {
  std::vector<CutSide> sides;
  for (NodeId v = 0; v < graph.node_count; ++v) {
    for (std::uint32_t k = 0; k < 3; ++k) {
      if (graph.node_edges[3 * std::size_t{v} + k] != kNoEdge) continue;
      const VertexId a = part.corners[3 * std::size_t{v} + k];
      const VertexId b = part.corners[3 * std::size_t{v} + (k + 1) % 3];
      if (a != b) sides.push_back({std::min(a, b), std::max(a, b), v, k});
    }
  }
  std::sort(sides.begin(), sides.end(), [](const CutSide& x, const CutSide& y) {
    return x.low != y.low ? x.low < y.low : x.high != y.high ? x.high < y.high : x.node < y.node;
  });
  std::vector<CutSide> single;
  for (std::size_t i = 0, j; i < sides.size(); i = j) {
    for (j = i + 1;
         j < sides.size() && sides[j].low == sides[i].low && sides[j].high == sides[i].high; ++j) {
    }
    if (j - i == 1) single.push_back(sides[i]);
  }
  return single;
}

// The borders and the own triangles' open edges (ascending by (low, high, face)).
Borders find_borders(const PartTriangles& part, const PairableGraph& graph,
                     std::vector<OpenEdge>& open_edges) {
  Borders borders{std::vector<std::uint8_t>(graph.node_count, 0),
                  std::vector<std::uint8_t>(graph.node_count, 0)};
  auto add = [&](NodeId v, std::uint32_t k, VertexId low, VertexId high) {
    borders.own_border[v] |= std::uint8_t(1u << k);
    const std::span<const VertexId> t = part.corners.subspan(3 * std::size_t{v}, 3);
    open_edges.push_back({low, high, part.first_face + v, apex_of(t, k, low)});
  };
  for (const CutSide& s : single_cut_sides(part, graph)) {
    borders.open[s.node] |= std::uint8_t(1u << s.side);
    if (s.node >= part.carried) add(s.node, s.side, s.low, s.high);
  }
  for (NodeId v = part.carried; v < graph.node_count; ++v) {
    for (std::uint32_t k = 0; k < 3; ++k) {
      const EdgeId e = graph.node_edges[3 * std::size_t{v} + k];
      if (e == kNoEdge ||
          (graph.edge_ends[2 * e] ^ graph.edge_ends[2 * e + 1] ^ v) >= part.carried) {
        continue;
      }
      const VertexId a = part.corners[3 * std::size_t{v} + k];
      const VertexId b = part.corners[3 * std::size_t{v} + (k + 1) % 3];
      add(v, k, std::min(a, b), std::max(a, b));
    }
  }
  std::sort(open_edges.begin(), open_edges.end(), [](const OpenEdge& x, const OpenEdge& y) {
    return x.low != y.low ? x.low < y.low : x.high != y.high ? x.high < y.high : x.face < y.face;
  });
  return borders;
}

// The own triangles within `radius` steps (across pairable edges between own triangles) of one
// with an own border side: a breadth-first search from all of those at once. O(m) for the
// distances, O(b log b) for the band.
std::vector<BandFace> band_of(const PartTriangles& part, const PairableGraph& graph,
                              const Borders& borders, std::uint32_t radius) {
  constexpr std::uint32_t kFar = 0xFFFFFFFFu;
  std::vector<std::uint32_t> distance(graph.node_count, kFar);
  std::vector<NodeId> queue;
  for (NodeId v = part.carried; v < graph.node_count; ++v) {
    if (borders.own_border[v]) {
      distance[v] = 0;
      queue.push_back(v);
    }
  }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const NodeId v = queue[head];
    if (distance[v] == radius) continue;
    for (std::uint32_t k = 0; k < 3; ++k) {
      const EdgeId e = graph.node_edges[3 * std::size_t{v} + k];
      if (e == kNoEdge) continue;
      const NodeId w = graph.edge_ends[2 * e] ^ graph.edge_ends[2 * e + 1] ^ v;
      if (w < part.carried || distance[w] != kFar) continue;
      distance[w] = distance[v] + 1;
      queue.push_back(w);
    }
  }
  std::sort(queue.begin(), queue.end());
  std::vector<BandFace> band(queue.size());
  for (std::size_t i = 0; i < queue.size(); ++i) {
    const NodeId v = queue[i];
    BandFace& face = band[i];
    face.face = part.first_face + v;
    face.distance = distance[v];
    for (std::uint32_t k = 0; k < 3; ++k) {
      face.corners[k] = part.corners[3 * std::size_t{v} + k];
      face.sides[k] = (borders.own_border[v] >> k) & 1u                     ? SideState::open
                      : graph.node_edges[3 * std::size_t{v} + k] != kNoEdge ? SideState::pairable
                                                                            : SideState::cut;
    }
  }
  return band;
}

// The pairable graph without the edges of the held triangles (carried ones paired outside).
CsrGraph csr_of(const PairableGraph& graph, std::span<const std::uint8_t> held) {
  std::pmr::vector<std::array<NodeId, 2>> edges;
  edges.reserve(graph.edge_count());
  for (EdgeId e = 0; e < graph.edge_count(); ++e) {
    const NodeId a = graph.edge_ends[2 * e], b = graph.edge_ends[2 * e + 1];
    if (!held[a] && !held[b]) edges.push_back({a, b});
  }
  return CsrGraph::from_edges(graph.node_count, edges);
}

// Whether each carried triangle is held (paired outside the part); checks carried_partner.
std::vector<std::uint8_t> held_triangles(const PartTriangles& part, std::uint32_t n) {
  if (part.carried_partner.size() != part.carried || part.carried > n) {
    throw std::invalid_argument("pair_part: " + std::to_string(part.carried_partner.size()) +
                                " carried partners for " + std::to_string(part.carried) +
                                " carried of " + std::to_string(n) + " triangles");
  }
  std::vector<std::uint8_t> held(n, 0);
  for (NodeId v = 0; v < part.carried; ++v) {
    const FaceId p = part.carried_partner[v];
    const std::uint64_t local = std::uint64_t{p} - part.first_face;
    if (p == kNoFace) continue;
    if (p < part.first_face || local >= n) {
      held[v] = 1;
    } else if (local >= part.carried || part.carried_partner[local] != part.first_face + v) {
      throw std::invalid_argument("pair_part: carried face " + std::to_string(part.first_face + v) +
                                  " names partner " + std::to_string(p) +
                                  ", which does not name it back");
    }
  }
  return held;
}

void check_part(const PartTriangles& part) {
  if (part.corners.size() % 3 != 0) {
    throw std::invalid_argument("pair_part: the corner count " +
                                std::to_string(part.corners.size()) + " is no multiple of 3");
  }
  if (std::uint64_t{part.first_face} + part.corners.size() / 3 > kNoFace) {
    throw MeshError("part from face " + std::to_string(part.first_face) + " with " +
                    std::to_string(part.corners.size() / 3) +
                    " triangles runs past the largest face id (2^32 - 2)");
  }
}

// The carried pairs inside the part, then a greedy pass over the other edges in id order.
Matching initial_matching(const CsrGraph& csr, const PartTriangles& part) {
  Matching matching(csr.node_count());
  for (NodeId v = 0; v < part.carried; ++v) {
    const FaceId p = part.carried_partner[v];
    if (p == kNoFace || p < part.first_face || p - part.first_face >= part.carried) continue;
    for (EdgeId e : csr.incident_edges(v)) {
      if (csr.other_end(e, v) == p - part.first_face) matching.mate_edge[v] = e;
    }
  }
  for (EdgeId e = 0; e < csr.edge_count(); ++e) {
    const auto [a, b] = csr.endpoints(e);
    if (!matching.is_matched(a) && !matching.is_matched(b))
      matching.mate_edge[a] = matching.mate_edge[b] = e;
  }
  return matching;
}

// The certified maximum matching of the part's graph, its free nodes moved to the own
// triangles' open sides (held and carried triangles are no destination).
std::pmr::vector<NodeId> match_part(const PairableGraph& graph, const PartTriangles& part,
                                    const Borders& borders, std::span<const std::uint8_t> held,
                                    const PartPairingOptions& options, PartPairing& result) {
  const CsrGraph csr = csr_of(graph, held);
  MaximumMatchingResult maximum =
      part.carried == 0 ? maximum_matching(csr, options.augment)
                        : maximum_matching(csr, initial_matching(csr, part), options.augment);
  if (MatchingCheck check = verify_maximum_matching(csr, maximum.matching, maximum.tutte_set);
      !check.ok()) {
    throw std::logic_error("internal error: a part's matching fails its witness: " + check.message);
  }
  result.maximum_certified = true;
  std::vector<std::uint8_t> destination(graph.node_count, 0);
  for (NodeId v = 0; v < graph.node_count; ++v) {
    destination[v] = held[v] || (v >= part.carried && borders.open[v] != 0);
  }
  const partition_detail::MoveStats moves = move_to_border(
      csr, maximum.matching, destination,
      options.move_budget > 0 ? options.move_budget : 4 * std::uint64_t{graph.node_count});
  if (MatchingCheck check = verify_matching(csr, maximum.matching); !check.ok()) {
    throw std::logic_error("internal error: moving a part's unpaired triangles broke it: " +
                           check.message);
  }
  result.moved_to_border = moves.moved;
  result.stranded = moves.stranded;
  std::pmr::vector<NodeId> mate(graph.node_count, kNoNode, options.memory);
  for (NodeId v = 0; v < graph.node_count; ++v) {
    const EdgeId e = maximum.matching.mate_edge[v];
    if (e != kNoEdge) mate[v] = csr.other_end(e, v);
  }
  return mate;
}

// The part as a mesh over its own vertices (with their positions where the part has them; the
// graph reads only their count otherwise), and its pairable graph under the sharp-angle cut.
PairableGraph graph_of(const PartTriangles& part, const PartPairingOptions& options,
                       PolygonMesh& mesh) {
  partition_detail::LocalCorners local = local_corners(part.corners, part.first_face);
  mesh.positions.resize(local.vertex_count);
  for (std::size_t c = 0; c < part.corner_positions.size(); ++c) {
    mesh.positions[local.corners[c]] = part.corner_positions[c];
  }
  mesh.corners = std::move(local.corners);
  CutOptions cuts;
  cuts.sharp_angle_degrees = options.costs.sharp_angle_degrees;
  return build_pairable_graph(mesh, cuts, options.threads, options.memory);
}

void fill_partners(const PartTriangles& part, std::span<const NodeId> mate,
                   std::span<const std::uint8_t> held, PartPairing& result) {
  result.partner.resize(mate.size());
  for (NodeId v = 0; v < mate.size(); ++v) {
    const NodeId w = mate[v];
    if (held[v]) {
      result.partner[v] = part.carried_partner[v];
    } else if (w == kNoNode) {
      result.partner[v] = kNoFace;
      result.unpaired.push_back(part.first_face + v);
    } else {
      result.partner[v] = part.first_face + w;
      result.pairs += v < w;
    }
  }
}

// The value of each odd set of the certificate plus those of the sets holding it, so that a
// node's part of an edge's constraint is its own value plus its innermost set's sum. O(sets).
std::vector<std::int64_t> nested_set_sums(const MatchingCertificate& certificate) {
  const std::size_t sets = certificate.set_count();
  std::vector<std::int64_t> sum(sets);
  std::vector<std::uint8_t> done(sets, 0);
  std::vector<std::uint32_t> chain;
  for (std::uint32_t s = 0; s < sets; ++s) {
    std::uint32_t t = s;
    for (; t != kNoSet && !done[t]; t = certificate.set_parent[t]) chain.push_back(t);
    std::int64_t above = t == kNoSet ? 0 : sum[t];
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
      above = sum[*it] = certificate.set_dual[*it] + above;
      done[*it] = 1;
    }
    chain.clear();
  }
  return sum;
}

// The cost objectives' matching of the part's graph under quadrangulate's costs (the edges the
// corner threshold refuses left out), its certificate checked; the part's optimum and, for
// Objective::quads, each seam node's dual in both copies of the doubled graph into `result`.
std::pmr::vector<NodeId> match_part_at_cost(const PairableGraph& graph, const PolygonMesh& mesh,
                                            const PartPairingOptions& options,
                                            PartPairing& result) {
  const std::pmr::vector<double> degrees =
      pairable_edge_quality(graph, mesh, options.threads, options.memory);
  std::pmr::vector<std::array<NodeId, 2>> edges(options.memory);
  std::pmr::vector<double> kept(options.memory);
  edges.reserve(graph.edge_count());
  kept.reserve(graph.edge_count());
  for (EdgeId e = 0; e < graph.edge_count(); ++e) {
    if (options.costs.max_corner_deviation && degrees[e] > *options.costs.max_corner_deviation)
      continue;
    edges.push_back({graph.edge_ends[2 * e], graph.edge_ends[2 * e + 1]});
    kept.push_back(degrees[e]);
  }
  const CsrGraph csr = CsrGraph::from_edges(graph.node_count, edges, options.memory);
  const std::pmr::vector<Cost> costs = scale_costs(kept, kDefaultCostScale, options.memory);
  const std::uint32_t n = graph.node_count;
  Matching matching(0, options.memory);  // the results' are moved in, on the same resource
  if (options.costs.objective == Objective::quads) {
    const std::pmr::vector<Cost> prices = triangle_prices(
        n, csr.edge_ends(), costs, std::llround(options.costs.triangle_cost * kDefaultCostScale),
        options.memory);
    MinCostMatchingResult r = min_cost_matching(
        csr, costs, prices, {.threads = options.threads, .memory = options.memory});
    if (CertificateCheck check = verify_min_cost_matching(
            n, csr.edge_ends(), costs, prices, r.matching, r.total, r.certificate, options.memory);
        !check.ok()) {
      throw std::logic_error("internal error: a part's least-cost pairing fails its certificate: " +
                             check.problem);
    }
    result.objective_units = r.total;
    result.maximum_certified = 2 * std::uint64_t{r.size} == n;
    const std::vector<std::int64_t> sums = nested_set_sums(r.certificate);
    auto dual = [&](NodeId v) {
      const std::uint32_t s = r.certificate.node_set[v];
      return r.certificate.node_dual[v] + (s == kNoSet ? 0 : sums[s]);
    };
    std::vector<std::uint32_t> mark(r.certificate.set_count(), kNoNode);
    for (SeamFace& face : result.seam) {
      const NodeId v = face.face - result.first_face;
      face.dual = {dual(v), dual(n + v)};
      face.price = prices[v];
      // The stay edge v–v' counts the sets holding exactly one of its ends: those holding both,
      // the common chain above their lowest common set, count twice in dual(v) + dual(v').
      // O(depth of the two chains).
      for (std::uint32_t s = r.certificate.node_set[v]; s != kNoSet;
           s = r.certificate.set_parent[s])
        mark[s] = v;
      std::uint32_t common = r.certificate.node_set[n + v];
      while (common != kNoSet && mark[common] != v) common = r.certificate.set_parent[common];
      face.stay_dual = face.dual[0] + face.dual[1] - (common == kNoSet ? 0 : 2 * sums[common]);
    }
    matching = std::move(r.matching);
  } else {
    MinCostMaximumResult r = min_cost_maximum_matching(
        csr, costs, {.threads = options.threads, .memory = options.memory});
    if (CertificateCheck check =
            verify_min_cost_maximum_matching(n, csr.edge_ends(), costs, r.matching, r.total_cost,
                                             r.unmatched_cost, r.certificate, options.memory);
        !check.ok()) {
      throw std::logic_error(
          "internal error: a part's cheapest maximum pairing fails its "
          "certificate: " +
          check.problem);
    }
    result.objective_units = r.total_cost;
    result.maximum_certified = true;
    matching = std::move(r.matching);
  }
  result.optimality_certified = true;
  std::pmr::vector<NodeId> mate(n, kNoNode, options.memory);
  for (NodeId v = 0; v < n; ++v) {
    const EdgeId e = matching.mate_edge[v];
    if (e != kNoEdge) mate[v] = csr.other_end(e, v);
  }
  return mate;
}

// The band (band_of) with the corners' positions; partners and duals come with the matching.
std::vector<SeamFace> seam_of(const PartTriangles& part, const PairableGraph& graph,
                              const Borders& borders, std::uint32_t radius) {
  const std::vector<BandFace> band = band_of(part, graph, borders, radius);
  std::vector<SeamFace> seam(band.size());
  for (std::size_t i = 0; i < band.size(); ++i) {
    const std::size_t v = band[i].face - part.first_face;
    seam[i].face = band[i].face;
    seam[i].corners = band[i].corners;
    seam[i].sides = band[i].sides;
    seam[i].distance = band[i].distance;
    for (int k = 0; k < 3; ++k) seam[i].positions[k] = part.corner_positions[3 * v + k];
  }
  return seam;
}

// pair_part with a cost objective: the part alone (no carried triangles), no moves (they would
// change the cost), its band as seam faces.
PartPairing pair_part_at_cost(const PartTriangles& part, const PartPairingOptions& options) {
  const Stopwatch clock;
  if (part.carried > 0) {
    throw std::invalid_argument("pair_part: the cost objectives pair each part alone, not " +
                                std::to_string(part.carried) + " carried triangles");
  }
  if (part.corner_positions.size() != part.corners.size()) {
    throw std::invalid_argument("pair_part: the cost objectives need a position per corner: " +
                                std::to_string(part.corner_positions.size()) + " for " +
                                std::to_string(part.corners.size()) + " corners");
  }
  if (options.costs.objective == Objective::quads && options.band_radius < 3) {
    // The seams price a face beside a cut from its two rings (pair_seams), which must lie in
    // the bands.
    throw std::invalid_argument(
        "pair_part: the quads objective needs a band radius of 3 or more, not " +
        std::to_string(options.band_radius));
  }
  PartPairing result{.first_face = part.first_face,
                     .partner = std::pmr::vector<FaceId>(options.memory)};
  PolygonMesh mesh(options.memory);
  const PairableGraph graph = graph_of(part, options, mesh);
  result.inner_structural_cuts =
      graph.cuts.structural() - graph.cuts.by_cause[static_cast<int>(CutCause::boundary)];
  const Borders borders = find_borders(part, graph, result.open_edges);
  result.seam = seam_of(part, graph, borders, options.band_radius);
  const std::pmr::vector<NodeId> mate = match_part_at_cost(graph, mesh, options, result);
  const std::vector<std::uint8_t> held(graph.node_count, 0);
  fill_partners(part, mate, held, result);
  for (SeamFace& face : result.seam) face.partner = result.partner[face.face - part.first_face];
  result.seconds = clock.seconds();
  return result;
}

}  // namespace

PartPairing pair_part(const PartTriangles& part, const PartPairingOptions& options) {
  check_part(part);
  if (options.costs.sharp_angle_degrees && part.corner_positions.size() != part.corners.size()) {
    throw std::invalid_argument("pair_part: the sharp-angle cut needs a position per corner");
  }
  if (options.costs.objective != Objective::pairs) return pair_part_at_cost(part, options);
  if (options.costs.sharp_angle_degrees || options.costs.max_corner_deviation) {
    // The band repair pairs across the cuts without measuring the quads.
    throw std::invalid_argument(
        "pair_part: the sharp angle and the corner threshold go with a cost objective");
  }
  const Stopwatch clock;
  PartPairing result{.first_face = part.first_face,
                     .partner = std::pmr::vector<FaceId>(options.memory)};
  // The mesh is freed before the matching: the pairs objective measures nothing. The graph is
  // made on options.memory and moved out, not assigned (which would copy it).
  const PairableGraph graph = [&] {
    PolygonMesh mesh(options.memory);
    return graph_of(part, options, mesh);
  }();
  const std::vector<std::uint8_t> held = held_triangles(part, graph.node_count);
  result.inner_structural_cuts =
      graph.cuts.structural() - graph.cuts.by_cause[static_cast<int>(CutCause::boundary)];
  const Borders borders = find_borders(part, graph, result.open_edges);
  const std::pmr::vector<NodeId> mate = match_part(graph, part, borders, held, options, result);
  fill_partners(part, mate, held, result);
  result.band = band_of(part, graph, borders, options.band_radius);
  result.seconds = clock.seconds();
  return result;
}

}  // namespace petersen
