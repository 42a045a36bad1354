// The seam step of the cost objectives (partition.hpp): the triangles the parts left beside a cut
// paired across it by a minimum-cost matching, and the parts' duals stitched into a lower bound.

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "petersen/dualize/quad_quality.hpp"
#include "petersen/graph/stopwatch.hpp"
#include "petersen/matching/verify_min_cost.hpp"
#include "petersen/partition/partition.hpp"

namespace petersen {

namespace {

constexpr std::uint32_t kAbsent = 0xFFFFFFFFu;

// Seam face indices by face id. Throws std::invalid_argument for a face given twice.
struct SeamIndex {
  std::vector<std::uint32_t> by_face;
  std::span<const SeamFace> faces;

  explicit SeamIndex(std::span<const SeamFace> seam) : faces(seam) {
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
    if (it == by_face.end() || faces[*it].face != face) {
      throw std::invalid_argument("pair_seams: face " + std::to_string(face) +
                                  " of a cut adjacency is no seam face");
    }
    return *it;
  }
};

// Each adjacency's two seam faces (the lower face first) and its quad's cost in degrees, or NaN
// where the pair is refused: the adjacencies as a mesh of two triangles each, so that the cut and
// the measure are quadrangulate's own (build_pairable_graph with the sharp angle,
// pairable_edge_quality from the lower face), then the corner threshold.
struct CrossEdges {
  std::vector<std::array<std::uint32_t, 2>> ends;
  std::vector<double> degrees;
};

CrossEdges measure(const SeamIndex& index, std::span<const CutAdjacency> adjacencies,
                   const PartCosts& costs, std::uint32_t threads) {
  CrossEdges cross;
  const std::size_t a = adjacencies.size();
  cross.ends.resize(a);
  cross.degrees.assign(a, std::nan(""));
  PolygonMesh mesh;
  mesh.positions.resize(4 * a);
  mesh.corners.resize(6 * a);
  for (std::size_t i = 0; i < a; ++i) {
    const SeamFace& low = index.faces[cross.ends[i][0] = index.find(adjacencies[i].first)];
    const SeamFace& high = index.faces[cross.ends[i][1] = index.find(adjacencies[i].second)];
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
  CutOptions cuts;
  cuts.sharp_angle_degrees = costs.sharp_angle_degrees;
  const PairableGraph graph = build_pairable_graph(mesh, cuts, threads);
  const HugeVector<double> degrees = pairable_edge_quality(graph, mesh, threads);
  for (EdgeId e = 0; e < graph.edge_count(); ++e) {
    const double d = degrees[e];
    if (!costs.max_corner_deviation || d <= *costs.max_corner_deviation) {
      cross.degrees[graph.edge_ends[2 * e] / 2] = d;
    }
  }
  return cross;
}

// The stitched duals' loss: each cross edge's constraint in each copy of the doubled graph,
// violated by the parts' duals, lowers its lower face's node dual by what is left of the
// violation after the lowerings already made at its two ends.
std::int64_t dual_lowering(const SeamIndex& index, const CrossEdges& cross,
                           std::span<const Cost> units) {
  std::vector<std::array<std::int64_t, 2>> lowered(index.faces.size(), {0, 0});
  std::int64_t total = 0;
  for (std::size_t i = 0, j = 0; i < cross.ends.size(); ++i) {
    if (std::isnan(cross.degrees[i])) continue;
    const Cost cost = units[j++];
    const auto [x, y] = cross.ends[i];
    for (int k = 0; k < 2; ++k) {
      const std::int64_t left = index.faces[x].dual[k] + index.faces[y].dual[k] - 2 * cost -
                                lowered[x][k] - lowered[y][k];
      if (left > 0) {
        lowered[x][k] += left;
        total += left;
      }
    }
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
  const CrossEdges cross = measure(index, input.adjacencies, costs, threads);
  std::vector<double> allowed;
  for (double d : cross.degrees)
    if (!std::isnan(d)) allowed.push_back(d);
  const HugeVector<Cost> units = scale_costs(allowed);
  SeamResult result;
  if (costs.objective == Objective::quads)
    result.dual_lowering = dual_lowering(index, cross, units);

  // The seam graph: the cross edges between two faces their parts left unpaired.
  std::vector<std::uint32_t> node_of(index.faces.size(), kAbsent);
  std::vector<std::uint32_t> face_of;
  std::vector<std::array<NodeId, 2>> edges;
  std::vector<Cost> edge_units;
  auto node = [&](std::uint32_t i) {
    if (node_of[i] == kAbsent) {
      node_of[i] = static_cast<std::uint32_t>(face_of.size());
      face_of.push_back(i);
    }
    return node_of[i];
  };
  for (std::size_t i = 0, j = 0; i < cross.ends.size(); ++i) {
    if (std::isnan(cross.degrees[i])) continue;
    const Cost cost = units[j++];
    const auto [x, y] = cross.ends[i];
    if (index.faces[x].paired || index.faces[y].paired) continue;
    edges.push_back({node(x), node(y)});
    edge_units.push_back(cost);
  }
  const CsrGraph graph = CsrGraph::from_edges(static_cast<std::uint32_t>(face_of.size()), edges);
  result.seam_graph_faces = graph.node_count();
  result.seam_graph_edges = graph.edge_count();
  result.certified = true;
  if (graph.node_count() == 0) {
    result.seconds = clock.seconds();
    return result;
  }
  Matching matching;
  if (costs.objective == Objective::quads) {
    const Cost price = static_cast<Cost>(std::llround(costs.triangle_cost * kDefaultCostScale));
    MinCostMatchingResult r =
        min_cost_matching(graph, edge_units, {&price, 1}, {.threads = threads});
    if (CertificateCheck check =
            verify_min_cost_matching(graph.node_count(), graph.edge_ends(), edge_units, {&price, 1},
                                     r.matching, r.total, r.certificate);
        !check.ok()) {
      throw std::logic_error(
          "internal error: the seams' least-cost pairing fails its "
          "certificate: " +
          check.problem);
    }
    result.objective_change = r.total - price * Cost(graph.node_count());
    matching = std::move(r.matching);
  } else {
    MinCostMaximumResult r = min_cost_maximum_matching(graph, edge_units, {.threads = threads});
    if (CertificateCheck check = verify_min_cost_maximum_matching(
            graph.node_count(), graph.edge_ends(), edge_units, r.matching, r.total_cost,
            r.unmatched_cost, r.certificate);
        !check.ok()) {
      throw std::logic_error(
          "internal error: the seams' cheapest maximum pairing fails its "
          "certificate: " +
          check.problem);
    }
    result.objective_change = r.total_cost;
    matching = std::move(r.matching);
  }
  for (EdgeId e = 0; e < graph.edge_count(); ++e) {
    const auto [a, b] = graph.endpoints(e);
    if (matching.mate_edge[a] != e) continue;
    const FaceId fa = index.faces[face_of[a]].face, fb = index.faces[face_of[b]].face;
    result.pairs.push_back({std::min(fa, fb), std::max(fa, fb)});
  }
  std::sort(result.pairs.begin(), result.pairs.end());
  result.seconds = clock.seconds();
  return result;
}

double lower_bound_degrees(Cost parts_units, std::int64_t dual_lowering) {
  return (double(parts_units) - double(dual_lowering) / 4) / kDefaultCostScale;
}

}  // namespace petersen
