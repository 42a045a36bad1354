// petersen: any mesh -> its triangles paired into quads on the same vertices; graphs -> matchings.

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <vector>

#include "json_text.hpp"
#include "keep_edges.hpp"
#include "match_command.hpp"
#include "option_checks.hpp"
#include "out_of_core_command.hpp"
#include "petersen/dualize/quad_quality.hpp"
#include "petersen/generators/polygon_generators.hpp"
#include "petersen/generators/surface_generators.hpp"
#include "petersen/graph/huge_pages.hpp"
#include "petersen/graph/stopwatch.hpp"
#include "petersen/io/read_mesh.hpp"
#include "petersen/io/write_mesh.hpp"
#include "petersen/lemon_peer/lemon_peer.hpp"
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
  PolygonMesh mesh = read_mesh(path, &dropped, {.strict = strict});
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
  std::string input, output, algorithm = "auto", augment = "local", objective = "pairs", stats_json,
                             render;
  std::vector<double> view;
  std::uint32_t render_width = 800, render_height = 800;
  std::uint64_t seed = 1;
  std::uint32_t threads = 0;
  bool all_quad = false, keep_polygons = false, strict = false, drop_duplicate_faces = false;
  std::optional<double> sharp_angle, max_corner_deviation;
  std::string keep_edges;
  std::vector<std::string> cross;
  std::string memory_limit;
  std::uint64_t part_triangles = 0;
};

int quad(const QuadArgs& args) {
  if (const auto limit = out_of_core_limit(args.input, args.memory_limit)) {
    if (args.drop_duplicate_faces) {
      throw CLI::ValidationError("--drop-duplicate-faces", "not available out of core");
    }
    return quad_out_of_core_command({.input = args.input,
                                     .output = args.output,
                                     .augment = args.augment,
                                     .stats_json = args.stats_json,
                                     .memory_limit = *limit,
                                     .part_triangles = args.part_triangles,
                                     .threads = args.threads});
  }
  const auto algorithm = parse_algorithm(args.algorithm);
  if (!algorithm) throw CLI::ValidationError("--algorithm", "unknown algorithm " + args.algorithm);
  const auto augment = parse_augment(args.augment);
  if (!augment) throw CLI::ValidationError("--augment", "unknown augmentation " + args.augment);
  const auto objective = parse_objective(args.objective);
  if (!objective) throw CLI::ValidationError("--objective", "unknown objective " + args.objective);
  mesh_format_of(args.output);  // an unknown output format fails before any work
  std::vector<CutCause> cross;
  for (const std::string& name : args.cross) {
    const auto cause = parse_cut_cause(name);
    if (!cause || !is_attribute_cause(*cause)) {
      throw CLI::ValidationError("--cross",
                                 "not a cut of the mesh's attributes: " + name +
                                     " (uv_seam, normal_seam, material, group, object, smoothing "
                                     "or face_property)");
    }
    cross.push_back(*cause);
  }
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
  report.options.peer = &lemon_peer::maximum_matching;
  report.options.cross = cross;
  report.options.threads = args.threads;
  // The tool writes the mesh and the stats, never the quads' sources: not asking for them lets
  // lrs free the input's corners early (12 bytes per triangle at its peak).
  report.options.sources = false;
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
  QuadResult result;
  try {
    // Consumed: its positions become the output's, not a copy of them.
    result = quadrangulate(std::move(mesh), report.options);
  } catch (const MeshError& e) {
    throw MeshError(args.input + ": " + e.what());  // the reader's own errors name it already
  }
  report.quad = result.stats;
  // The rest of the input is not needed past this point: freed before the output's bytes are
  // built beside the output mesh, where the peak would otherwise be.
  mesh = {};
  clock.lap();
  warn_dropped(args.output, write_mesh(args.output, result.mesh));
  report.write_seconds = clock.lap();
  report.total_seconds = total.lap();
  print_summary(stdout, report);
  if (!args.stats_json.empty()) {
    write_printed(args.stats_json, [&](std::FILE* out) { write_json(out, report); });
  }
  if (!args.render.empty()) {
    const QuadStats& s = result.stats;
    RenderOptions options;
    options.view = view;
    options.width = args.render_width;
    options.height = args.render_height;
    options.first_added_vertex = input_vertices;
    options.caption = {std::filesystem::path(args.input).filename().string() + " by " +
                           (report.options.objective == Objective::quality
                                ? std::string("min-cost (objective quality)")
                                : std::string(to_string(report.options.algorithm))) +
                           (args.all_quad ? ", all quads" : ""),
                       std::to_string(s.faces_in) + " faces in: " + std::to_string(s.pairs) +
                           " pairs, " + std::to_string(s.triangles_left) + " triangles left, " +
                           std::to_string(s.polygons_kept) + " polygons kept, " +
                           std::to_string(s.added_vertices) + " vertices added",
                       describe(quality_figures(quad_costs(result.mesh)))};
    render_mesh(result.mesh, args.render, options);
  }
  return 0;
}

struct GenerateArgs {
  std::string output, kind = "plate";
  std::uint32_t holes_x = 2, holes_y = 1, subdivision = 4, splits = 0, flips = 0;
  std::uint32_t nx = 16, ny = 16, holes = 0, fins = 0, pinches = 0, flip_faces = 0;
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

PolygonMesh generated_surface(const GenerateArgs& args) {
  if (args.kind == "klein") return klein_bottle(args.nx, args.ny);
  if (args.kind == "projective") return projective_plane(args.subdivision);
  if (args.kind == "open-grid") return open_grid(args.nx, args.ny);
  if (args.kind == "jittered-grid" || args.kind == "jittered-torus") {
    return jittered_grid({.nx = args.nx,
                          .ny = args.ny,
                          .jitter = args.jitter,
                          .torus = args.kind == "jittered-torus",
                          .seed = args.seed});
  }
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
  const PolygonMesh mesh = generated_mesh(args);
  write_mesh(args.output, mesh);
  std::printf("%zu triangles, %zu vertices written to %s\n", mesh.face_count(),
              mesh.positions.size(), args.output.c_str());
  return 0;
}

// render_mesh's limits, checked before any work.
CLI::Range picture_side() {
  return CLI::Range(200u, 16384u);
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
                   "paper has it), ds, gw, frink, lemon or lrs")
      ->capture_default_str();
  quad_cmd
      ->add_option("--augment", quad_args.augment,
                   "augmenting-path variant for auto, sg and ps: local or faithful")
      ->capture_default_str();
  quad_cmd->add_option("--seed", quad_args.seed, "seed of the random orders (auto, sg, ps)")
      ->capture_default_str();
  quad_cmd
      ->add_option("--objective", quad_args.objective,
                   "pairs (any maximum pairing, by --algorithm) or quality (the exact "
                   "minimum-cost pairing by quad shape, certified)")
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
      ->delimiter(',');
  quad_cmd
      ->add_option("--threads", quad_args.threads,
                   "threads for the phases that split into independent parts (0: every core)")
      ->check(CLI::Range(0u, petersen::kMaxQuadThreads))
      ->capture_default_str();
  quad_cmd->add_flag("--all-quad", quad_args.all_quad,
                     "make every face a quad, splitting the fewest edges (certified)");
  quad_cmd->add_flag(
      "--keep-polygons", quad_args.keep_polygons,
      "with --all-quad: keep the input's polygons that are not triangles as they are");
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
  render_cmd->add_option("OUT", render_args.output, "picture to write: .png or .svg")->required();
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
      "Write a test triangulation: a voxel plate with holes (genus holes-x*holes-y) or dents "
      "(genus 0), a Klein bottle, a projective plane, an open grid or a jittered grid or torus; "
      "optionally with holes, "
      "fins, pinched vertices and flipped faces");
  gen_cmd->add_option("OUT", gen_args.output, "mesh to write (.off, .obj, .ply)")->required();
  gen_cmd->add_option("--holes-x", gen_args.holes_x)->capture_default_str();
  gen_cmd->add_option("--holes-y", gen_args.holes_y)->capture_default_str();
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
  gen_cmd->add_option("--seed", gen_args.seed)->capture_default_str();
  gen_cmd
      ->add_option("--kind", gen_args.kind,
                   "plate, klein (Klein bottle), projective (projective plane), open-grid, "
                   "jittered-grid or jittered-torus (near-square quads cut along random "
                   "diagonals), streamed-plate (a closed plate of --triangles, written as it is "
                   "made: any size, binary PLY)")
      ->check(CLI::IsMember({"plate", "klein", "projective", "open-grid", "jittered-grid",
                             "jittered-torus", "streamed-plate"}))
      ->capture_default_str();
  gen_cmd
      ->add_option("--triangles", gen_args.triangles, "about this many triangles (streamed-plate)")
      ->capture_default_str();
  gen_cmd->add_option("--nx", gen_args.nx, "grid columns of klein and the grids")
      ->capture_default_str();
  gen_cmd->add_option("--ny", gen_args.ny, "grid rows of klein and the grids")
      ->capture_default_str();
  gen_cmd
      ->add_option("--jitter", gen_args.jitter,
                   "jittered grids: how far a vertex may move, a fraction of the spacing")
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
  petersen::huge_pages::enable_pool_unless_switched_off();
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

  CLI11_PARSE(app, argc, argv);
  try {
    if (info_cmd->parsed()) return info(info_path, info_strict);
    if (quad_cmd->parsed()) return quad(quad_args);
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
