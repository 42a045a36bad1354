#include "petersen/quadrangulate/quadrangulate.hpp"

#include <algorithm>
#include <bit>
#include <string>

#include "all_quad.hpp"
#include "attribute_cuts.hpp"
#include "carry_attributes.hpp"
#include "pair_triangles.hpp"
#include "petersen/dualize/cross_field.hpp"
#include "petersen/dualize/quad_of.hpp"
#include "petersen/dualize/quad_quality.hpp"
#include "petersen/graph/component_forest.hpp"
#include "petersen/graph/huge_pages.hpp"
#include "petersen/graph/parallel.hpp"
#include "petersen/graph/stopwatch.hpp"
#include "petersen/matching/min_cost_matching.hpp"
#include "petersen/mesh/duplicate_faces.hpp"
#include "shape_cuts.hpp"
#include "validate_input.hpp"

namespace petersen {

namespace {

constexpr std::pair<Objective, std::string_view> kObjectiveNames[] = {
    {Objective::quads, "quads"}, {Objective::pairs, "pairs"}, {Objective::quality, "quality"}};

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

std::string_view to_string(const PairingAlgorithm& algorithm) {
  if (const Algorithm* graph = std::get_if<Algorithm>(&algorithm)) return to_string(*graph);
  return "lrs";
}

std::optional<PairingAlgorithm> parse_pairing_algorithm(std::string_view name) {
  if (name == to_string(kLrs)) return kLrs;
  if (const std::optional<Algorithm> graph = parse_algorithm(name)) return *graph;
  return std::nullopt;
}

namespace {

using quad_detail::FaceKind;

// One call of the front door: its input, what each step makes for the next, and the result.
struct QuadRun {
  const PolygonMesh& mesh;
  const QuadOptions& options;
  // The mesh itself when the caller gave it up: the output takes over its positions instead of
  // copying them once nothing reads them any more, and lrs may free its corners (pair_triangles);
  // null otherwise.
  PolygonMesh* movable;
  // Counted before the pairing, which may free the mesh's corners.
  FaceId face_count = static_cast<FaceId>(mesh.face_count());
  std::size_t corners_in = mesh.corners.size();
  QuadResult result = {};
  PairableGraph graph = {};
  std::int64_t referenced_vertices = 0;  // those some face uses, for the Euler characteristic
  HugeVector<double> edge_costs = {};    // per pairable edge: quad_corner_deviation, when wanted
  HugeVector<double> edge_flow = {};     // per pairable edge, Objective::quads: the quad's flow
  quad_detail::TrianglePairing pairing = {};
  // Per output face, what it is: the quads' measure reads which faces are pairs' quads, all_quad
  // which to split (1 byte each). Their sources (8 bytes each: 0.8 GB of fresh memory at 10^8
  // triangles) are made only when something reads them (make_sources).
  std::vector<FaceKind> kinds = {};
  bool make_sources = false;

  QuadStats& stats() { return result.stats; }
};

// How many vertices some face's corners name (those out of range left out: the graph rejects
// them). A bit per vertex: 86 KB on armadillo-sub2, where a byte each is 692 KB of fresh pages.
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

// ---- The pairable graph and its cuts ----

// The graph with the mesh's attribute cuts, and the referenced vertices counted on a second thread
// beside the graph's single-threaded start (the corners' range check and the bucket offsets,
// longer than the count).
void build_graph_with_cuts(QuadRun& run) {
  run_parallel(run.options.threads, 2, [&](std::uint32_t task) {
    if (task == 1) {
      run.referenced_vertices = referenced_vertex_count(run.mesh);
      return;
    }
    quad_detail::AttributeCutIds ids;  // freed once the graph has the cuts
    run.graph = build_pairable_graph(
        run.mesh, quad_detail::attribute_cuts(run.mesh, run.options, ids), run.options.threads);
  });
}

bool wants_edge_costs(const QuadRun& run) {
  return run.options.objective != Objective::pairs || run.options.max_corner_deviation;
}

void measure_edge_costs(QuadRun& run) {
  run.edge_costs = pairable_edge_quality(run.graph, run.mesh, run.options.threads);
}

bool wants_flow(const QuadRun& run) {
  return run.options.objective == Objective::quads && run.options.flow_weight > 0;
}

// The cross field over the whole pairable graph, before any shape cut: a threshold says which
// pairs are allowed, not where the quads' edge loops run.
void measure_flow(QuadRun& run) {
  Stopwatch clock;
  const CrossField field = cross_field(run.graph, run.mesh);
  run.edge_flow = pairable_edge_flow(run.graph, side_alignment(field));
  run.stats().field_iterations = field.iterations;
  run.stats().field_seconds = clock.lap();
}

bool wants_shape_cuts(const QuadRun& run) {
  return run.options.max_corner_deviation.has_value();
}

void cut_by_shape(QuadRun& run) {
  quad_detail::cut_by_shape(run.graph, run.mesh, run.edge_costs, *run.options.max_corner_deviation,
                            run.edge_flow.empty() ? nullptr : &run.edge_flow);
}

// Objective::quads: each pair's cost is its shape plus its weighted flow.
void add_flow_to_costs(QuadRun& run) {
  const double weight = run.options.flow_weight;
  for (EdgeId e = 0; e < run.edge_costs.size(); ++e) run.edge_costs[e] += weight * run.edge_flow[e];
  run.edge_flow = HugeVector<double>();
}

// The faces that may have the same corners as another: the polygons, and the triangles cut on
// every side (a triangle's copy shares all its edges with it, so each is an edge of three or more
// faces or a duplicate cut). Without non-manifold or duplicate cuts there are no copies of
// triangles, and the caller does not ask. O(F).
std::vector<FaceId> duplicate_candidates(const QuadRun& run) {
  const PairableGraph& graph = run.graph;
  std::vector<FaceId> faces;
  for (NodeId v = 0; v < graph.node_count; ++v) {
    const EdgeId* sides = graph.node_edges.data() + 3 * std::size_t{v};
    if (sides[0] == kNoEdge && sides[1] == kNoEdge && sides[2] == kNoEdge) {
      faces.push_back(graph.node_face.empty() ? v : graph.node_face[v]);
    }
  }
  if (!run.mesh.all_triangles()) {
    for (FaceId f = 0; f < run.face_count; ++f) {
      if (run.mesh.arity(f) != 3) faces.push_back(f);
    }
  }
  return faces;
}

void record_graph_figures(QuadRun& run) {
  QuadStats& stats = run.stats();
  const PairableGraph& graph = run.graph;
  const FaceId face_count = run.face_count;
  stats.faces_in = face_count;
  stats.vertices = run.mesh.positions.size();
  stats.triangles = graph.node_count;
  stats.polygons_kept = face_count - graph.node_count;
  stats.mesh_edges = graph.mesh_edges;
  stats.cuts = graph.cuts;
  if (graph.cuts.by_cause[static_cast<int>(CutCause::non_manifold)] > 0 ||
      graph.cuts.by_cause[static_cast<int>(CutCause::duplicate)] > 0) {
    stats.duplicate_faces = duplicate_faces(run.mesh, duplicate_candidates(run)).size();
  }
  stats.inconsistent_edges = graph.inconsistent_edges;
  stats.euler_characteristic =
      run.referenced_vertices - std::int64_t(graph.mesh_edges) + std::int64_t(face_count);
}

// A closed, consistently oriented surface of triangles whose pairs some chosen cuts refuse (seams,
// borders, sharp edges): its genus is the surface's, whose components join across those cuts.
// Without chosen cuts the pairing counts the components anyway (genus_from_components).
bool oriented_surface_with_chosen_cuts(const QuadRun& run) {
  const PairableGraph& graph = run.graph;
  return graph.cuts.structural() == 0 && run.result.stats.polygons_kept == 0 &&
         graph.inconsistent_edges + graph.inconsistent_chosen_cuts == 0 &&
         !graph.chosen_cut_ends.empty();
}

void genus_across_chosen_cuts(QuadRun& run) {
  ComponentForest surface(run.graph.node_count, run.graph.edge_ends);
  surface.join(run.graph.chosen_cut_ends);
  QuadStats& stats = run.stats();
  stats.genus = (2 * std::int64_t(surface.root_count()) - stats.euler_characteristic) / 2;
}

void drop_chosen_cuts(QuadRun& run) {
  run.graph.chosen_cut_ends = HugeVector<NodeId>();  // `= {}` would keep the capacity
}

// ---- The pairing ----

void find_pairs(QuadRun& run) {
  HugeVector<VertexId>* releasable = run.movable != nullptr ? &run.movable->corners : nullptr;
  run.pairing = quad_detail::pair_triangles(run.graph, run.mesh, releasable, run.edge_costs,
                                            run.options, run.stats());
  // A closed, consistently oriented triangle surface: every component of the graph is one of the
  // surface's, whose genus follows from their count.
  QuadStats& stats = run.stats();
  if (run.graph.cubic && run.graph.inconsistent_edges == 0 && stats.polygons_kept == 0) {
    stats.genus = (2 * std::int64_t(stats.components) - stats.euler_characteristic) / 2;
  }
}

// ---- The output faces ----

// Per face, its node (kNoNode for a polygon); empty when node v is face v. Decided by the mesh:
// node_face is empty both when every face is a triangle and when none is.
HugeVector<NodeId> node_of_faces(const QuadRun& run) {
  HugeVector<NodeId> face_node;
  if (!run.mesh.all_triangles()) {
    face_node.assign(run.face_count, kNoNode);
    for (NodeId v = 0; v < run.graph.node_count; ++v) face_node[run.graph.node_face[v]] = v;
  }
  return face_node;
}

// Takes the input's positions, and sizes the output's arrays exactly, so that none grows past what
// it holds: a pair turns six corners into four.
void start_output(QuadRun& run) {
  PolygonMesh& out = run.result.mesh;
  if (run.movable != nullptr) {
    out.positions = std::move(run.movable->positions);
  } else {
    out.positions = run.mesh.positions;
  }
  const std::size_t face_count = run.face_count;
  std::size_t paired_nodes = 0;
  for (NodeId partner : run.pairing.partner) paired_nodes += partner != kNoNode;
  out.corners.reserve(run.corners_in - paired_nodes);
  if (paired_nodes > 0) out.face_start.reserve(face_count - paired_nodes / 2 + 1);
  const MeshAttributes& attributes = run.mesh.attributes;
  run.make_sources = run.options.sources || run.options.all_quad ||
                     attributes.has_corner_attributes() || attributes.has_face_attributes();
  if (run.make_sources) run.result.sources.reserve(face_count - paired_nodes / 2);
  run.kinds.reserve(face_count - paired_nodes / 2);
}

void add_face(QuadRun& run, std::span<const VertexId> corners, FaceKind kind,
              std::array<FaceId, 2> sources) {
  run.result.mesh.add_face(corners);
  if (run.make_sources) run.result.sources.push_back(sources);
  run.kinds.push_back(kind);
}

// The faces in input order: a pair's quad where its first triangle was, every other face as it is.
void add_faces_in_input_order(QuadRun& run) {
  const PolygonMesh& mesh = run.mesh;
  const PairableGraph& graph = run.graph;
  const HugeVector<NodeId>& partner_of = run.pairing.partner;
  const HugeVector<NodeId> face_node = node_of_faces(run);
  const FaceId face_count = run.face_count;
  for (FaceId f = 0; f < face_count; ++f) {
    // A pair's second triangle is anywhere in the mesh: fetching its corners a few faces ahead
    // takes a quarter off this loop's time on armadillo-sub2.
    if (constexpr FaceId kAhead = 8; f + kAhead < face_count) {
      const NodeId ahead = face_node.empty() ? f + kAhead : face_node[f + kAhead];
      const NodeId partner = ahead == kNoNode ? kNoNode : partner_of[ahead];
      if (partner < graph.node_count) __builtin_prefetch(mesh.face(graph.face_of(partner)).data());
    }
    const NodeId v = face_node.empty() ? f : face_node[f];
    const NodeId partner = v == kNoNode ? kNoNode : partner_of[v];
    if (v == kNoNode || partner == kNoNode) {
      add_face(run, mesh.face(f), v != kNoNode ? FaceKind::left : FaceKind::kept, {f, kNoFace});
      run.stats().triangles_left += v != kNoNode;
    } else if (partner != quad_detail::kLrsNode && v < partner) {
      const FaceId g = graph.face_of(partner);
      add_face(run, quad_of(mesh.face(f), mesh.face(g)), FaceKind::pair, {f, g});
      ++run.stats().pairs;
    }
  }
}

void make_output_faces(QuadRun& run) {
  start_output(run);
  add_faces_in_input_order(run);
  for (const quad_detail::LrsQuad& quad : run.pairing.lrs_quads) {
    add_face(run, quad.corners, FaceKind::pair, quad.sources);
    ++run.stats().pairs;
  }
  for (NodeId v : run.pairing.tutte_set) run.result.tutte_set.push_back(run.graph.face_of(v));
  // Freed before the quads' costs are measured (`= {}` would keep the buffer): those come from
  // the huge-page pool, which reuses the range it keeps.
  run.pairing.partner = HugeVector<NodeId>();
}

// Each output face's quad_corner_deviation, −1 for a face that is not a pair's quad; measured in
// blocks on the threads, written in full (from the huge-page pool, not fresh pages).
HugeArray<double> pair_quad_costs(const PolygonMesh& out, std::span<const FaceKind> kinds,
                                  std::uint32_t threads) {
  const FaceId out_faces = static_cast<FaceId>(out.face_count());
  HugeArray<double> costs = make_huge_array<double>(out_faces);
  constexpr FaceId kBlock = 1 << 16;
  run_parallel(threads, (out_faces + kBlock - 1) / kBlock, [&](std::uint32_t block) {
    const auto& p = out.positions;
    const FaceId end = std::min(out_faces, (block + 1) * kBlock);
    for (FaceId o = block * kBlock; o < end; ++o) {
      // The corners' positions are random reads (on armadillo-sub2, 65 % of the measure's
      // samples wait on them): fetched a few faces ahead, both ends of each 24-byte position.
      constexpr FaceId kAhead = 8;
      if (o + kAhead < end) {
        for (VertexId v : out.face(o + kAhead)) {
          __builtin_prefetch(p[v].data());
          __builtin_prefetch(p[v].data() + 2);
        }
      }
      const auto c = out.face(o);
      const bool pair_quad = kinds[o] == FaceKind::pair;
      costs[o] = pair_quad ? quad_corner_deviation(p[c[0]], p[c[1]], p[c[2]], p[c[3]]) : -1.0;
    }
  });
  return costs;
}

// The quality of the pairs' quads: their costs gathered and summed in face order, so that the
// figures do not depend on the threads.
void measure_quads(QuadRun& run) {
  const PolygonMesh& out = run.result.mesh;
  const HugeArray<double> costs = pair_quad_costs(out, run.kinds, run.options.threads);
  const std::span<double> all_costs(costs.get(), out.face_count());
  const auto quad_costs_end =
      std::remove_if(all_costs.begin(), all_costs.end(), [](double c) { return c < 0; });
  const QualityFigures quality = quality_figures_in_place({all_costs.begin(), quad_costs_end});
  QuadStats& stats = run.stats();
  stats.quality_median = quality.median;
  stats.quality_p95 = quality.p95;
  stats.nonconvex_quads = quality.nonconvex;
  stats.objective_total = run.options.objective != Objective::pairs
                              ? double(run.pairing.objective_units) / kDefaultCostScale
                              : quality.total;
}

bool has_attributes(const QuadRun& run) {
  return !run.mesh.attributes.empty();
}

void carry_attributes(QuadRun& run) {
  run.result.mesh.attributes =
      quad_detail::attributes_of_pairs(run.mesh, run.result.mesh, run.result.sources);
}

// Not an attribute, but what the input's coordinates were: a float PLY is written back as float.
void keep_position_type(QuadRun& run) {
  run.result.mesh.attributes.position_type = run.mesh.attributes.position_type;
}

bool wants_all_quad(const QuadRun& run) {
  return run.options.all_quad;
}

void make_all_quad(QuadRun& run) {
  quad_detail::split_leftovers(run.result, run.kinds, run.options);
}

bool sources_unwanted(const QuadRun& run) {
  return !run.options.sources;
}

void drop_sources(QuadRun& run) {
  run.result.sources = HugeVector<std::array<FaceId, 2>>();
}

// ---- The steps in order ----

struct Step {
  bool (*applies)(const QuadRun&) = nullptr;  // null: always
  void (*run)(QuadRun&);
  // After the step, the seconds since the clock's last lap go to this field of QuadStats. A step
  // without one is timed with the steps after it, unless it is self_timed: it fills its own
  // phases' times, and its lap is dropped.
  double QuadStats::*seconds = nullptr;
  bool self_timed = false;
};

// The strategy of the pairing itself (closed components by the chosen algorithm or lrs, the others
// by augmenting paths, Objective::quality by the minimum-cost matching) is pair_triangles's.
constexpr Step kSteps[] = {
    {.run = build_graph_with_cuts},
    {.applies = wants_edge_costs, .run = measure_edge_costs},
    {.applies = wants_flow, .run = measure_flow},
    {.applies = wants_shape_cuts, .run = cut_by_shape},
    {.applies = wants_flow, .run = add_flow_to_costs},
    {.run = record_graph_figures},
    {.applies = oriented_surface_with_chosen_cuts, .run = genus_across_chosen_cuts},
    {.run = drop_chosen_cuts, .seconds = &QuadStats::check_seconds},
    {.run = find_pairs, .self_timed = true},
    {.run = make_output_faces},
    {.run = measure_quads},
    {.applies = has_attributes, .run = carry_attributes},
    {.run = keep_position_type, .seconds = &QuadStats::quads_seconds},
    {.applies = wants_all_quad, .run = make_all_quad, .seconds = &QuadStats::all_quad_seconds},
    {.applies = sources_unwanted, .run = drop_sources},
};

QuadResult quadrangulate(const PolygonMesh& mesh, const QuadOptions& options,
                         PolygonMesh* movable) {
  Stopwatch total, clock;
  quad_detail::validate_options(options);
  quad_detail::validate_positions(mesh);  // timed with the check (check_seconds)
  QuadRun run{.mesh = mesh, .options = options, .movable = movable};
  for (const Step& step : kSteps) {
    if (step.applies != nullptr && !step.applies(run)) continue;
    step.run(run);
    if (step.seconds != nullptr) {
      run.stats().*step.seconds = clock.lap();
    } else if (step.self_timed) {
      clock.lap();
    }
  }
  run.stats().total_seconds = total.lap();
  return std::move(run.result);
}

}  // namespace

QuadResult quadrangulate(const PolygonMesh& mesh, const QuadOptions& options) {
  return quadrangulate(mesh, options, nullptr);
}

QuadResult quadrangulate(PolygonMesh&& mesh, const QuadOptions& options) {
  return quadrangulate(mesh, options, &mesh);
}

}  // namespace petersen
