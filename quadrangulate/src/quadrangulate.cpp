#include "petersen/quadrangulate/quadrangulate.hpp"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "all_quad.hpp"
#include "attribute_cuts.hpp"
#include "carry_attributes.hpp"
#include "lap_clock.hpp"
#include "pair_triangles.hpp"
#include "petersen/dualize/quad_of.hpp"
#include "petersen/dualize/quad_quality.hpp"
#include "petersen/graph/component_forest.hpp"
#include "petersen/graph/huge_pages.hpp"
#include "petersen/graph/parallel.hpp"
#include "petersen/matching/min_cost_matching.hpp"
#include "shape_cuts.hpp"

namespace petersen {

namespace {

// How many vertices some face's corners name (those out of range left out).
std::int64_t referenced_vertex_count(const PolygonMesh& mesh) {
  const std::size_t vertex_count = mesh.positions.size();
  std::vector<std::uint64_t> referenced((vertex_count + 63) / 64, 0);
  for (VertexId v : mesh.corners) {
    if (v < vertex_count) referenced[v / 64] |= std::uint64_t{1} << (v % 64);
  }
  std::int64_t count = 0;
  for (std::uint64_t word : referenced) count += std::popcount(word);
  return count;
}

constexpr std::pair<Objective, std::string_view> kObjectiveNames[] = {
    {Objective::pairs, "pairs"}, {Objective::quality, "quality"}};

}  // namespace

std::string_view to_string(Objective objective) {
  for (auto [o, name] : kObjectiveNames)
    if (o == objective) return name;
  return "?";
}

std::optional<Objective> parse_objective(std::string_view name) {
  for (auto [o, n] : kObjectiveNames)
    if (n == name) return o;
  return std::nullopt;
}

namespace {

// The front door; `movable`, when given, is the mesh itself, whose positions the output takes over
// instead of copying once nothing reads them any more, and whose corners lrs may free
// (pair_triangles).
QuadResult quadrangulate(const PolygonMesh& mesh, const QuadOptions& options,
                         PolygonMesh* movable) {
  if (options.max_corner_deviation && std::isnan(*options.max_corner_deviation)) {
    throw std::invalid_argument("max_corner_deviation is NaN");
  }
  quad_detail::LapClock total, clock;
  QuadResult result;
  QuadStats& stats = result.stats;
  const std::uint32_t face_count = static_cast<std::uint32_t>(mesh.face_count());
  stats.faces_in = face_count;
  stats.vertices = mesh.positions.size();
  // The vertices that some face uses, for the Euler characteristic: counted on a second thread
  // while the graph's single-threaded start (the corners' range check, the bucket offsets: about
  // 8 ms on armadillo-sub2) runs, which the count (about 3 ms) fits beside. A bit per vertex (86 KB
  // there, not a byte's 692 KB of fresh pages). Corners out of range are skipped: the graph
  // rejects them.
  std::int64_t vertices = 0;
  PairableGraph graph;
  run_parallel(options.threads, 2, [&](std::uint32_t task) {
    if (task == 1) {
      vertices = referenced_vertex_count(mesh);
      return;
    }
    quad_detail::AttributeCutIds ids;  // freed once the graph has the cuts
    graph = build_pairable_graph(mesh, quad_detail::attribute_cuts(mesh, options, ids),
                                 options.threads);
  });
  HugeVector<double> degrees;
  if (options.objective == Objective::quality || options.max_corner_deviation) {
    degrees = pairable_edge_quality(graph, mesh, options.threads);
  }
  if (options.max_corner_deviation) {
    quad_detail::cut_by_shape(graph, mesh, degrees, *options.max_corner_deviation);
  }
  stats.triangles = graph.node_count;
  stats.polygons_kept = face_count - graph.node_count;
  stats.mesh_edges = graph.mesh_edges;
  stats.cuts = graph.cuts;
  stats.inconsistent_edges = graph.inconsistent_edges;
  stats.euler_characteristic = vertices - std::int64_t(graph.mesh_edges) + std::int64_t(face_count);
  // A closed, consistently oriented surface of triangles whose pairs some chosen cuts refuse
  // (seams, borders, sharp edges): its genus is the surface's, whose components join across
  // those cuts. Without cuts the pairing counts the components anyway (below).
  const bool oriented_surface = graph.cuts.structural() == 0 && stats.polygons_kept == 0 &&
                                graph.inconsistent_edges + graph.inconsistent_chosen_cuts == 0;
  if (oriented_surface && !graph.chosen_cut_ends.empty()) {
    ComponentForest surface(graph.node_count, graph.edge_ends);
    surface.join(graph.chosen_cut_ends);
    stats.genus = (2 * std::int64_t(surface.root_count()) - stats.euler_characteristic) / 2;
  }
  graph.chosen_cut_ends = HugeVector<NodeId>();  // `= {}` would keep the capacity
  stats.check_seconds = clock.lap();

  // Counted before the pairing, which may free the mesh's corners.
  const std::size_t corners_in = mesh.corners.size();
  quad_detail::TrianglePairing pairing = quad_detail::pair_triangles(
      graph, mesh, movable != nullptr ? &movable->corners : nullptr, degrees, options, stats);
  if (graph.cubic && graph.inconsistent_edges == 0 && stats.polygons_kept == 0) {
    stats.genus = (2 * std::int64_t(stats.components) - stats.euler_characteristic) / 2;
  }
  clock.lap();  // its phases are in stats already

  // Output faces in input order: a pair's quad where its first triangle was.
  HugeVector<NodeId> face_node;
  // Decided by the mesh: node_face is empty both when every face is a triangle and when none is.
  if (!mesh.all_triangles()) {
    face_node.assign(face_count, kNoNode);
    for (NodeId v = 0; v < graph.node_count; ++v) face_node[graph.node_face[v]] = v;
  }
  PolygonMesh& out = result.mesh;
  if (movable != nullptr) {
    out.positions = std::move(movable->positions);
  } else {
    out.positions = mesh.positions;
  }
  // Exact sizes, so that no array grows past what it holds: a pair turns six corners into four.
  std::size_t paired_nodes = 0;
  for (NodeId partner : pairing.partner) paired_nodes += partner != kNoNode;
  out.corners.reserve(corners_in - paired_nodes);
  if (paired_nodes > 0) out.face_start.reserve(face_count - paired_nodes / 2 + 1);
  // Each face's kind (1 byte) tells the quads' measure below which faces are pairs' quads, and
  // all_quad which to split. The sources (8 bytes: 0.8 GB of fresh memory at 10^8 triangles) are
  // made when asked for and when all_quad or the attributes read them.
  const bool make_sources = options.sources || options.all_quad ||
                            mesh.attributes.has_corner_attributes() ||
                            mesh.attributes.has_face_attributes();
  if (make_sources) result.sources.reserve(face_count - paired_nodes / 2);
  std::vector<quad_detail::FaceKind> kinds;
  kinds.reserve(face_count - paired_nodes / 2);
  auto emitted = [&](quad_detail::FaceKind kind, std::array<FaceId, 2> sources) {
    if (make_sources) result.sources.push_back(sources);
    kinds.push_back(kind);
  };
  for (FaceId f = 0; f < face_count; ++f) {
    // A pair's second triangle is anywhere in the mesh: its corners are fetched a few faces
    // ahead (armadillo-sub2, this loop, medians of 5 alternated at load 3: 0.029 -> 0.022 s).
    if (constexpr FaceId kAhead = 8; f + kAhead < face_count) {
      const NodeId ahead = face_node.empty() ? f + kAhead : face_node[f + kAhead];
      const NodeId partner = ahead == kNoNode ? kNoNode : pairing.partner[ahead];
      if (partner < graph.node_count) __builtin_prefetch(mesh.face(graph.face_of(partner)).data());
    }
    const NodeId v = face_node.empty() ? f : face_node[f];
    const NodeId partner = v == kNoNode ? kNoNode : pairing.partner[v];
    if (v == kNoNode || partner == kNoNode) {
      out.add_face(mesh.face(f));
      stats.triangles_left += v != kNoNode;
      emitted(v != kNoNode ? quad_detail::FaceKind::left : quad_detail::FaceKind::kept,
              {f, kNoFace});
    } else if (partner != quad_detail::kLrsNode && v < partner) {
      const FaceId g = graph.face_of(partner);
      const std::array<VertexId, 4> quad = quad_of(mesh.face(f), mesh.face(g));
      out.add_face(quad);
      ++stats.pairs;
      emitted(quad_detail::FaceKind::pair, {f, g});
    }
  }
  for (const quad_detail::LrsQuad& quad : pairing.lrs_quads) {
    out.add_face(quad.corners);
    ++stats.pairs;
    emitted(quad_detail::FaceKind::pair, quad.sources);
  }
  for (NodeId v : pairing.tutte_set) result.tutte_set.push_back(graph.face_of(v));
  // Freed before the quads' costs are measured beside the output (`= {}` would keep the buffer):
  // the costs below come from the huge-page pool, which reuses the range it keeps.
  pairing.partner = HugeVector<NodeId>();
  // Quality of the pairs' quads (every output face of four corners made from triangles): each
  // face's cost (−1 for the others) measured in blocks on the threads, then gathered and summed
  // in face order, so the figures do not depend on the threads.
  const FaceId out_faces = static_cast<FaceId>(out.face_count());
  // Written in full below; from the pool, not fresh pages.
  const HugeArray<double> costs = make_huge_array<double>(out_faces);
  constexpr FaceId kBlock = 1 << 16;
  run_parallel(options.threads, (out_faces + kBlock - 1) / kBlock, [&](std::uint32_t block) {
    const auto& p = out.positions;
    const FaceId end = std::min(out_faces, (block + 1) * kBlock);
    for (FaceId o = block * kBlock; o < end; ++o) {
      // The corners' positions are random reads (on armadillo-sub2, 65 % of the measure's
      // samples waited on them): fetched a few faces ahead, both ends of each 24-byte position.
      constexpr FaceId kAhead = 8;
      if (o + kAhead < end) {
        for (VertexId v : out.face(o + kAhead)) {
          __builtin_prefetch(p[v].data());
          __builtin_prefetch(p[v].data() + 2);
        }
      }
      const auto c = out.face(o);
      const bool pair_quad = kinds[o] == quad_detail::FaceKind::pair;
      costs[o] = pair_quad ? quad_corner_deviation(p[c[0]], p[c[1]], p[c[2]], p[c[3]]) : -1.0;
    }
  });
  const std::span<double> all_costs(costs.get(), out_faces);
  const auto quad_costs_end =
      std::remove_if(all_costs.begin(), all_costs.end(), [](double c) { return c < 0; });
  const QualityFigures quality = quality_figures_in_place({all_costs.begin(), quad_costs_end});
  stats.quality_median = quality.median;
  stats.quality_p95 = quality.p95;
  stats.nonconvex_quads = quality.nonconvex;
  stats.objective_total = options.objective == Objective::quality
                              ? double(pairing.objective_units) / kDefaultCostScale
                              : quality.total;
  if (!mesh.attributes.empty()) {
    out.attributes = quad_detail::attributes_of_pairs(mesh, out, result.sources);
  }
  // Not an attribute, but what the input's coordinates were: a float PLY is written back as float.
  out.attributes.position_type = mesh.attributes.position_type;
  stats.quads_seconds = clock.lap();

  if (options.all_quad && stats.triangles_left > 0) {
    quad_detail::split_leftovers(result, kinds);
    stats.all_quad_seconds = clock.lap();
  }
  if (!options.sources) result.sources = HugeVector<std::array<FaceId, 2>>();
  stats.total_seconds = total.lap();
  return result;
}

}  // namespace

QuadResult quadrangulate(const PolygonMesh& mesh, const QuadOptions& options) {
  return quadrangulate(mesh, options, nullptr);
}

QuadResult quadrangulate(PolygonMesh&& mesh, const QuadOptions& options) {
  return quadrangulate(mesh, options, &mesh);
}

}  // namespace petersen
