#include "petersen/quadrangulate/quadrangulate.hpp"

#include <string>

#include "petersen/graph/stopwatch.hpp"
#include "petersen/matching/min_cost_matching.hpp"
#include "petersen/quadrangulate/stages.hpp"
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

// A closed, consistently oriented triangle surface: every component of the graph is one of the
// surface's, whose genus follows from their count (pair_triangles counts them).
void genus_from_components(const PairableGraph& graph, QuadStats& stats) {
  if (graph.cubic && graph.inconsistent_edges == 0 && stats.polygons_kept == 0) {
    stats.genus = (2 * std::int64_t(stats.components) - stats.euler_characteristic) / 2;
  }
}

// The stages (stages.hpp) in order. `movable` is the mesh itself when the caller gave it up: lrs
// may free its corners, and the output takes over its positions instead of copying them; null
// otherwise.
QuadResult quadrangulate(const PolygonMesh& mesh, const QuadOptions& options,
                         PolygonMesh* movable) {
  Stopwatch total, clock;
  quad_detail::validate_options(options);
  quad_detail::validate_positions(mesh);  // timed with the check (check_seconds)
  QuadStats stats;
  PairableMesh pairable = pairable_mesh(mesh, options, stats);
  stats.check_seconds = clock.lap();

  TrianglePairing pairing =
      pair_triangles(pairable.graph, mesh, movable != nullptr ? &movable->corners : nullptr,
                     pairable.costs, options, stats);  // fills its own phases' times
  genus_from_components(pairable.graph, stats);
  free_storage(pairable.costs);
  clock.lap();

  const MeshAttributes& attributes = mesh.attributes;
  const bool with_sources = options.sources || options.all_quad ||
                            attributes.has_corner_attributes() || attributes.has_face_attributes();
  const std::int64_t objective_units = pairing.objective_units;
  OutputFaces out = output_faces(mesh, pairable.graph, std::move(pairing),
                                 movable != nullptr && movable->memory()->is_equal(*options.memory)
                                     ? std::move(movable->positions)
                                     : Positions(mesh.positions, options.memory),
                                 with_sources, stats);
  QuadResult& result = out.result;
  const QualityFigures quality = measure_quads(result.mesh, out.kinds, options.threads);
  stats.quality_median = quality.median;
  stats.quality_p95 = quality.p95;
  stats.nonconvex_quads = quality.nonconvex;
  stats.objective_total = options.objective != Objective::pairs
                              ? double(objective_units) / kDefaultCostScale
                              : quality.total;
  if (!attributes.empty()) {
    result.mesh.attributes = attributes_of_pairs(mesh, result.mesh, result.sources);
  }
  // Not an attribute, but what the input's coordinates were: a float PLY is written back as float.
  result.mesh.attributes.position_type = attributes.position_type;
  stats.quads_seconds = clock.lap();
  result.stats = stats;

  if (options.all_quad) {
    split_leftovers(result, out.kinds, options);
    result.stats.all_quad_seconds = clock.lap();
  }
  if (!options.sources) free_storage(result.sources);
  result.stats.total_seconds = total.lap();
  return std::move(result);
}

}  // namespace

QuadResult quadrangulate(const PolygonMesh& mesh, const QuadOptions& options) {
  return quadrangulate(mesh, options, nullptr);
}

QuadResult quadrangulate(PolygonMesh&& mesh, const QuadOptions& options) {
  return quadrangulate(mesh, options, &mesh);
}

}  // namespace petersen
