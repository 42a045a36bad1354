// petersen: any mesh -> its triangles paired into quads on the same vertices; graphs -> matchings.

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory_resource>
#include <optional>
#include <vector>

#include "flag_suggestions.hpp"
#include "json_text.hpp"
#include "keep_edges.hpp"
#include "match_command.hpp"
#include "memory_pool.hpp"
#include "option_checks.hpp"
#include "out_of_core_command.hpp"
#include "petersen/dualize/quad_quality.hpp"
#include "petersen/generators/knot_tube.hpp"
#include "petersen/generators/mesh_class_generators.hpp"
#include "petersen/generators/polygon_generators.hpp"
#include "petersen/generators/surface_generators.hpp"
#include "petersen/graph/memory.hpp"
#include "petersen/graph/stopwatch.hpp"
#include "petersen/io/read_mesh.hpp"
#include "petersen/io/write_mesh.hpp"
#include "petersen/memory_pool/huge_page_pool.hpp"
#include "petersen/mesh/duplicate_faces.hpp"
#include "petersen/mesh/mesh_report.hpp"
#include "petersen/quadrangulate/quadrangulate.hpp"
#include "petersen/render/render_mesh.hpp"
#include "petersen/version.hpp"
#include "run_report.hpp"

namespace petersen::cli {
namespace {

// Prints on stderr what a reader read past or a writer had no place for, one warning per kind of
// thing, naming the file.
void warn_dropped(const std::string& path, const std::vector<std::string>& dropped) {
  for (const std::string& item : dropped) {
    std::fprintf(stderr, "petersen: warning: %s: dropped %s\n", path.c_str(), item.c_str());
  }
}

PolygonMesh read_mesh_warning(const std::string& path, bool strict = false) {
  std::vector<std::string> dropped;
  PolygonMesh mesh = read_mesh(path, &dropped, {.strict = strict, .memory = program_memory()});
  warn_dropped(path, dropped);
  return mesh;
}

int info(const std::string& path, bool strict) {
  const PolygonMesh mesh = read_mesh_warning(path, strict);
  std::fputs(describe(inspect_mesh(mesh)).c_str(), stdout);
  // The quads' shape, by the measure `petersen quad` reports and --objective quality minimises.
  const QualityFigures quality = quality_figures(quad_costs(mesh));
  if (quality.quads > 0) std::printf("quality: %s\n", describe(quality).c_str());
  return 0;
}

// --view x,y,z: the direction the eye looks along.
std::optional<std::array<double, 3>> parse_view(const std::vector<double>& view) {
  if (view.empty()) return std::nullopt;
  if (view.size() != 3) throw CLI::ValidationError("--view", "needs three numbers x,y,z");
  const bool finite = std::isfinite(view[0]) && std::isfinite(view[1]) && std::isfinite(view[2]);
  if (!finite || (view[0] == 0 && view[1] == 0 && view[2] == 0)) {
    throw CLI::ValidationError("--view", "needs a finite direction that is not zero");
  }
  return std::array<double, 3>{view[0], view[1], view[2]};
}

struct RenderArgs {
  std::string input, output;
  std::vector<double> view;
  std::uint32_t width = 800, height = 800;
};

int render(const RenderArgs& args) {
  const PolygonMesh mesh = read_mesh_warning(args.input);
  const MeshReport report = inspect_mesh(mesh);
  std::string faces;
  for (const auto& [arity, count] : report.faces_by_arity) {
    faces += (faces.empty() ? "" : ", ") + std::to_string(count) + " of " + std::to_string(arity);
  }
  RenderOptions options;
  options.width = args.width;
  options.height = args.height;
  options.view = parse_view(args.view);
  options.caption = {std::filesystem::path(args.input).filename().string(),
                     std::to_string(report.vertices) + " vertices, " +
                         std::to_string(report.faces) + " faces (" + faces + " corners), " +
                         std::to_string(report.boundary_loops) + " boundary loops"};
  const QualityFigures quality = quality_figures(quad_costs(mesh));
  if (quality.quads > 0) options.caption.push_back(describe(quality));
  render_mesh(mesh, args.output, options);
  std::printf("%s written\n", args.output.c_str());
  return 0;
}

struct QuadArgs {
  std::string input, output, algorithm = "auto", augment = "local", objective = "quads", stats_json,
                             render;
  std::vector<double> view;
  std::uint32_t render_width = 800, render_height = 800;
  std::uint64_t seed = 1;
  std::uint32_t threads = 0;
  bool all_quad = false, keep_polygons = false, strict = false, drop_duplicate_faces = false;
  std::optional<double> sharp_angle, max_corner_deviation;
  double triangle_cost = kDefaultTriangleCost, flow_weight = kDefaultFlowWeight;
  std::string keep_edges;
  std::vector<std::string> cross;
  std::string memory_limit;
  std::uint64_t part_triangles = 0;
  std::vector<std::string> given;  // the flags on the command line (given_flags)
};

// The flags given on `command`'s command line, by their long names.
std::vector<std::string> given_flags(const CLI::App& command) {
  std::vector<std::string> names;
  for (const CLI::Option* option : command.get_options()) {
    if (option->count() > 0 && !option->get_lnames().empty()) {
      names.push_back("--" + option->get_lnames().front());
    }
  }
  return names;
}

// Why the out-of-core conversion does not take a flag of `petersen quad`: each part is paired
// from its own faces and positions, so what needs the whole mesh (or its attributes) at once is
// refused rather than ignored.
std::string out_of_core_refusal(const std::string& flag, Objective objective) {
  const bool costs = objective != Objective::pairs;
  if ((flag == "--sharp-angle" || flag == "--max-corner-deviation") && !costs) {
    return "--objective pairs pairs the maximum out of core without measuring the quads: give "
           "--objective quads or quality with it";
  }
  if (flag == "--augment" && costs) {
    return "chooses the augmenting paths of --objective pairs; the cost objectives pair by the "
           "minimum-cost matching";
  }
  if (flag == "--algorithm" || flag == "--seed") {
    return "each part is paired by the maximum matching (--objective pairs) or the minimum-cost "
           "matching, whatever the algorithm";
  }
  if (flag == "--flow-weight") return "the cross field of the edge flow needs the whole mesh";
  if (flag == "--keep-edges" || flag == "--cross" || flag == "--strict" ||
      flag == "--drop-duplicate-faces") {
    return "the parts are read as a binary PLY of triangles without attributes or edge lists";
  }
  if (flag.starts_with("--render") || flag == "--view") return "drawing needs the whole mesh";
  return "it needs the whole mesh in memory";
}

// The flags the out-of-core conversion takes for this objective; any other is refused before any
// work, naming the flag and why.
void refuse_out_of_core_flags(const QuadArgs& args, Objective objective) {
  const bool costs = objective != Objective::pairs;
  for (const std::string& flag : args.given) {
    const bool taken = flag == "--memory-limit" || flag == "--part-triangles" ||
                       flag == "--threads" || flag == "--stats-json" || flag == "--objective" ||
                       flag == "--all-quad" || flag == "--keep-polygons" ||
                       flag == "--triangle-cost" || (flag == "--augment" && !costs) ||
                       ((flag == "--sharp-angle" || flag == "--max-corner-deviation") && costs);
    if (!taken) {
      throw CLI::ValidationError(flag,
                                 "not taken by the out-of-core conversion (--memory-limit, "
                                 "or an input too large for memory): " +
                                     out_of_core_refusal(flag, objective));
    }
  }
}

// The weights only --objective quads reads, refused where the run would not read them, in memory
// and out of core alike.
void refuse_unread_weights(const QuadArgs& args, Objective objective) {
  auto given = [&](const char* flag) { return std::ranges::count(args.given, flag) > 0; };
  if (given("--triangle-cost") && objective != Objective::quads) {
    throw CLI::ValidationError("--triangle-cost",
                               "prices the triangles --objective quads leaves; --objective " +
                                   args.objective + " pairs the maximum");
  }
  if (given("--triangle-cost") && args.all_quad) {
    throw CLI::ValidationError("--triangle-cost",
                               "with --all-quad every triangle left is split into quads, so the "
                               "pairing is the cheapest maximum, which prices no triangle");
  }
  if (given("--flow-weight") && objective != Objective::quads) {
    throw CLI::ValidationError(
        "--flow-weight",
        "weighs the edge flow in the costs of --objective quads, not --objective " +
            args.objective);
  }
}

int quad(const QuadArgs& args) {
  const auto objective = parse_objective(args.objective);
  if (!objective) throw CLI::ValidationError("--objective", "unknown objective " + args.objective);
  refuse_unread_weights(args, *objective);
  if (const auto limit = out_of_core_limit(args.input, args.memory_limit, *objective)) {
    refuse_out_of_core_flags(args, *objective);
    return quad_out_of_core_command({.input = args.input,
                                     .output = args.output,
                                     .augment = args.augment,
                                     .stats_json = args.stats_json,
                                     .costs = {.objective = *objective,
                                               .triangle_cost = args.triangle_cost,
                                               .max_corner_deviation = args.max_corner_deviation,
                                               .sharp_angle_degrees = args.sharp_angle},
                                     .memory_limit = *limit,
                                     .part_triangles = args.part_triangles,
                                     .threads = args.threads,
                                     .all_quad = args.all_quad,
                                     .keep_polygons = args.keep_polygons});
  }
  if (args.part_triangles > 0) {
    throw CLI::ValidationError("--part-triangles",
                               "sizes the parts of the out-of-core conversion: give --memory-limit "
                               "with it (IN a binary PLY)");
  }
  const auto algorithm = parse_pairing_algorithm(args.algorithm);
  if (!algorithm) throw CLI::ValidationError("--algorithm", "unknown algorithm " + args.algorithm);
  const auto augment = parse_augment(args.augment);
  if (!augment) throw CLI::ValidationError("--augment", "unknown augmentation " + args.augment);
  if (*objective != Objective::pairs && *algorithm != PairingAlgorithm{Algorithm::automatic}) {
    throw CLI::ValidationError(
        "--algorithm", "chooses how --objective pairs pairs, and --objective " + args.objective +
                           " pairs by the minimum-cost matching: add "
                           "--objective pairs");
  }
  mesh_format_of(args.output);  // an unknown output format fails before any work
  std::vector<CutCause> cross;  // names checked by --cross's one_of
  for (const std::string& name : args.cross) cross.push_back(*parse_cut_cause(name));
  const auto view = parse_view(args.view);
  if (!args.render.empty() && !is_picture_path(args.render)) {
    throw CLI::ValidationError("--render", "a picture must be .png or .svg: " + args.render);
  }
  RunReport report;
  report.input = args.input;
  report.output = args.output;
  report.options.algorithm = *algorithm;
  report.options.augment = *augment;
  report.options.seed = args.seed;
  report.options.all_quad = args.all_quad;
  report.options.keep_polygons = args.keep_polygons;
  report.options.objective = *objective;
  report.options.triangle_cost = args.triangle_cost;
  report.options.flow_weight = args.flow_weight;
  report.options.cross = cross;
  report.options.threads = args.threads;
  // The tool writes the mesh and the stats, never the quads' sources: not asking for them lets
  // lrs free the input's corners early (12 bytes per triangle at its peak).
  report.options.sources = false;
  report.options.memory = program_memory();
  Stopwatch total, clock;
  PolygonMesh mesh = read_mesh_warning(args.input, args.strict);
  if (args.drop_duplicate_faces) {
    DroppedFaces copies = drop_duplicate_faces(mesh);
    if (!copies.dropped.empty()) {
      warn_dropped(args.input, {std::to_string(copies.dropped.size()) +
                                " duplicate faces (--drop-duplicate-faces), the first face " +
                                std::to_string(copies.dropped[0])});
    }
    mesh = std::move(copies.mesh);
  }
  const std::vector<std::array<VertexId, 2>> keep_edges =
      args.keep_edges.empty() ? std::vector<std::array<VertexId, 2>>{}
                              : read_keep_edges(args.keep_edges, mesh.positions.size());
  report.options.cuts.sharp_angle_degrees = args.sharp_angle;
  report.options.max_corner_deviation = args.max_corner_deviation;
  report.options.cuts.user_edges = keep_edges;
  report.load_seconds = clock.lap();
  const auto input_vertices = static_cast<VertexId>(mesh.positions.size());
  QuadResult result = [&] {
    try {
      // Consumed: its positions become the output's, not a copy of them.
      return quadrangulate(std::move(mesh), report.options);
    } catch (const MeshError& e) {
      throw MeshError(args.input + ": " + e.what());  // the reader's own errors name it already
    }
  }();
  report.quad = result.stats;
  // The rest of the input is not needed past this point: freed before the output's bytes are
  // built beside the output mesh, where the peak would otherwise be.
  mesh = PolygonMesh(mesh.memory());  // on its resource: `= {}` from another would keep them
  clock.lap();
  warn_dropped(args.output, write_mesh(args.output, result.mesh));
  report.write_seconds = clock.lap();
  report.total_seconds = total.lap();
  print_summary(stdout, report);
  if (!args.stats_json.empty()) {
    write_printed(args.stats_json, [&](std::FILE* out) { write_json(out, report); });
    std::printf("written     %s\n", args.stats_json.c_str());
  }
  if (!args.render.empty()) {
    const QuadStats& s = result.stats;
    RenderOptions options;
    options.view = view;
    options.width = args.render_width;
    options.height = args.render_height;
    options.first_added_vertex = input_vertices;
    options.caption = {
        std::filesystem::path(args.input).filename().string() + " by " +
            (report.options.objective != Objective::pairs
                 ? "min-cost (objective " + std::string(to_string(report.options.objective)) + ")"
                 : std::string(to_string(report.options.algorithm))) +
            (args.all_quad ? ", all quads" : ""),
        std::to_string(s.faces_in) + " faces in: " + std::to_string(s.pairs) + " pairs, " +
            std::to_string(s.triangles_left) + " triangles left, " +
            std::to_string(s.polygons_kept) + " polygons kept, " +
            std::to_string(s.added_vertices) + " vertices added",
        describe(quality_figures(quad_costs(result.mesh)))};
    render_mesh(result.mesh, args.render, options);
    std::printf("written     %s\n", args.render.c_str());
  }
  return 0;
}

struct GenerateArgs {
  std::string output, kind = "plate";
  std::uint32_t holes_x = 2, holes_y = 1, subdivision = 4, splits = 0, flips = 0;
  std::optional<std::uint32_t> nx, ny;  // each kind's own default when not given (grid_size)
  std::uint32_t holes = 0, fins = 0, pinches = 0, flip_faces = 0;
  bool dents = false, spatial_order = false;
  double jitter = 0.1;
  std::uint64_t seed = 1;
  std::uint64_t triangles = 1000000;
};

PolygonMesh randomized_plate(const GenerateArgs& args) {
  PolygonMesh mesh = voxel_plate({args.holes_x, args.holes_y, args.subdivision, args.dents});
  if (args.splits > 0 || args.flips > 0) {
    mesh = randomize_triangulation(std::move(mesh), args.splits, args.flips, args.seed);
  }
  if (args.spatial_order) mesh = spatially_ordered(mesh);
  return mesh;
}

// --nx and --ny as given, or the kind's defaults: a torus's lattice wraps round a ring of major
// radius nx/ny, so it needs nx >= 3 ny for its hole; the trefoil's quads are near square at
// 8.5 segments per side.
std::array<std::uint32_t, 2> grid_size(const GenerateArgs& args) {
  const bool torus = args.kind == "jittered-torus" || args.kind == "quad-dominant-torus";
  const std::array<std::uint32_t, 2> defaults = torus                    ? std::array{48u, 16u}
                                                : args.kind == "trefoil" ? std::array{136u, 16u}
                                                                         : std::array{16u, 16u};
  return {args.nx.value_or(defaults[0]), args.ny.value_or(defaults[1])};
}

// The sizes each kind needs, named by the flags that set them, before any work.
void check_grid_size(const GenerateArgs& args) {
  const auto [nx, ny] = grid_size(args);
  const std::string size = std::to_string(nx) + " x " + std::to_string(ny);
  const bool grid = args.kind == "klein" || args.kind == "trefoil" || args.kind == "open-grid" ||
                    args.kind.starts_with("jittered-") || args.kind.starts_with("quad-dominant");
  if (!grid && (args.nx || args.ny)) {
    throw CLI::ValidationError("--nx, --ny", args.kind +
                                                 " has no grid to size: --nx and --ny "
                                                 "are for klein, trefoil and the grids");
  }
  const bool closed = args.kind == "klein" || args.kind == "trefoil";
  if (closed && (nx < 3 || ny < 3)) {
    throw CLI::ValidationError("--nx, --ny",
                               args.kind + " needs --nx >= 3 and --ny >= 3, not " + size);
  }
  if (args.kind.ends_with("-torus") && (ny < 3 || nx < 3 * std::uint64_t{ny})) {
    throw CLI::ValidationError("--nx, --ny",
                               args.kind +
                                   " needs --ny >= 3 and --nx >= 3 x --ny (the ring round its "
                                   "hole), not " +
                                   size);
  }
  if ((args.kind == "open-grid" || args.kind == "jittered-grid" || args.kind == "quad-dominant") &&
      (nx == 0 || ny == 0)) {
    throw CLI::ValidationError("--nx, --ny", args.kind + " needs --nx >= 1 and --ny >= 1");
  }
  if (6 * std::uint64_t{nx} * ny > 0xFFFFFFFFull) {
    throw CLI::ValidationError("--nx, --ny",
                               size +
                                   " makes more than 2^32 - 1 corners (at most about 715 "
                                   "million triangles)");
  }
}

PolygonMesh generated_surface(const GenerateArgs& args) {
  const auto [nx, ny] = grid_size(args);
  if (args.kind == "klein") return klein_bottle(nx, ny);
  if (args.kind == "projective") return projective_plane(args.subdivision);
  if (args.kind == "open-grid") return open_grid(nx, ny);
  if (args.kind == "trefoil") return trefoil_tube({.segments = nx, .sides = ny});
  if (args.kind == "jittered-grid" || args.kind == "jittered-torus") {
    return jittered_grid({.nx = nx,
                          .ny = ny,
                          .jitter = args.jitter,
                          .torus = args.kind == "jittered-torus",
                          .seed = args.seed});
  }
  if (args.kind == "quad-dominant" || args.kind == "quad-dominant-torus") {
    // One pentagon and one hexagon per 100 squares, at least one each.
    const std::uint32_t odd =
        std::max<std::uint32_t>(1, std::uint32_t(std::uint64_t{nx} * ny / 100));
    return quad_dominant_grid({.nx = nx,
                               .ny = ny,
                               .jitter = args.jitter,
                               .torus = args.kind == "quad-dominant-torus",
                               .pentagons = odd,
                               .hexagons = odd,
                               .seed = args.seed});
  }
  if (args.kind == "chamfered-cube") return chamfered_cube();
  return randomized_plate(args);
}

PolygonMesh generated_mesh(const GenerateArgs& args) {
  PolygonMesh surface = generated_surface(args);
  // Each step with its own seed, so that asking for one does not change what another does.
  if (args.holes > 0) surface = punch_holes(surface, args.holes, args.seed + 1);
  if (args.fins > 0) surface = add_fins(surface, args.fins, args.seed + 2);
  if (args.pinches > 0) surface = pinch_vertices(surface, args.pinches, args.seed + 3);
  if (args.flip_faces > 0) surface = flip_faces(surface, args.flip_faces, args.seed + 4);
  return surface;
}

int generate(const GenerateArgs& args) {
  if (args.kind == "streamed-plate") return generate_streamed_plate(args.output, args.triangles);
  mesh_format_of(args.output);  // an unknown format fails before any work
  check_grid_size(args);
  const PolygonMesh mesh = generated_mesh(args);
  write_mesh(args.output, mesh);
  std::printf("%zu faces, %zu vertices written to %s\n", mesh.face_count(), mesh.positions.size(),
              args.output.c_str());
  return 0;
}

// render_mesh's limits, checked before any work.
CLI::Range picture_side() {
  return CLI::Range(200u, 16384u);
}

// What --cross takes: the causes of the cuts of the mesh's attributes.
std::vector<std::string> attribute_cause_names() {
  std::vector<std::string> names;
  for (const CutCause cause : attribute_causes()) names.emplace_back(to_string(cause));
  return names;
}

// What --algorithm takes: perfect_matching's algorithms, then lrs.
std::vector<std::string> pairing_algorithm_names() {
  std::vector<std::string> names = names_of<Algorithm>();
  names.emplace_back(to_string(kLrs));
  return names;
}

// `petersen quad` and its flags, into `args`.
CLI::App* add_quad_command(CLI::App& app, QuadArgs& quad_args) {
  CLI::App* quad_cmd = app.add_subcommand("quad",
                                          "Pair the triangles of any mesh into quads (a certified "
                                          "maximum pairing; other polygons kept)");
  quad_cmd->add_option("IN", quad_args.input, "mesh: OFF, OBJ or PLY, optionally .gz")->required();
  quad_cmd
      ->add_option("OUT", quad_args.output,
                   "mesh to write (written whole, then renamed into place); format from the "
                   "extension (.off, .obj, .ply, optionally .gz)")
      ->required()
      ->check(in_existing_folder());
  quad_cmd
      ->add_option("--algorithm", quad_args.algorithm,
                   "auto (the fastest pairing, then augmenting paths), sg, ps (Puli-Segal as the "
                   "paper has it), ds, gw, frink or lrs")
      ->transform(one_of(pairing_algorithm_names()))
      ->capture_default_str();
  quad_cmd
      ->add_option("--augment", quad_args.augment,
                   "augmenting-path variant for auto, sg and ps: local or faithful")
      ->transform(one_of(names_of<Augment>()))
      ->capture_default_str();
  quad_cmd->add_option("--seed", quad_args.seed, "seed of the random orders (auto, sg, ps)")
      ->capture_default_str();
  quad_cmd
      ->add_option("--objective", quad_args.objective,
                   "quads (the exact least-cost pairing by quad shape and edge flow, leaving a "
                   "triangle where pairing it costs more than --triangle-cost; certified), "
                   "pairs (any maximum pairing, by --algorithm: fastest) or quality (the exact "
                   "maximum pairing of least quad shape cost, certified)")
      ->transform(one_of(names_of<Objective>()))
      ->capture_default_str();
  quad_cmd
      ->add_option("--triangle-cost", quad_args.triangle_cost,
                   "--objective quads: what leaving a triangle costs, in degrees of quad cost "
                   "(higher pairs more)")
      ->check(finite_in(0, petersen::kMaxTriangleCost))
      ->capture_default_str();
  quad_cmd
      ->add_option("--flow-weight", quad_args.flow_weight,
                   "--objective quads: degrees of shape per degree of edge flow (0: shape alone)")
      ->check(finite_in(0, petersen::kMaxFlowWeight))
      ->capture_default_str();
  quad_cmd
      ->add_option("--sharp-angle", quad_args.sharp_angle,
                   "never pair across an edge whose triangles fold by more than DEG degrees")
      ->check(finite_in(0, 180));
  quad_cmd
      ->add_option("--max-corner-deviation", quad_args.max_corner_deviation,
                   "only pair two triangles whose quad's worst corner is at most DEG degrees "
                   "from 90 (Blender's threshold mode, exact: the maximum pairing of what is "
                   "allowed, the cheapest with --objective quality); others stay triangles")
      ->check(finite_in(0, petersen::kDegenerateQuadCost));
  quad_cmd->add_option("--keep-edges", quad_args.keep_edges,
                       "never pair across these edges: a file of vertex id pairs, one per line");
  quad_cmd
      ->add_option("--cross", quad_args.cross,
                   "let pairs cross these cuts of the mesh's attributes, which are on by default: "
                   "uv_seam, normal_seam, material, group, object, smoothing, face_property "
                   "(comma-separated)")
      ->delimiter(',')
      ->transform(one_of(attribute_cause_names(),
                         " (the cuts of the mesh's attributes; no pair crosses the others)"));
  quad_cmd
      ->add_option("--threads", quad_args.threads,
                   "threads for the phases that split into independent parts (0: every core)")
      ->check(CLI::Range(0u, petersen::kMaxQuadThreads))
      ->capture_default_str();
  quad_cmd->add_flag(
      "--all-quad", quad_args.all_quad,
      "make every face a quad, splitting the fewest edges (certified; out of core, the fewest "
      "for each part given the parts before it)");
  quad_cmd->add_flag(
      "--keep-polygons", quad_args.keep_polygons,
      "with --all-quad: keep the input's polygons that are not triangles as they are (out of "
      "core the input is all triangles: nothing to keep)");
  quad_cmd->add_flag("--drop-duplicate-faces", quad_args.drop_duplicate_faces,
                     "drop faces with the same vertices as an earlier face before pairing");
  quad_cmd->add_flag("--strict", quad_args.strict,
                     "refuse a texture coordinate or normal index the file does not have, "
                     "instead of dropping it with a warning");
  quad_cmd
      ->add_option("--stats-json", quad_args.stats_json,
                   "also write the summary as one JSON object to this file (whole, then renamed "
                   "into place)")
      ->check(in_existing_folder());
  quad_cmd->add_option("--memory-limit", quad_args.memory_limit,
                       "convert out of core within this much memory (e.g. 3G): a binary PLY of "
                       "triangles, paired part by part (automatic when the input will not fit)");
  quad_cmd->add_option("--part-triangles", quad_args.part_triangles,
                       "out of core: triangles per part instead of from --memory-limit");

  quad_cmd
      ->add_option("--render", quad_args.render,
                   "also draw the result into this picture (.png or .svg)")
      ->check(in_existing_folder());
  quad_cmd->add_option("--view", quad_args.view, "--render's view direction x,y,z")
      ->delimiter(',')
      ->expected(3);
  quad_cmd->add_option("--render-width", quad_args.render_width)
      ->check(picture_side())
      ->capture_default_str();
  quad_cmd->add_option("--render-height", quad_args.render_height)
      ->check(picture_side())
      ->capture_default_str();
  return quad_cmd;
}

// `petersen render` and its flags, into `args`.
CLI::App* add_render_command(CLI::App& app, RenderArgs& render_args) {
  CLI::App* render_cmd = app.add_subcommand(
      "render",
      "Draw a mesh as a PNG or SVG picture: shaded, edges drawn, quads coloured by their worst "
      "corner's deviation from 90 degrees, triangles beside quads highlighted");
  render_cmd->add_option("MESH", render_args.input, "OFF, OBJ or PLY file, optionally .gz")
      ->required();
  render_cmd->add_option("OUT", render_args.output, "picture to write: .png or .svg")
      ->required()
      ->check(in_existing_folder());
  render_cmd->add_option("--view", render_args.view, "view direction x,y,z (default: automatic)")
      ->delimiter(',')
      ->expected(3);
  render_cmd->add_option("--width", render_args.width)
      ->check(picture_side())
      ->capture_default_str();
  render_cmd->add_option("--height", render_args.height)
      ->check(picture_side())
      ->capture_default_str();
  return render_cmd;
}

// `petersen generate` and its flags, into `args`.
CLI::App* add_generate_command(CLI::App& app, GenerateArgs& gen_args) {
  CLI::App* gen_cmd = app.add_subcommand(
      "generate",
      "Write a test mesh: a voxel plate with holes (genus holes-x*holes-y) or dents (genus 0), a "
      "Klein bottle, a projective plane, an open grid or a jittered grid or torus, or a quad "
      "model (a quad-dominant grid or torus, a chamfered cube); optionally with holes, fins, "
      "pinched vertices and flipped faces");
  gen_cmd->add_option("OUT", gen_args.output, "mesh to write (.off, .obj, .ply)")
      ->required()
      ->check(in_existing_folder());
  gen_cmd->add_option("--holes-x", gen_args.holes_x, "plate: through-holes along x")
      ->capture_default_str();
  gen_cmd->add_option("--holes-y", gen_args.holes_y, "plate: through-holes along y")
      ->capture_default_str();
  gen_cmd
      ->add_option("--subdivision", gen_args.subdivision,
                   "squares per voxel face side (plate); midpoint subdivision rounds (projective)")
      ->capture_default_str();
  gen_cmd->add_flag("--dents", gen_args.dents, "cavities instead of through-holes (genus 0)");
  gen_cmd->add_flag("--spatial-order", gen_args.spatial_order,
                    "plate: store triangles in Morton order of their centroids and vertices in "
                    "order of first use, as scanners and subdivisions do");
  gen_cmd
      ->add_option("--splits", gen_args.splits, "random 1-to-3 triangle splits, for irregularity")
      ->capture_default_str();
  gen_cmd->add_option("--flips", gen_args.flips, "random edge flips, for irregularity")
      ->capture_default_str();
  gen_cmd
      ->add_option("--seed", gen_args.seed,
                   "seed of the random choices (splits, flips, jitter, diagonals, holes, fins, "
                   "pinches, flipped faces)")
      ->capture_default_str();
  gen_cmd
      ->add_option("--kind", gen_args.kind,
                   "plate (a voxel plate with holes), trefoil (a tube round a trefoil knot, "
                   "made of quads each cut along one diagonal, as exporters do), klein (Klein "
                   "bottle), projective (projective plane), open-grid, jittered-grid or "
                   "jittered-torus (near-square quads cut along random diagonals), "
                   "quad-dominant or quad-dominant-torus (a quad model: near-square quads, about "
                   "3 squares in 16 left as two triangles, one pentagon and one hexagon per 100 "
                   "squares), chamfered-cube (a hard-surface model: 18 quads, 8 corner "
                   "triangles), streamed-plate (a closed plate of --triangles, written as it is "
                   "made: any size, binary PLY)")
      ->transform(one_of({"plate", "trefoil", "klein", "projective", "open-grid", "jittered-grid",
                          "jittered-torus", "quad-dominant", "quad-dominant-torus",
                          "chamfered-cube", "streamed-plate"}))
      ->capture_default_str();
  gen_cmd
      ->add_option("--triangles", gen_args.triangles, "about this many triangles (streamed-plate)")
      ->capture_default_str();
  gen_cmd->add_option("--nx", gen_args.nx,
                      "columns of klein and the grids (default 16; jittered-torus: 48, at least "
                      "3 x --ny), segments along the trefoil (default 136)");
  gen_cmd->add_option("--ny", gen_args.ny,
                      "rows of klein and the grids (default 16, at least 3 for klein and "
                      "jittered-torus), sides round the trefoil's tube (default 16)");
  gen_cmd
      ->add_option(
          "--jitter", gen_args.jitter,
          "jittered and quad-dominant grids: how far a vertex may move, a fraction of the spacing, "
          "below 0.25")
      ->check(finite_in(0, 0.2499))
      ->capture_default_str();
  gen_cmd->add_option("--holes", gen_args.holes, "random patches of faces to remove");
  gen_cmd->add_option("--fins", gen_args.fins, "triangles to add on edges (non-manifold edges)");
  gen_cmd->add_option("--pinches", gen_args.pinches, "vertex pairs to merge (pinched vertices)");
  gen_cmd->add_option("--flip-faces", gen_args.flip_faces, "faces whose orientation to reverse");
  return gen_cmd;
}

}  // namespace
}  // namespace petersen::cli

int main(int argc, char** argv) {
  using namespace petersen::cli;
  // The program's pool (memory_pool.hpp), handed to the library in the options and the default
  // resource of this process.
  if (huge_page_pool_wanted()) {
    program_pool = new petersen::HugePagePool;
    std::pmr::set_default_resource(program_pool);
  }
  CLI::App app{
      "petersen: perfect matchings of cubic bridgeless graphs, and quad meshes from closed "
      "triangle meshes"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("petersen ") + petersen::kVersion);

  std::string info_path;
  bool info_strict = false;
  CLI::App* info_cmd =
      app.add_subcommand("info",
                         "Print V, E, F by arity, components, boundary loops, non-manifold edges, "
                         "orientability, genus and the quads' worst-corner figures");
  info_cmd->add_option("MESH", info_path, "OFF, OBJ or PLY file, optionally .gz")->required();
  info_cmd->add_flag("--strict", info_strict,
                     "refuse a texture coordinate or normal index the file does not have");

  QuadArgs quad_args;
  CLI::App* quad_cmd = add_quad_command(app, quad_args);
  RenderArgs render_args;
  CLI::App* render_cmd = add_render_command(app, render_args);
  GenerateArgs gen_args;
  CLI::App* gen_cmd = add_generate_command(app, gen_args);
  MatchArgs match_args;
  CLI::App* match_cmd = add_match_command(app, match_args);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    if (code != 0) print_suggestions(app, std::vector<std::string>(argv + 1, argv + argc), stderr);
    return code;
  }
  try {
    if (info_cmd->parsed()) return info(info_path, info_strict);
    if (quad_cmd->parsed()) {
      quad_args.given = given_flags(*quad_cmd);
      return quad(quad_args);
    }
    if (gen_cmd->parsed()) return generate(gen_args);
    if (render_cmd->parsed()) return render(render_args);
    if (match_cmd->parsed()) return run_match(match_args);
  } catch (const CLI::Error& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "petersen: %s\n", e.what());
    return 1;
  }
  return 0;
}
