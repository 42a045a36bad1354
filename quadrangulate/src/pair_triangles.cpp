#include "pair_triangles.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "lap_clock.hpp"
#include "pair_whole_mesh_by_lrs.hpp"
#include "petersen/graph/component_forest.hpp"
#include "petersen/graph/csr_graph.hpp"
#include "petersen/graph/parallel.hpp"
#include "petersen/lrs/lrs.hpp"
#include "petersen/matching/augment.hpp"
#include "petersen/matching/min_cost_matching.hpp"
#include "petersen/matching/perfect_partners.hpp"
#include "petersen/matching/tutte_berge.hpp"
#include "petersen/matching/verify_min_cost.hpp"

namespace petersen::quad_detail {

namespace {

void add_run(PerfectMatchingStats& total, const PerfectMatchingStats& run) {
  total.initial_seconds += run.initial_seconds;
  total.augment_seconds += run.augment_seconds;
  total.unpaired_after_initial += run.unpaired_after_initial;
  total.augmenting_paths += run.augmenting_paths;
  total.blossoms += run.blossoms;
  total.nodes_labelled += run.nodes_labelled;
  total.reductions += run.reductions;
  total.replacement_searches += run.replacement_searches;
  total.cover_swaps += run.cover_swaps;
  total.schrijver = total.schrijver || run.schrijver;              // some component matched by it
  total.ordered_sweep = total.ordered_sweep || run.ordered_sweep;  // some component paired by it
  for (int k = 0; k < 3; ++k) total.lift_cases[k] += run.lift_cases[k];
}

// Components of the pairable graph (disjoint sets over its edges), numbered in order of their
// first node, and whether each is closed: every node has three pairable sides.
struct Components {
  std::vector<std::uint32_t> of_node;
  std::vector<std::uint8_t> closed;
};

Components components_of(const PairableGraph& graph) {
  const std::uint32_t n = graph.node_count;
  ComponentForest forest(n, graph.edge_ends);
  auto find = [&](NodeId v) { return forest.find(v); };
  Components components;
  components.of_node.resize(n);
  std::vector<std::uint32_t> id_of_root(n, kNoNode);
  for (NodeId v = 0; v < n; ++v) {
    const NodeId root = find(v);
    if (id_of_root[root] == kNoNode) {
      id_of_root[root] = static_cast<std::uint32_t>(components.closed.size());
      components.closed.push_back(1);
    }
    components.of_node[v] = id_of_root[root];
  }
  for (NodeId v = 0; v < n; ++v) {
    for (int k = 0; k < 3; ++k) {
      if (graph.node_edges[3 * std::size_t{v} + k] == kNoEdge) {
        components.closed[components.of_node[v]] = 0;
      }
    }
  }
  return components;
}

// The subgraph induced by `nodes` (whole components, ascending), renumbered in their order.
// Its edges keep their relative order; local edge i is graph edge edge_of[i].
struct Subgraph {
  std::vector<NodeId> nodes;
  std::vector<EdgeId> edge_of;
  HugeVector<NodeId> edge_ends;
};

Subgraph induced(const PairableGraph& graph, std::vector<NodeId> nodes) {
  Subgraph sub;
  std::vector<NodeId> local(graph.node_count, kNoNode);
  for (NodeId i = 0; i < nodes.size(); ++i) local[nodes[i]] = i;
  // Counted first, so that the arrays are made at their size: grown by doubling, they held up to
  // twice that, and three times while moving (part of an open mesh's 149 bytes per triangle).
  std::size_t edges = 0;
  for (EdgeId e = 0; e < graph.edge_count(); ++e) edges += local[graph.edge_ends[2 * e]] != kNoNode;
  sub.edge_of.reserve(edges);
  sub.edge_ends.reserve(2 * edges);
  for (EdgeId e = 0; e < graph.edge_count(); ++e) {
    const NodeId a = local[graph.edge_ends[2 * e]];
    if (a == kNoNode) continue;
    sub.edge_of.push_back(e);
    sub.edge_ends.push_back(a);
    sub.edge_ends.push_back(local[graph.edge_ends[2 * e + 1]]);
  }
  sub.nodes = std::move(nodes);
  return sub;
}

// A closed component as a triangle mesh on its own vertices, for lrs.
struct ComponentMesh {
  TriangleMesh mesh;
  std::vector<VertexId> vertex_of;  // local vertex -> input vertex; empty: the same ids
  VertexId input_vertex(VertexId v) const { return vertex_of.empty() ? v : vertex_of[v]; }
};

ComponentMesh component_mesh(const PolygonMesh& mesh, const PairableGraph& graph,
                             std::span<const NodeId> nodes, std::vector<VertexId>& local) {
  ComponentMesh part;
  if (nodes.size() == graph.node_count && mesh.all_triangles()) {
    // The whole mesh is one closed component (the common case): no renumbering.
    part.mesh.positions = mesh.positions;
    part.mesh.triangles.resize(nodes.size());
    for (NodeId v = 0; v < nodes.size(); ++v) {
      const auto corners = mesh.face(v);
      part.mesh.triangles[v] = {corners[0], corners[1], corners[2]};
    }
    return part;
  }
  part.mesh.triangles.reserve(nodes.size());
  for (NodeId v : nodes) {
    const auto corners = mesh.face(graph.face_of(v));
    std::array<VertexId, 3> triangle;
    for (int k = 0; k < 3; ++k) {
      VertexId& id = local[corners[k]];
      if (id == kNoNode) {
        id = static_cast<VertexId>(part.vertex_of.size());
        part.vertex_of.push_back(corners[k]);
        part.mesh.positions.push_back(mesh.positions[corners[k]]);
      }
      triangle[k] = id;
    }
    part.mesh.triangles.push_back(triangle);
  }
  for (VertexId v : part.vertex_of) local[v] = kNoNode;
  return part;
}

// The input triangle behind each of K's triangles (kNoFace for one its flips made): K's faces are
// numbered anew (spatially), so an unflipped one is found by its vertex set, among the input
// triangles bucketed by their smallest vertex (a counting sort; the buckets hold a few each).
std::vector<FaceId> input_faces_of(const TriangleMesh& part, std::span<const NodeId> nodes,
                                   const PairableGraph& graph, const TriangleMesh& k_mesh) {
  auto sorted = [](std::array<VertexId, 3> t) {
    std::sort(t.begin(), t.end());
    return t;
  };
  std::vector<std::uint32_t> start(part.positions.size() + 1, 0);
  for (const auto& t : part.triangles) ++start[sorted(t)[0] + 1];
  for (std::size_t v = 0; v < part.positions.size(); ++v) start[v + 1] += start[v];
  std::vector<std::uint32_t> bucket(part.triangles.size());
  {
    std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
    for (std::uint32_t i = 0; i < part.triangles.size(); ++i) {
      bucket[next[sorted(part.triangles[i])[0]]++] = i;
    }
  }
  std::vector<FaceId> input_face(k_mesh.triangles.size(), kNoFace);
  for (FaceId f = 0; f < k_mesh.triangles.size(); ++f) {
    const auto t = sorted(k_mesh.triangles[f]);
    for (std::uint32_t j = start[t[0]]; j < start[t[0] + 1]; ++j) {
      if (sorted(part.triangles[bucket[j]]) == t) {
        input_face[f] = graph.face_of(nodes[bucket[j]]);
        break;
      }
    }
  }
  return input_face;
}

// Runs lrs on one closed component; appends its quads with their input faces. Returns false,
// with the reason, when lrs cannot take the component.
bool pair_by_lrs(const PolygonMesh& mesh, const PairableGraph& graph, std::span<const NodeId> nodes,
                 const QuadOptions& options, std::vector<VertexId>& local, TrianglePairing& pairing,
                 QuadStats& stats) {
  if (mesh.attributes.has_corner_attributes() || mesh.attributes.has_face_attributes()) {
    // A triangle lrs's flips make has no input corners or face to take these from.
    if (stats.lrs_fallback_components++ == 0) {
      stats.lrs_fallback_reason =
          "a mesh without texture coordinates, normals or face attributes (its flipped triangles "
          "would have none)";
    }
    return false;
  }
  ComponentMesh part = component_mesh(mesh, graph, nodes, local);
  LrsResult result;
  try {
    result = quadrangulate_lrs(part.mesh, {.augment = options.augment});
  } catch (const MeshError& e) {
    // Its surface check: lrs needs a connected, orientable manifold (no pinched vertex).
    if (stats.lrs_fallback_components++ == 0) stats.lrs_fallback_reason = e.what();
    return false;
  }
  // The quads are made from a perfect matching of K's dual, so the verifier's word on the
  // matching is all they need; K itself is checked by lrs's tests.
  if (MatchingCheck check = verify_perfect_matching(result.dual, result.matching); !check.ok()) {
    throw std::logic_error("internal error: lrs returned a matching that is not perfect: " +
                           check.message);
  }
  stats.matching.initial_seconds +=
      result.stats.contraction_seconds + result.stats.expansion_seconds;
  stats.matching.augment_seconds += result.stats.augment_seconds;
  stats.matching.unpaired_after_initial += result.stats.unpaired_after_expansion;
  stats.matching.augmenting_paths += result.stats.augmenting_paths;
  stats.flipped_edges += result.stats.flipped_edges;
  stats.irreducible_vertices += result.stats.irreducible_vertices;
  const auto& k_triangles = result.flipped_mesh.triangles;
  const std::vector<FaceId> input_face_of =
      input_faces_of(part.mesh, nodes, graph, result.flipped_mesh);
  // quads_from_matching makes one quad per matched edge, in order of its first triangle.
  std::size_t q = 0;
  for (FaceId t = 0; t < k_triangles.size(); ++t) {
    const auto [t1, t2] = result.dual.endpoints(result.matching.mate_edge[t]);
    if (t != t1) continue;
    LrsQuad quad;
    for (int k = 0; k < 4; ++k) quad.corners[k] = part.input_vertex(result.quads.quads[q][k]);
    quad.sources = {input_face_of[t1], input_face_of[t2]};
    pairing.lrs_quads.push_back(quad);
    ++q;
  }
  for (NodeId v : nodes) pairing.partner[v] = kLrsNode;
  return true;
}

// Closed components by `algorithm` (perfect, by Petersen's theorem), or with `costs` by the
// exact minimum-cost perfect matching; verified, and its certificate checked. `beside_verifier`
// runs on another thread (given options.threads > 1) while the matching is verified: work that
// needs neither the matching nor the matching's memory, which is freed by then.
template <class BesideVerifier>
void pair_closed(const CubicGraph& cubic, std::span<const NodeId> node_of,
                 std::span<const Cost> costs, const QuadOptions& options, Algorithm algorithm,
                 TrianglePairing& pairing, QuadStats& stats, LapClock& clock,
                 BesideVerifier beside_verifier) {
  Matching matching;
  std::string name(to_string(algorithm));
  if (costs.empty()) {
    // No bridge test: a bridge would leave a set of triangles whose only boundary is one edge,
    // but a boundary (mod 2) has no ends, and one edge has two.
    PerfectMatchingResult result = perfect_matching(cubic, {.algorithm = algorithm,
                                                            .augment = options.augment,
                                                            .seed = options.seed,
                                                            .validate = false,
                                                            .peer = options.peer});
    add_run(stats.matching, result.stats);
    matching = std::move(result.matching);
    clock.lap();
  } else {
    name = "the minimum-cost matching";
    MinCostResult result = min_cost_perfect_matching(cubic, costs, {.threads = options.threads});
    stats.matching.initial_seconds += result.stats.init_seconds;
    stats.matching.unpaired_after_initial += result.stats.free_after_init;
    stats.matching.augment_seconds +=
        result.stats.search_seconds + result.stats.certificate_seconds;
    stats.matching.augmenting_paths += result.stats.searches;
    stats.matching.blossoms += result.stats.blossoms_shrunk;
    stats.matching.nodes_labelled += result.stats.nodes_labelled;
    clock.lap();
    if (CertificateCheck check = verify_min_cost_perfect_matching(
            cubic.node_count(), cubic.edge_ends(), costs, result.matching, result.total_cost,
            result.certificate);
        !check.ok()) {
      throw std::logic_error("internal error: the minimum-cost matching's certificate fails: " +
                             check.problem);
    }
    pairing.objective_units += result.total_cost;
    matching = std::move(result.matching);
  }
  MatchingCheck check;
  run_parallel(options.threads, 2, [&](std::uint32_t task) {
    if (task == 0) {
      check = verify_perfect_matching(cubic, matching);
    } else {
      beside_verifier();
    }
  });
  if (!check.ok()) {
    throw std::logic_error("internal error: " + name +
                           " returned a matching that is not perfect: " + check.message);
  }
  if (node_of.empty()) {
    // The whole graph: the partners are written over the mate edges, each from its own entry,
    // so that no second array of n entries is live beside the graph.
    pairing.partner = std::move(matching.mate_edge);
    for (NodeId v = 0; v < cubic.node_count(); ++v) {
      pairing.partner[v] = cubic.other_end(pairing.partner[v], v);
    }
  } else {
    for (NodeId v = 0; v < cubic.node_count(); ++v) {
      pairing.partner[node_of[v]] = node_of[cubic.other_end(matching.mate_edge[v], v)];
    }
  }
  stats.verify_seconds += clock.lap();
}

// The common case, ps on a closed mesh, on one adjacency: the graph becomes its neighbour rows
// in place and the matching runs on them alone, so at its peak it holds the mesh (24 bytes per
// triangle), the rows (12), the search state (16) and the partners (4). perfect_matching holds
// the graph (24), its table (28) and the mate edges (4) at once, 80 bytes per triangle with the
// mesh before PS's own sets: over the 64 the tool aims at (issue 15). The same pairs, checked
// against the same adjacency.
// The components are counted on the edge list while the rows are written over the incidences,
// not before: each is a single-threaded pass of random reads (on armadillo-sub2 about 0.03 s
// together, one after the other), and the forest (4 bytes per node) is still gone before the
// matching's peak.
void pair_by_partners(CubicGraph cubic, Algorithm algorithm, const QuadOptions& options,
                      TrianglePairing& pairing, QuadStats& stats, LapClock& clock) {
  const std::uint32_t node_count = cubic.node_count();
  const HugeVector<NodeId> rows =
      std::move(cubic).into_neighbour_rows(options.threads, [&](std::span<const NodeId> edge_ends) {
        stats.components = stats.closed_components =
            ComponentForest(node_count, edge_ends).root_count();
      });
  stats.dual_seconds += clock.lap();
  PartnerResult result = perfect_partners(
      rows, {.algorithm = algorithm, .augment = options.augment, .seed = options.seed});
  add_run(stats.matching, result.stats);
  clock.lap();
  if (MatchingCheck check = verify_perfect_partners(rows, result.partner); !check.ok()) {
    throw std::logic_error("internal error: ps returned a matching that is not perfect: " +
                           check.message);
  }
  pairing.partner = std::move(result.partner);
  stats.verify_seconds += clock.lap();
}

}  // namespace

TrianglePairing pair_triangles(PairableGraph& graph, const PolygonMesh& mesh,
                               HugeVector<VertexId>* releasable_corners,
                               std::span<const double> degrees, const QuadOptions& options,
                               QuadStats& stats) {
  LapClock clock;
  TrianglePairing pairing;
  const std::uint32_t n = graph.node_count;
  const Algorithm closed_algorithm =
      options.algorithm == Algorithm::lrs ? Algorithm::automatic : options.algorithm;
  const bool quality = options.objective == Objective::quality;
  // lrs flips edges, making quads the threshold never judged: with one, ps does its work.
  bool use_lrs = options.algorithm == Algorithm::lrs && !quality && !options.max_corner_deviation;
  const HugeVector<Cost> costs = quality ? scale_costs(degrees) : HugeVector<Cost>{};
  stats.dual_seconds += clock.lap();

  // lrs on a whole closed mesh (the common case) builds its triangulation from the graph itself.
  if (use_lrs && graph.cubic && graph.inconsistent_edges == 0 && mesh.all_triangles() &&
      !mesh.attributes.has_corner_attributes() && !mesh.attributes.has_face_attributes() &&
      ComponentForest(n, graph.edge_ends).root_count() == 1) {
    stats.components = stats.closed_components = 1;
    try {
      pair_whole_mesh_by_lrs(graph, mesh, releasable_corners, options, pairing, stats, clock);
      stats.maximum_certified = true;
      return pairing;
    } catch (const MeshError& e) {
      // A pinched vertex: ps pairs the mesh instead, on the graph made again. No cut touched this
      // mesh (every side of every triangle is pairable), so it is the graph built before.
      stats.lrs_fallback_components = 1;
      stats.lrs_fallback_reason = e.what();
      PairableGraph again = build_pairable_graph(mesh, {}, options.threads);
      graph.node_edges = std::move(again.node_edges);
      graph.edge_ends = std::move(again.edge_ends);
      use_lrs = false;
    }
  }

  // The common case, a closed triangle mesh matched by a graph algorithm: the pairable graph is
  // the cubic dual itself.
  if (graph.cubic && !use_lrs) {
    if ((closed_algorithm == Algorithm::automatic || closed_algorithm == Algorithm::ps) &&
        costs.empty()) {
      pair_by_partners(
          CubicGraph::from_valid_incidence(std::move(graph.node_edges), std::move(graph.edge_ends)),
          closed_algorithm, options, pairing, stats, clock);
    } else {
      CubicGraph cubic =
          CubicGraph::from_valid_incidence(std::move(graph.node_edges), std::move(graph.edge_ends));
      stats.dual_seconds += clock.lap();
      // Only their number, without per-node ids (on armadillo-sub2 their two fresh arrays were
      // most of the run's 4 KiB page faults), counted while the matching is verified: on
      // armadillo-sub2 each takes about 0.02 s, and the count was most of the dual phase.
      pair_closed(cubic, {}, costs, options, closed_algorithm, pairing, stats, clock, [&] {
        stats.components = stats.closed_components =
            ComponentForest(cubic.node_count(), cubic.edge_ends()).root_count();
      });
    }
    stats.maximum_certified = true;
    stats.optimality_certified = quality;
    return pairing;
  }

  pairing.partner.assign(n, kNoNode);
  Components components = components_of(graph);
  stats.components = components.closed.size();
  std::vector<NodeId> closed_nodes, open_nodes;
  for (NodeId v = 0; v < n; ++v) {
    (components.closed[components.of_node[v]] ? closed_nodes : open_nodes).push_back(v);
  }
  for (std::uint8_t closed : components.closed) stats.closed_components += closed;

  if (use_lrs && !closed_nodes.empty()) {
    // Each closed component on its own; those lrs cannot take stay for ps.
    std::vector<NodeId> by_component = closed_nodes;
    std::stable_sort(by_component.begin(), by_component.end(), [&](NodeId a, NodeId b) {
      return components.of_node[a] < components.of_node[b];
    });
    std::vector<VertexId> local(mesh.positions.size(), kNoNode);
    std::vector<NodeId> left_for_ps;
    const double matching_before = stats.matching.matching_seconds();
    for (std::size_t first = 0; first < by_component.size();) {
      std::size_t last = first + 1;
      const std::uint32_t c = components.of_node[by_component[first]];
      while (last < by_component.size() && components.of_node[by_component[last]] == c) ++last;
      const std::span<const NodeId> nodes(by_component.data() + first, last - first);
      if (!pair_by_lrs(mesh, graph, nodes, options, local, pairing, stats)) {
        left_for_ps.insert(left_for_ps.end(), nodes.begin(), nodes.end());
      }
      first = last;
    }
    std::sort(left_for_ps.begin(), left_for_ps.end());
    closed_nodes = std::move(left_for_ps);
    // Beside its phases, lrs builds its triangulation and K's dual: set-up, like a dual.
    stats.dual_seconds += clock.lap() - (stats.matching.matching_seconds() - matching_before);
  }
  components = Components();

  if (!closed_nodes.empty()) {
    Subgraph sub = induced(graph, std::move(closed_nodes));
    HugeVector<EdgeId> node_edges(3 * sub.nodes.size());
    std::vector<EdgeId> local_edge(graph.edge_count(), kNoEdge);
    for (EdgeId i = 0; i < sub.edge_of.size(); ++i) local_edge[sub.edge_of[i]] = i;
    for (NodeId i = 0; i < sub.nodes.size(); ++i) {
      for (int k = 0; k < 3; ++k) {
        node_edges[3 * std::size_t{i} + k] =
            local_edge[graph.node_edges[3 * std::size_t{sub.nodes[i]} + k]];
      }
    }
    const CubicGraph cubic =
        CubicGraph::from_valid_incidence(std::move(node_edges), std::move(sub.edge_ends));
    HugeVector<Cost> local_costs;
    if (quality) {
      for (EdgeId e : sub.edge_of) local_costs.push_back(costs[e]);
    }
    stats.dual_seconds += clock.lap();
    pair_closed(cubic, sub.nodes, local_costs, options, closed_algorithm, pairing, stats, clock,
                [] {});
  }

  if (!open_nodes.empty()) {
    Subgraph sub = induced(graph, std::move(open_nodes));
    // From here on the open components' own arrays are all that is read: each copy is freed as
    // soon as the next is made, so that the search's state is not added to all of them.
    graph.node_edges = HugeVector<EdgeId>();
    graph.edge_ends = HugeVector<NodeId>();
    // And given back to the kernel, not kept by the pool: the CSR graph comes from malloc, which
    // would not reuse them (an open mesh of 1.38M triangles peaked 33 MB higher with them kept).
    huge_pages::release_retained();
    CsrGraph open;
    {
      std::vector<std::array<NodeId, 2>> edges(sub.edge_of.size());
      for (EdgeId i = 0; i < edges.size(); ++i) {
        edges[i] = {sub.edge_ends[2 * i], sub.edge_ends[2 * i + 1]};
      }
      sub.edge_ends = HugeVector<NodeId>();
      open = CsrGraph::from_edges(static_cast<std::uint32_t>(sub.nodes.size()), edges);
    }
    if (!quality) sub.edge_of = std::vector<EdgeId>();  // only the costs are looked up by it
    stats.dual_seconds += clock.lap();
    // The cardinality search runs in every case: its Tutte–Berge witness proves any matching of
    // its size maximum, the minimum-cost one included.
    MaximumMatchingResult result = maximum_matching(open, options.augment);
    // Its greedy pass is the initial pairing here; each augmenting path then paired two more.
    stats.matching.unpaired_after_initial += static_cast<std::uint32_t>(
        open.node_count() - 2 * (result.size - result.stats.augmenting_paths));
    stats.matching.augmenting_paths += result.stats.augmenting_paths;
    stats.matching.blossoms += result.stats.blossoms;
    stats.matching.nodes_labelled += result.stats.nodes_labelled;
    stats.matching.augment_seconds += clock.lap();
    if (quality) {
      HugeVector<Cost> local_costs;
      for (EdgeId e : sub.edge_of) local_costs.push_back(costs[e]);
      MinCostMaximumResult cheapest =
          min_cost_maximum_matching(open, local_costs, {.threads = options.threads});
      stats.matching.augment_seconds += clock.lap();
      if (CertificateCheck check = verify_min_cost_maximum_matching(
              open.node_count(), open.edge_ends(), local_costs, cheapest.matching,
              cheapest.total_cost, cheapest.unmatched_cost, cheapest.certificate);
          !check.ok()) {
        throw std::logic_error(
            "internal error: the minimum-cost maximum matching's certificate "
            "fails: " +
            check.problem);
      }
      pairing.objective_units += cheapest.total_cost;
      result.matching = std::move(cheapest.matching);
    }
    if (MatchingCheck check = verify_maximum_matching(open, result.matching, result.tutte_set);
        !check.ok()) {
      throw std::logic_error(
          "internal error: the pairing of the open components is not proved "
          "maximum: " +
          check.message);
    }
    for (NodeId i = 0; i < sub.nodes.size(); ++i) {
      const EdgeId e = result.matching.mate_edge[i];
      if (e != kNoEdge) pairing.partner[sub.nodes[i]] = sub.nodes[open.other_end(e, i)];
    }
    for (NodeId i : result.tutte_set) pairing.tutte_set.push_back(sub.nodes[i]);
    stats.verify_seconds += clock.lap();
  }
  stats.maximum_certified = true;
  stats.optimality_certified = quality;
  return pairing;
}

}  // namespace petersen::quad_detail
