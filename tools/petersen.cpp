// petersen: triangle mesh of a closed surface -> all-quad mesh on the same vertices.

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <memory>

#include "petersen/dualize/dual.hpp"
#include "petersen/dualize/quads.hpp"
#include "petersen/dualize/read_mesh.hpp"
#include "petersen/dualize/surface_check.hpp"
#include "petersen/dualize/surface_generators.hpp"
#include "petersen/dualize/write_mesh.hpp"
#include "petersen/graph/huge_pages.hpp"
#include "petersen/lemon_peer/lemon_peer.hpp"
#include "petersen/lrs/lrs.hpp"
#include "petersen/matching/perfect_matching.hpp"
#include "petersen/version.hpp"
#include "match_command.hpp"
#include "run_report.hpp"

namespace petersen::cli {
namespace {

class Clock {
 public:
  double lap() {
    auto now = std::chrono::steady_clock::now();
    double s = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return s;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

int info(const std::string& path) {
  TriangleMesh mesh = read_triangle_mesh(path);
  SurfaceReport report = inspect_surface(mesh);
  std::fputs(describe(report).c_str(), stdout);
  return 0;
}

// The verifier is O(n): every answer is checked before anything is written.
void verify_or_throw(const CubicGraph& graph, const Matching& matching,
                     const std::string& algorithm) {
  if (MatchingCheck check = verify_perfect_matching(graph, matching); !check.ok()) {
    throw std::logic_error("internal error: " + algorithm +
                           " returned a matching that is not perfect: " + check.message);
  }
}

struct QuadArgs {
  std::string input, output, algorithm = "ps", augment = "local", stats_json;
  std::uint64_t seed = 1;
};

// Checks, matches, verifies and writes; MeshErrors are prefixed with the input by the caller.
void convert(const QuadArgs& args, const TriangleMesh& mesh, RunReport& report, Clock& total) {
  Clock clock;
  SurfaceReport surface = inspect_surface(mesh);
  require_closed_surface(surface);
  report.vertices = surface.vertices;
  report.triangles = mesh.triangles.size();
  report.genus = surface.genus.value_or(0);
  report.components = surface.components;

  QuadMesh quads;
  auto augment = parse_augment(args.augment);
  if (!augment) throw CLI::ValidationError("--augment", "unknown augmentation " + args.augment);
  report.augment = args.augment;
  if (args.algorithm == "lrs") {
    report.algorithm = "lrs";
    LrsResult result = quadrangulate_lrs(mesh, {.augment = *augment});
    report.initial_seconds = result.stats.contraction_seconds + result.stats.expansion_seconds;
    report.unpaired_after_initial = result.stats.unpaired_after_expansion;
    report.augment_seconds = result.stats.augment_seconds;
    report.augmenting_paths = result.stats.augmenting_paths;
    report.flipped_edges = result.stats.flipped_edges;
    report.irreducible_vertices = result.stats.irreducible_vertices;
    verify_or_throw(result.dual, result.matching, report.algorithm);
    quads = std::move(result.quads);
  } else {
    auto algorithm = parse_algorithm(args.algorithm);
    if (!algorithm) {
      throw CLI::ValidationError("--algorithm", "unknown algorithm " + args.algorithm);
    }
    report.algorithm = args.algorithm;
    if (*algorithm != Algorithm::sg && *algorithm != Algorithm::ps) report.augment.clear();
    clock.lap();
    Dual dual = build_dual(mesh);
    report.dual_seconds = clock.lap();
    Result result = perfect_matching(dual.graph, {.algorithm = *algorithm,
                                                  .augment = *augment,
                                                  .seed = args.seed,
                                                  .validate = false,
                                                  .peer = &lemon_peer::maximum_matching});
    report.initial_seconds = result.stats.initial_seconds;
    report.unpaired_after_initial = result.stats.unpaired_after_initial;
    report.augment_seconds = result.stats.augment_seconds;
    report.augmenting_paths = result.stats.augmenting_paths;
    report.blossoms = result.stats.blossoms;
    report.nodes_labelled = result.stats.nodes_labelled;
    report.reductions = result.stats.reductions;
    verify_or_throw(dual.graph, result.matching, report.algorithm);
    quads = quads_from_matching(mesh, dual.graph, result.matching);
  }
  if (QuadCheck check = check_quad_mesh(mesh, quads); !check.ok()) {
    throw std::logic_error("internal error: the quad mesh fails its check: " + check.problem);
  }
  clock.lap();
  write_quad_mesh(args.output, quads);
  report.write_seconds = clock.lap();
  report.quads = quads.quads.size();
  report.total_seconds = total.lap();
  print_summary(stdout, report);
  if (!args.stats_json.empty()) {
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(args.stats_json.c_str(), "w"),
                                                         &std::fclose);
    if (!file) throw std::runtime_error("cannot write " + args.stats_json);
    write_json(file.get(), report);
  }
}

int quad(const QuadArgs& args) {
  RunReport report;
  report.input = args.input;
  report.output = args.output;
  mesh_format_of(args.output);  // an unknown output format fails before any work
  Clock total, clock;
  TriangleMesh mesh = read_triangle_mesh(args.input);
  report.load_seconds = clock.lap();
  try {
    convert(args, mesh, report, total);
  } catch (const MeshError& e) {
    throw MeshError(args.input + ": " + e.what());  // the reader's own errors name it already
  }
  return 0;
}

struct GenerateArgs {
  std::string output;
  std::uint32_t holes_x = 2, holes_y = 1, subdivision = 4, splits = 0, flips = 0;
  bool dents = false;
  std::uint64_t seed = 1;
};

int generate(const GenerateArgs& args) {
  TriangleMesh mesh = voxel_plate({args.holes_x, args.holes_y, args.subdivision, args.dents});
  if (args.splits > 0 || args.flips > 0) {
    mesh = randomize_triangulation(std::move(mesh), args.splits, args.flips, args.seed);
  }
  write_triangle_mesh(args.output, mesh);
  std::printf("%zu triangles, %zu vertices written to %s\n", mesh.triangles.size(),
              mesh.positions.size(), args.output.c_str());
  return 0;
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
  CLI::App* info_cmd = app.add_subcommand(
      "info", "Print V, E, F, components, genus and what kind of surface a mesh is");
  info_cmd->add_option("MESH", info_path, "OFF, OBJ or PLY file, optionally .gz")->required();

  QuadArgs quad_args;
  CLI::App* quad_cmd = app.add_subcommand(
      "quad", "Convert a closed triangle mesh into a quad mesh on the same vertices");
  quad_cmd
      ->add_option("IN", quad_args.input, "closed triangle mesh: OFF, OBJ or PLY, optionally .gz")
      ->required();
  quad_cmd
      ->add_option("OUT", quad_args.output,
                   "quad mesh to write; format from the extension (.off, .obj, .ply)")
      ->required();
  quad_cmd->add_option("--algorithm", quad_args.algorithm, "sg, ps, ds, gw, frink, lemon or lrs")
      ->capture_default_str();
  quad_cmd
      ->add_option("--augment", quad_args.augment,
                   "augmenting-path variant for sg and ps: local or faithful")
      ->capture_default_str();
  quad_cmd->add_option("--seed", quad_args.seed, "seed of the random orders (sg, ps)")
      ->capture_default_str();
  quad_cmd->add_option("--stats-json", quad_args.stats_json,
                       "also write the summary as one JSON object to this file");

  GenerateArgs gen_args;
  CLI::App* gen_cmd = app.add_subcommand("generate",
                                         "Write a closed test triangulation: a voxel plate with "
                                         "holes (genus holes-x*holes-y) or dents (genus 0)");
  gen_cmd->add_option("OUT", gen_args.output, "mesh to write (.off, .obj, .ply)")->required();
  gen_cmd->add_option("--holes-x", gen_args.holes_x)->capture_default_str();
  gen_cmd->add_option("--holes-y", gen_args.holes_y)->capture_default_str();
  gen_cmd->add_option("--subdivision", gen_args.subdivision, "squares per voxel face side")
      ->capture_default_str();
  gen_cmd->add_flag("--dents", gen_args.dents, "cavities instead of through-holes (genus 0)");
  gen_cmd
      ->add_option("--splits", gen_args.splits, "random 1-to-3 triangle splits, for irregularity")
      ->capture_default_str();
  gen_cmd->add_option("--flips", gen_args.flips, "random edge flips, for irregularity")
      ->capture_default_str();
  gen_cmd->add_option("--seed", gen_args.seed)->capture_default_str();

  MatchArgs match_args;
  CLI::App* match_cmd = add_match_command(app, match_args);

  CLI11_PARSE(app, argc, argv);
  try {
    if (info_cmd->parsed()) return info(info_path);
    if (quad_cmd->parsed()) return quad(quad_args);
    if (gen_cmd->parsed()) return generate(gen_args);
    if (match_cmd->parsed()) return run_match(match_args);
  } catch (const CLI::Error& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "petersen: %s\n", e.what());
    return 1;
  }
  return 0;
}
