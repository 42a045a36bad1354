#include "out_of_core_command.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory_resource>
#include <optional>

#include "json_text.hpp"
#include "memory_pool.hpp"
#include "petersen/generators/streamed_plate.hpp"
#include "petersen/graph/memory.hpp"
#include "petersen/io/file_bytes.hpp"
#include "petersen/io/ply_stream.hpp"
#include "petersen/memory_pool/huge_page_pool.hpp"
#include "petersen/partition/out_of_core.hpp"

namespace petersen::cli {

namespace {

// What `petersen quad` holds per triangle at its peak, by objective (bench/RESULTS.md, "Scale", and
// docs/distributed.md): pairs on a closed mesh; the minimum-cost matching's doubled graph for
// quads, and for quality on an open mesh also the maximum matching that sizes its price.
double in_memory_bytes_per_triangle(Objective objective) {
  return objective == Objective::pairs ? 55 : objective == Objective::quads ? 600 : 800;
}
// A binary PLY of a closed triangle mesh: 13 bytes per face and 12 per vertex, half a vertex per
// face.
constexpr double kPlyBytesPerTriangle = 19;

// MemAvailable from /proc/meminfo, in bytes; nothing where it cannot be read.
std::optional<std::uint64_t> available_memory() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  std::uint64_t kib = 0;
  std::string unit;
  while (meminfo >> key >> kib >> unit) {
    if (key == "MemAvailable:") return kib * 1024;
  }
  return std::nullopt;
}

// The gap between the total and the lower bound, absolute and relative to the total (0 when both
// are 0).
std::pair<double, double> gap_of(const OutOfCoreStats& s) {
  const double gap = std::max(0.0, s.objective_total - s.lower_bound);
  return {gap, s.objective_total > 0 ? gap / s.objective_total : 0.0};
}

// The figures as one JSON object: the keys of the in-memory --stats-json where the meaning is the
// same (input, output, objective, algorithm, triangle_cost, flow_weight, vertices, faces_in,
// triangles, pairs, triangles_left, quality_median, quality_p95, nonconvex_quads,
// maximum_certified, objective_total, optimality_certified, total_seconds), and the parts' own.
void write_stats_json(const std::string& path, const OutOfCoreArgs& args, const OutOfCoreStats& s) {
  const Objective objective = args.costs.objective;
  std::string json = "{\"mode\": \"out_of_core\", \"objective\": " +
                     json_string(std::string(to_string(objective))) + ", \"algorithm\": " +
                     json_string(objective == Objective::pairs ? "auto" : "min-cost");
  auto add = [&](const char* key, const std::string& value) {
    json += std::string(", \"") + key + "\": " + value;
  };
  auto u = [&](const char* key, std::uint64_t value) { add(key, std::to_string(value)); };
  auto b = [&](const char* key, bool value) { add(key, value ? "true" : "false"); };
  auto d = [&](const char* key, double value, const char* format = "%.3f") {
    char text[64];
    std::snprintf(text, sizeof text, format, value);
    add(key, text);
  };
  add("input", json_string(args.input));
  add("output", json_string(args.output));
  if (objective == Objective::quads) {
    d("triangle_cost", args.costs.triangle_cost, "%.17g");
    d("flow_weight", 0.0, "%.17g");  // shape alone: --flow-weight is refused out of core
  }
  if (args.costs.max_corner_deviation) {
    d("max_corner_deviation", *args.costs.max_corner_deviation, "%.17g");
  }
  if (args.costs.sharp_angle_degrees) d("sharp_angle", *args.costs.sharp_angle_degrees, "%.17g");
  u("vertices", s.vertices);
  u("faces_in", s.triangles);  // out of core takes triangles only
  u("triangles", s.triangles);
  u("parts", s.parts);
  u("part_triangles", s.part_triangles);
  u("pairs", s.pairs);
  u("triangles_left", s.triangles_left);
  u("unpaired_after_parts", s.unpaired_after_parts);
  d("quality_median", s.quality_median, "%.17g");
  d("quality_p95", s.quality_p95, "%.17g");
  u("nonconvex_quads", s.nonconvex_quads);
  u("cut_adjacencies", s.cut_adjacencies);
  if (objective == Objective::pairs) {
    u("repaired", s.repaired);
    u("band_faces", s.band_faces);
    u("band_graph_faces", s.band_graph_faces);
    u("repair_radius", s.repair_radius);
  } else {
    u("band_faces", s.band_faces);
    u("seam_pairs", s.seam_pairs);
    u("seam_graph_faces", s.seam_graph_faces);
  }
  b("closed", s.closed);
  b("perfect_certified", s.perfect_certified);
  b("maximum_certified", s.perfect_certified);
  if (objective == Objective::pairs) {
    b("parts_certified", s.parts_certified);
  } else {
    d("objective_total", s.objective_total, "%.17g");
    b("costs_certified", s.costs_certified);
    if (s.lower_bound_valid) {
      const auto [gap, relative] = gap_of(s);
      d("lower_bound", s.lower_bound, "%.17g");
      d("gap", gap, "%.17g");
      d("gap_relative", relative, "%.17g");
    }
    b("optimality_certified", s.optimality_certified);
  }
  if (args.all_quad) {
    // The in-memory keys where they apply: added_vertices_minimum and all_quad_certified claim
    // a whole-mesh minimum, which part by part is not proved (all_quad_parts_certified: each
    // part's T-join is minimal for its own T).
    u("added_vertices", s.added_vertices);
    u("split_edges", s.split_edges);
    u("degenerate_faces", s.degenerate_faces);
    u("centre_vertices", s.centre_vertices);
    b("all_quad_certified", false);
    b("all_quad_parts_certified", s.all_quad_parts_certified);
    u("all_quad_parts", s.all_quad_parts);
    u("split_quads", s.split_quads);
    d("split_quality_median", s.split_quality_median);
    d("split_quality_p95", s.split_quality_p95);
    u("faces_out", s.faces_out);
    d("all_quad_seconds", s.all_quad_seconds);
  }
  u("temp_bytes", s.temp_bytes);
  d("read_pair_seconds", s.read_pair_seconds);
  d("cut_seconds", s.cut_seconds);
  d(objective == Objective::pairs ? "repair_seconds" : "seam_seconds", s.repair_seconds);
  d("write_seconds", s.write_seconds);
  d("total_seconds", s.total_seconds);
  json += "}\n";
  cli::write_printed(path, [&](std::FILE* file) { std::fputs(json.c_str(), file); });
}

// What the cost objectives' summary says they proved.
void print_costs(const OutOfCoreStats& s, Objective objective) {
  std::printf(
      "pairs: %llu, triangles left: %llu (unpaired after the parts: %llu, paired across the "
      "cuts: %llu; seam graph %llu faces)\n",
      (unsigned long long)s.pairs, (unsigned long long)s.triangles_left,
      (unsigned long long)s.unpaired_after_parts, (unsigned long long)(2 * s.seam_pairs),
      (unsigned long long)s.seam_graph_faces);
  if (objective == Objective::quads) {
    const auto [gap, relative] = gap_of(s);
    std::printf("objective quads: total %.6f, lower bound %.6f, gap %.6f (%.4f%%): %s\n",
                s.objective_total, s.lower_bound, gap, 100 * relative,
                s.optimality_certified ? "optimum certified" : "optimal within gap");
  } else {
    std::printf("objective quality: total %.6f; maximum per part, cost not certified\n",
                s.objective_total);
  }
  std::printf("certified: %s\n",
              s.perfect_certified
                  ? "perfect (closed mesh, every triangle paired, every pair checked)"
                  : "every pair checked; each part's and the seams' matching by its certificate");
}

}  // namespace

std::uint64_t parse_memory_size(const std::string& text) {
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    throw CLI::ValidationError("--memory-limit", "not a size: " + text);
  }
  std::string unit = text.substr(used);
  if (!unit.empty() && (unit.back() == 'B' || unit.back() == 'b')) unit.pop_back();
  if (unit.size() == 2 && (unit[1] == 'i' || unit[1] == 'I')) unit.pop_back();
  const std::string units = "KMGT";
  double scale = 1;
  if (unit.size() == 1 && units.find(char(std::toupper(unit[0]))) != std::string::npos) {
    scale = std::pow(1024.0, double(units.find(char(std::toupper(unit[0]))) + 1));
  } else if (!unit.empty()) {
    throw CLI::ValidationError("--memory-limit", "unknown unit in " + text + " (K, M, G or T)");
  }
  if (!(value > 0) || value * scale > 1e18) {
    throw CLI::ValidationError("--memory-limit", "not a positive size: " + text);
  }
  return static_cast<std::uint64_t>(value * scale);
}

std::optional<std::uint64_t> out_of_core_limit(const std::string& input,
                                               const std::string& memory_limit,
                                               Objective objective) {
  if (!memory_limit.empty()) {
    if (!ends_with_nocase(input, ".ply")) {
      throw CLI::ValidationError(
          "--memory-limit",
          "the out-of-core conversion reads a binary PLY of triangles (.ply), "
          "not " +
              input + "; without --memory-limit it is converted in memory");
    }
    return parse_memory_size(memory_limit);
  }
  std::error_code error;
  const std::uintmax_t bytes = std::filesystem::file_size(input, error);
  if (error || !ends_with_nocase(input, ".ply")) return std::nullopt;
  const std::optional<std::uint64_t> available = available_memory();
  const double needed =
      double(bytes) / kPlyBytesPerTriangle * in_memory_bytes_per_triangle(objective);
  if (!available || needed <= double(*available)) return std::nullopt;
  std::fprintf(stderr,
               "petersen: %s needs about %.1f GB in memory for --objective %s, %.1f GB are "
               "available: converting out of core with --memory-limit %.1fG\n",
               input.c_str(), needed / 1e9, std::string(to_string(objective)).c_str(),
               double(*available) / 1e9, double(*available / 2) / double(1u << 30));
  return *available / 2;
}

int quad_out_of_core_command(const OutOfCoreArgs& args) {
  const auto augment = parse_augment(args.augment);
  if (!augment) throw CLI::ValidationError("--augment", "unknown augmentation " + args.augment);
  if (!ends_with_nocase(args.output, ".ply")) {
    throw CLI::ValidationError("OUT", "the out-of-core conversion writes binary PLY (.ply)");
  }
  // Each part's arrays are the next part's: kept in a pool, they are not faulted in afresh for
  // every part (memory_pool.hpp). What it keeps and what it has handed out stay within seven
  // eighths of the limit together (its footprint), so that kept memory never takes the run past
  // it: the last eighth is for what the pool does not serve (small blocks, the matching's results,
  // buffers, the program). It is the default resource for the run, in place of the program's.
  std::optional<HugePagePool> pool;
  const std::uint64_t footprint = args.memory_limit - args.memory_limit / 8;
  if (huge_page_pool_wanted()) pool.emplace(footprint, footprint);
  std::pmr::memory_resource* const before = std::pmr::get_default_resource();
  if (pool) std::pmr::set_default_resource(&*pool);
  std::pmr::memory_resource* const memory = pool ? &*pool : before;
  struct Restore {
    std::pmr::memory_resource* before;
    ~Restore() { std::pmr::set_default_resource(before); }
  } restore{before};
  const OutOfCoreStats s = quad_out_of_core(args.input, args.output,
                                            {.costs = args.costs,
                                             .memory_limit = args.memory_limit,
                                             .part_triangles = args.part_triangles,
                                             .augment = *augment,
                                             .all_quad = args.all_quad,
                                             .keep_polygons = args.keep_polygons,
                                             .threads = args.threads,
                                             .memory = memory});
  std::printf("%s: %llu triangles in %llu part%s of %llu, out of core, objective %s\n",
              args.input.c_str(), (unsigned long long)s.triangles, (unsigned long long)s.parts,
              s.parts == 1 ? "" : "s", (unsigned long long)s.part_triangles,
              std::string(to_string(args.costs.objective)).c_str());
  if (args.costs.objective != Objective::pairs) {
    // With --all-quad, quads pairs the cheapest maximum, as quality (as in memory).
    print_costs(s, args.all_quad ? Objective::quality : args.costs.objective);
  } else {
    std::printf(
        "pairs: %llu, triangles left: %llu (unpaired after the parts: %llu, paired across "
        "the cuts: %llu; band graph %llu faces, radius %u)\n",
        (unsigned long long)s.pairs, (unsigned long long)s.triangles_left,
        (unsigned long long)s.unpaired_after_parts, (unsigned long long)(2 * s.repaired),
        (unsigned long long)s.band_graph_faces, s.repair_radius);
    std::printf(
        "certified: %s\n",
        s.perfect_certified ? "perfect (closed mesh, every triangle paired, every pair checked)"
        : s.parts_certified ? "every pair checked; each part's and the band's pairing maximum"
                            : "every pair checked");
  }
  std::printf("quality: median %.2f, 95th percentile %.2f degrees, %llu non-convex\n",
              s.quality_median, s.quality_p95, (unsigned long long)s.nonconvex_quads);
  if (args.all_quad) {
    std::printf(
        "all-quad: %llu faces, all quads%s; %llu vertices added (%llu midpoints, %llu centres) in "
        "%llu parts, each part's midpoints the fewest for it (%s), whole-mesh minimum not proved; "
        "%llu split quads, worst corner median %.1f, p95 %.1f\n",
        (unsigned long long)s.faces_out,
        s.degenerate_faces > 0 ? " but the faces repeating a vertex, kept" : "",
        (unsigned long long)s.added_vertices, (unsigned long long)s.split_edges,
        (unsigned long long)s.centre_vertices, (unsigned long long)s.all_quad_parts,
        s.all_quad_parts_certified ? "certified" : "NOT certified",
        (unsigned long long)s.split_quads, s.split_quality_median, s.split_quality_p95);
  }
  std::printf(
      "time: %.2f s (read and pair %.2f, cut %.2f, %s %.2f, %s %.2f); temporary files "
      "%.2f GB\n",
      s.total_seconds, s.read_pair_seconds, s.cut_seconds,
      args.costs.objective == Objective::pairs ? "repair" : "seams", s.repair_seconds,
      args.all_quad ? "all-quad and write" : "write",
      args.all_quad ? s.all_quad_seconds : s.write_seconds, double(s.temp_bytes) / 1e9);
  std::printf("%s written\n", args.output.c_str());
  if (!args.stats_json.empty()) write_stats_json(args.stats_json, args, s);
  return 0;
}

int generate_streamed_plate(const std::string& output, std::uint64_t triangles) {
  if (!ends_with_nocase(output, ".ply")) {
    throw CLI::ValidationError("OUT", "the streamed plate is written as binary PLY (.ply)");
  }
  const StreamedPlate plate = streamed_plate_of_size(triangles);
  PlyStreamWriter out(output,
                      "element vertex " + std::to_string(plate.vertices()) +
                          "\nproperty float x\nproperty float y\nproperty float z\n",
                      plate.triangles());
  for_each_plate_vertex(plate, [&](float x, float y, float z) {
    const float xyz[3] = {x, y, z};
    out.write_vertex_records({reinterpret_cast<const char*>(xyz), sizeof xyz});
  });
  for_each_plate_triangle(plate,
                          [&](VertexId a, VertexId b, VertexId c) { out.write_triangle(a, b, c); });
  out.commit();
  std::printf("%llu triangles, %llu vertices written to %s\n",
              (unsigned long long)plate.triangles(), (unsigned long long)plate.vertices(),
              output.c_str());
  return 0;
}

}  // namespace petersen::cli
