// The seam step of the cost objectives (partition.hpp): the parts' bands and the cut adjacencies
// paired again by a minimum-cost matching, and the parts' duals stitched into a lower bound.

#include <algorithm>
#include <cmath>
#include <memory_resource>
#include <stdexcept>
#include <string>
#include <vector>

#include "petersen/dualize/quad_quality.hpp"
#include "petersen/graph/component_forest.hpp"
#include "petersen/graph/stopwatch.hpp"
#include "petersen/matching/verify_min_cost.hpp"
#include "petersen/partition/partition.hpp"
#include "petersen/quadrangulate/triangle_prices.hpp"

namespace petersen {

namespace {

constexpr std::uint32_t kAbsent = 0xFFFFFFFFu;

// Seam face indices by face id. Throws std::invalid_argument for a face given twice, and for
// a price past kMaxCost or a dual past 2^61 in magnitude (the sums of two duals and a doubled
// cost, or a dual and four prices, stay inside 64 bits).
struct SeamIndex {
  std::pmr::vector<std::uint32_t> by_face;
  std::span<const SeamFace> faces;

  explicit SeamIndex(std::span<const SeamFace> seam) : faces(seam) {
    constexpr std::int64_t kMaxDual = std::int64_t{1} << 61;
    auto within = [](std::int64_t x, std::int64_t bound) { return x >= -bound && x <= bound; };
    for (const SeamFace& f : faces) {
      if (!within(f.price, kMaxCost) || !within(f.dual[0], kMaxDual) ||
          !within(f.dual[1], kMaxDual) || !within(f.stay_dual, kMaxDual)) {
        throw std::invalid_argument("pair_seams: face " + std::to_string(f.face) +
                                    " has a price or dual out of range");
      }
    }
    by_face.resize(faces.size());
    for (std::uint32_t i = 0; i < faces.size(); ++i) by_face[i] = i;
    std::sort(by_face.begin(), by_face.end(),
              [&](std::uint32_t x, std::uint32_t y) { return faces[x].face < faces[y].face; });
    for (std::size_t i = 1; i < by_face.size(); ++i) {
      if (faces[by_face[i]].face == faces[by_face[i - 1]].face) {
        throw std::invalid_argument("pair_seams: face " + std::to_string(faces[by_face[i]].face) +
                                    " is twice in the seams");
      }
    }
  }
  std::uint32_t find(FaceId face) const {
    const auto it = std::lower_bound(by_face.begin(), by_face.end(), face,
                                     [&](std::uint32_t i, FaceId f) { return faces[i].face < f; });
    return it != by_face.end() && faces[*it].face == face ? *it : kAbsent;
  }
  std::uint32_t at(FaceId face) const {
    const std::uint32_t i = find(face);
    if (i == kAbsent) {
      throw std::invalid_argument("pair_seams: face " + std::to_string(face) +
                                  " of a cut adjacency is no seam face");
    }
    return i;
  }
};

// The candidate edges, each as two seam faces (the lower face first): the cut adjacencies, then
// the pairable sides inside a part between two seam faces. O(s log s).
std::pmr::vector<std::array<std::uint32_t, 2>> candidate_edges(
    const SeamIndex& index, std::span<const CutAdjacency> adjacencies) {
  std::pmr::vector<std::array<std::uint32_t, 2>> ends;
  for (const CutAdjacency& a : adjacencies) ends.push_back({index.at(a.first), index.at(a.second)});
  struct Side {
    VertexId low, high;
    std::uint32_t face;
  };
  std::pmr::vector<Side> sides;
  for (std::uint32_t i = 0; i < index.faces.size(); ++i) {
    const SeamFace& f = index.faces[i];
    for (int k = 0; k < 3; ++k) {
      if (f.sides[k] != SideState::pairable) continue;
      const VertexId a = f.corners[k], b = f.corners[(k + 1) % 3];
      sides.push_back({std::min(a, b), std::max(a, b), i});
    }
  }
  std::sort(sides.begin(), sides.end(), [&](const Side& x, const Side& y) {
    return x.low != y.low     ? x.low < y.low
           : x.high != y.high ? x.high < y.high
                              : index.faces[x.face].face < index.faces[y.face].face;
  });
  for (std::size_t i = 0; i + 1 < sides.size(); ++i) {
    if (sides[i].low == sides[i + 1].low && sides[i].high == sides[i + 1].high) {
      ends.push_back({sides[i].face, sides[i + 1].face});
      ++i;
    }
  }
  return ends;
}

// Each candidate edge's quad cost in degrees, or NaN where the pair is refused: the edges as a
// mesh of two triangles each, so that the cut and the measure are quadrangulate's own
// (build_pairable_graph with the sharp angle, pairable_edge_quality from the lower face), then
// the corner threshold. The edges are independent, so they are measured `batch` at a time (at
// least one): the meshes of all at once would outweigh the seam faces. O(a).
std::pmr::vector<double> measure(const SeamIndex& index,
                                 std::span<const std::array<std::uint32_t, 2>> ends,
                                 const PartCosts& costs, std::size_t batch, std::uint32_t threads) {
  const std::size_t chunk = std::max<std::size_t>(1, batch);
  std::pmr::vector<double> degrees(ends.size(), std::nan(""));
  CutOptions cuts;
  cuts.sharp_angle_degrees = costs.sharp_angle_degrees;
  PolygonMesh mesh;
  for (std::size_t first = 0; first < ends.size(); first += chunk) {
    const std::size_t a = std::min(chunk, ends.size() - first);
    mesh.positions.resize(4 * a);
    mesh.corners.resize(6 * a);
    for (std::size_t i = 0; i < a; ++i) {
      const SeamFace& low = index.faces[ends[first + i][0]];
      const SeamFace& high = index.faces[ends[first + i][1]];
      const VertexId base = static_cast<VertexId>(4 * i);
      for (int k = 0; k < 3; ++k) {
        mesh.corners[6 * i + k] = base + k;
        mesh.positions[base + k] = low.positions[k];
      }
      for (int k = 0; k < 3; ++k) {
        const auto* shared = std::find(low.corners.begin(), low.corners.end(), high.corners[k]);
        const VertexId local =
            shared != low.corners.end() ? base + VertexId(shared - low.corners.begin()) : base + 3;
        mesh.corners[6 * i + 3 + k] = local;
        mesh.positions[local] = high.positions[k];
      }
    }
    const PairableGraph graph = build_pairable_graph(mesh, cuts, threads);
    const std::pmr::vector<double> measured = pairable_edge_quality(graph, mesh, threads);
    for (EdgeId e = 0; e < graph.edge_count(); ++e) {
      if (!costs.max_corner_deviation || measured[e] <= *costs.max_corner_deviation) {
        degrees[first + graph.edge_ends[2 * e] / 2] = measured[e];
      }
    }
  }
  return degrees;
}

// Each seam face's price for staying unpaired in the whole mesh. triangle_prices reads a face's
// two rings: a face within one step of an open side may have pairs or neighbours across the cut
// that its part did not see, so it is priced again over the seam faces and the allowed candidate
// edges, which hold its two rings whole (the band reaches 3 steps, see pair_part); any other
// face's rings lie inside its part, which priced it as the whole mesh does. O(s + a).
std::pmr::vector<Cost> whole_mesh_prices(const SeamIndex& index,
                                         std::span<const std::array<std::uint32_t, 2>> ends,
                                         std::span<const double> degrees,
                                         std::span<const Cost> units, Cost price) {
  std::pmr::vector<NodeId> allowed;
  std::pmr::vector<Cost> allowed_units;
  for (std::size_t i = 0; i < ends.size(); ++i) {
    if (std::isnan(degrees[i])) continue;
    allowed.insert(allowed.end(), ends[i].begin(), ends[i].end());
    allowed_units.push_back(units[i]);
  }
  std::pmr::vector<Cost> prices = triangle_prices(static_cast<std::uint32_t>(index.faces.size()),
                                                  allowed, allowed_units, price);
  for (std::size_t i = 0; i < index.faces.size(); ++i) {
    if (index.faces[i].distance > 1) prices[i] = index.faces[i].price;
  }
  return prices;
}

// The stitched duals' loss. First each stay edge v–v' whose whole-mesh price is below its part's,
// violated by the part's duals (SeamFace::stay_dual against 4·price, the certificate's units),
// lowers v's node dual by the violation; then each cut adjacency's constraint in each copy of the
// doubled graph, violated by the parts' duals, lowers its lower face's node dual by what is left
// of the violation after the lowerings already made at its two ends.
std::int64_t dual_lowering(const SeamIndex& index,
                           std::span<const std::array<std::uint32_t, 2>> cross,
                           std::span<const double> degrees, std::span<const Cost> units,
                           std::span<const Cost> prices) {
  std::pmr::vector<std::array<std::int64_t, 2>> lowered(index.faces.size(), {0, 0});
  std::int64_t total = 0;
  for (std::size_t i = 0; i < index.faces.size(); ++i) {
    const std::int64_t left = index.faces[i].stay_dual - 4 * prices[i];
    if (left > 0) {
      lowered[i][0] = left;
      total += left;
    }
  }
  for (std::size_t i = 0; i < cross.size(); ++i) {
    if (std::isnan(degrees[i])) continue;
    const auto [x, y] = cross[i];
    for (int k = 0; k < 2; ++k) {
      const std::int64_t left = index.faces[x].dual[k] + index.faces[y].dual[k] - 2 * units[i] -
                                lowered[x][k] - lowered[y][k];
      if (left > 0) {
        lowered[x][k] += left;
        total += left;
      }
    }
  }
  return total;
}

// The seam graph: the seam faces near a cut and not held (paired outside the seams), the allowed
// candidate edges between two of them, and each node's current partner node (kAbsent: unpaired).
struct SeamGraph {
  std::pmr::vector<std::uint32_t> face_of;  // seam face of each node
  std::pmr::vector<std::uint32_t> mate;     // current partner node
  std::pmr::vector<std::array<NodeId, 2>> edges;
  std::pmr::vector<Cost> units;
  std::pmr::vector<std::uint8_t> across;  // the edge is a cut adjacency
};

// The seam faces within the bands' depth of a cut adjacency, in steps across the allowed edges
// (the bands also reach around the true boundary, whose faces no cut concerns), with the partners
// of those reached, so that a pair is in or out whole: a breadth-first search from the
// adjacencies' ends. O(s + e).
std::pmr::vector<std::uint8_t> near_cuts(const SeamIndex& index,
                                         std::span<const std::array<std::uint32_t, 2>> ends,
                                         std::size_t cross, std::span<const double> degrees) {
  const std::size_t s = index.faces.size();
  std::uint32_t depth = 0;
  for (const SeamFace& f : index.faces) depth = std::max(depth, f.distance);
  std::pmr::vector<std::array<std::uint32_t, 3>> next(s, {kAbsent, kAbsent, kAbsent});
  auto link = [&](std::uint32_t a, std::uint32_t b) {
    for (std::uint32_t& slot : next[a]) {
      if (slot == kAbsent) {
        slot = b;
        return;
      }
    }
  };
  for (std::size_t i = cross; i < ends.size(); ++i) {
    if (std::isnan(degrees[i])) continue;
    link(ends[i][0], ends[i][1]);
    link(ends[i][1], ends[i][0]);
  }
  std::pmr::vector<std::uint32_t> distance(s, kAbsent), queue;
  for (std::size_t i = 0; i < cross; ++i) {
    for (std::uint32_t f : ends[i]) {
      if (distance[f] == kAbsent) {
        distance[f] = 0;
        queue.push_back(f);
      }
    }
  }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::uint32_t f = queue[head];
    if (distance[f] == depth) continue;
    for (std::uint32_t g : next[f]) {
      if (g == kAbsent || distance[g] != kAbsent) continue;
      distance[g] = distance[f] + 1;
      queue.push_back(g);
    }
  }
  std::pmr::vector<std::uint8_t> near(s, 0);
  for (std::uint32_t f : queue) {
    near[f] = 1;
    const std::uint32_t p =
        index.faces[f].partner == kNoFace ? kAbsent : index.find(index.faces[f].partner);
    if (p != kAbsent) near[p] = 1;
  }
  return near;
}

SeamGraph seam_graph(const SeamIndex& index, std::span<const std::array<std::uint32_t, 2>> ends,
                     std::size_t cross, std::span<const double> degrees,
                     std::span<const Cost> units) {
  SeamGraph g;
  const std::pmr::vector<std::uint8_t> near = near_cuts(index, ends, cross, degrees);
  std::pmr::vector<std::uint32_t> node_of(index.faces.size(), kAbsent);
  for (std::uint32_t i = 0; i < index.faces.size(); ++i) {
    const FaceId p = index.faces[i].partner;
    if (!near[i] || (p != kNoFace && index.find(p) == kAbsent)) continue;
    node_of[i] = static_cast<std::uint32_t>(g.face_of.size());
    g.face_of.push_back(i);
  }
  g.mate.assign(g.face_of.size(), kAbsent);
  for (NodeId v = 0; v < g.face_of.size(); ++v) {
    const FaceId p = index.faces[g.face_of[v]].partner;
    if (p != kNoFace) g.mate[v] = node_of[index.find(p)];
  }
  for (std::size_t i = 0; i < ends.size(); ++i) {
    const std::uint32_t a = node_of[ends[i][0]], b = node_of[ends[i][1]];
    if (std::isnan(degrees[i]) || a == kAbsent || b == kAbsent) continue;
    g.edges.push_back({a, b});
    g.units.push_back(units[i]);
    g.across.push_back(i < cross);
  }
  return g;
}

// The current pairs' total in the seam graph (quads: with the price of each unpaired node, by
// seam graph node; empty for quality). Throws std::logic_error for a pair that is no edge of it:
// the parts paired only allowed edges.
Cost current_total(const SeamGraph& g, const CsrGraph& graph, std::span<const Cost> units,
                   std::span<const Cost> prices) {
  Cost total = 0;
  for (NodeId v = 0; v < graph.node_count(); ++v) {
    const std::uint32_t w = g.mate[v];
    if (w == kAbsent) {
      total += prices.empty() ? 0 : prices[v];
      continue;
    }
    if (w < v) continue;
    Cost cheapest = -1;
    for (EdgeId e : graph.incident_edges(v)) {
      if (graph.other_end(e, v) == w && (cheapest < 0 || units[e] < cheapest)) cheapest = units[e];
    }
    if (cheapest < 0) {
      throw std::logic_error(
          "internal error: a part paired two seam faces that no allowed edge "
          "joins");
    }
    total += cheapest;
  }
  return total;
}

// The seam graph's components in batches of whole components, each at least `batch_faces`
// nodes but the last (SeamInput::batch_faces): the whole optimum is the union of the components'
// optima, and each solve holds only its batch (every cut's band at once, at 10^9 triangles, would
// hold tens of millions of faces). Components in the order of their first nodes, their nodes
// ascending, so the batches do not depend on the threads. O(s + e).
template <class Visit>
void for_each_batch(const CsrGraph& graph, std::uint32_t batch_faces, Visit visit) {
  const std::uint32_t n = graph.node_count();
  ComponentForest forest(n, graph.edge_ends());
  std::pmr::vector<NodeId> root_of(n);
  std::pmr::vector<std::uint32_t> size(n, 0), begin(n, 0);  // by root (0 for the other nodes)
  for (NodeId v = 0; v < n; ++v) ++size[root_of[v] = forest.find(v)];
  for (NodeId r = 0, at = 0; r < n; at += size[r], ++r) begin[r] = at;
  std::pmr::vector<NodeId> order(n);
  std::pmr::vector<std::uint32_t> next = begin;
  for (NodeId v = 0; v < n; ++v) order[next[root_of[v]]++] = v;
  std::size_t first = 0, last = 0;
  for (NodeId r = 0; r < n; ++r) {
    if (root_of[r] != r) continue;  // the roots, ascending: the components in order
    last = begin[r] + size[r];
    if (last - first >= batch_faces) {
      visit(std::span<const NodeId>(order.data() + first, last - first));
      first = last;
    }
  }
  if (last > first) visit(std::span<const NodeId>(order.data() + first, last - first));
}

// One batch's minimum-cost matching (quads: leaving node v costs prices[v], by seam graph node;
// quality, `prices` empty: the cheapest maximum), its certificate checked, its pairs written into
// `matching` in the seam graph's edge ids. Returns the batch's total in the solver's units.
// `local` maps the seam graph's nodes to the batch's (any value outside the batch).
Cost solve_batch(const CsrGraph& graph, std::span<const Cost> units, std::span<const NodeId> nodes,
                 std::span<const Cost> prices, std::uint32_t threads,
                 std::pmr::vector<NodeId>& local, Matching& matching) {
  const bool quads = !prices.empty();
  std::pmr::vector<Cost> batch_prices;
  for (NodeId i = 0; i < nodes.size(); ++i) {
    local[nodes[i]] = i;
    if (quads) batch_prices.push_back(prices[nodes[i]]);
  }
  std::pmr::vector<std::array<NodeId, 2>> edges;
  std::pmr::vector<EdgeId> edge_of;
  std::pmr::vector<Cost> batch_units;
  for (const NodeId v : nodes) {
    for (const EdgeId e : graph.incident_edges(v)) {
      const NodeId w = graph.other_end(e, v);
      if (v > w) continue;  // each edge once, from its lower end (a batch holds whole components)
      edges.push_back({local[v], local[w]});
      edge_of.push_back(e);
      batch_units.push_back(units[e]);
    }
  }
  const CsrGraph batch = CsrGraph::from_edges(static_cast<std::uint32_t>(nodes.size()), edges);
  auto checked = [](const CertificateCheck& check, const char* pairing) {
    if (!check.ok()) {
      throw std::logic_error(std::string("internal error: the seams' ") + pairing +
                             " fails its certificate: " + check.problem);
    }
  };
  Matching found;
  Cost total = 0;
  if (quads) {
    MinCostMatchingResult r =
        min_cost_matching(batch, batch_units, batch_prices, {.threads = threads});
    checked(verify_min_cost_matching(batch.node_count(), batch.edge_ends(), batch_units,
                                     batch_prices, r.matching, r.total, r.certificate),
            "least-cost pairing");
    total = r.total;
    found = std::move(r.matching);
  } else {
    MinCostMaximumResult r = min_cost_maximum_matching(batch, batch_units, {.threads = threads});
    checked(
        verify_min_cost_maximum_matching(batch.node_count(), batch.edge_ends(), batch_units,
                                         r.matching, r.total_cost, r.unmatched_cost, r.certificate),
        "cheapest maximum pairing");
    total = r.total_cost;
    found = std::move(r.matching);
  }
  for (NodeId i = 0; i < nodes.size(); ++i) {
    const EdgeId e = found.mate_edge[i];
    matching.mate_edge[nodes[i]] = e == kNoEdge ? kNoEdge : edge_of[e];
  }
  return total;
}

}  // namespace

SeamResult pair_seams(const SeamInput& input, const PartCosts& costs, std::uint32_t threads) {
  const Stopwatch clock;
  if (costs.objective == Objective::pairs) {
    throw std::invalid_argument("pair_seams: Objective::pairs repairs by repair_cuts");
  }
  const SeamIndex index(input.faces);
  const std::pmr::vector<std::array<std::uint32_t, 2>> ends =
      candidate_edges(index, input.adjacencies);
  const std::pmr::vector<double> degrees = measure(index, ends, costs, input.batch_faces, threads);
  std::pmr::vector<double> finite(degrees.size(), 0.0);
  for (std::size_t i = 0; i < degrees.size(); ++i)
    if (!std::isnan(degrees[i])) finite[i] = degrees[i];
  const std::pmr::vector<Cost> units = scale_costs(finite);
  const std::size_t cross = input.adjacencies.size();
  SeamResult result;
  // Objective::quads: each face's price in the whole mesh (quality: none).
  std::pmr::vector<Cost> prices;
  if (costs.objective == Objective::quads) {
    prices = whole_mesh_prices(index, ends, degrees, units,
                               std::llround(costs.triangle_cost * kDefaultCostScale));
    result.dual_lowering = dual_lowering(index, {ends.data(), cross}, degrees, units, prices);
  }
  result.partner.resize(index.faces.size());
  for (std::size_t i = 0; i < index.faces.size(); ++i) result.partner[i] = index.faces[i].partner;

  const SeamGraph g = seam_graph(index, ends, cross, degrees, units);
  const CsrGraph graph =
      CsrGraph::from_edges(static_cast<std::uint32_t>(g.face_of.size()), g.edges);
  result.seam_graph_faces = graph.node_count();
  result.seam_graph_edges = graph.edge_count();
  result.certified = true;
  if (graph.node_count() == 0) {
    result.seconds = clock.seconds();
    return result;
  }
  // The parts counted each face they left at their own price; the step pairs at the whole
  // mesh's, so that the change takes the total from the former to the latter.
  std::pmr::vector<Cost> part_prices, node_prices;
  if (costs.objective == Objective::quads) {
    for (std::uint32_t face : g.face_of) {
      part_prices.push_back(index.faces[face].price);
      node_prices.push_back(prices[face]);
    }
  }
  const Cost before = current_total(g, graph, g.units, part_prices);
  Matching matching(graph.node_count());
  Cost after = 0;
  std::pmr::vector<NodeId> local(graph.node_count());
  for_each_batch(graph, input.batch_faces, [&](std::span<const NodeId> nodes) {
    after += solve_batch(graph, g.units, nodes, node_prices, threads, local, matching);
  });
  result.objective_change = after - before;
  for (NodeId v = 0; v < graph.node_count(); ++v) {
    const EdgeId e = matching.mate_edge[v];
    const NodeId w = e == kNoEdge ? kNoNode : graph.other_end(e, v);
    result.partner[g.face_of[v]] = w == kNoNode ? kNoFace : index.faces[g.face_of[w]].face;
    result.pairs_across += e != kNoEdge && v < w && g.across[e];
  }
  result.seconds = clock.seconds();
  return result;
}

double lower_bound_degrees(Cost parts_units, std::int64_t dual_lowering) {
  return (double(parts_units) - double(dual_lowering) / 4) / kDefaultCostScale;
}

}  // namespace petersen
