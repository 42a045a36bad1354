#include "out_of_core_command.hpp"

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "json_text.hpp"
#include "petersen/generators/streamed_plate.hpp"
#include "petersen/graph/huge_pages.hpp"
#include "petersen/io/file_bytes.hpp"
#include "petersen/io/ply_stream.hpp"
#include "petersen/partition/out_of_core.hpp"

namespace petersen::cli {

namespace {

// What `petersen quad` holds per triangle of a closed mesh at its peak (bench/RESULTS.md, "Scale").
constexpr double kInMemoryBytesPerTriangle = 55;
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

void write_stats_json(const std::string& path, const OutOfCoreStats& s) {
  cli::write_printed(path, [&](std::FILE* file) {
    std::fprintf(file,
                 "{\"mode\": \"out_of_core\", \"vertices\": %llu, \"triangles\": %llu, \"parts\": "
                 "%llu, \"part_triangles\": %llu, \"pairs\": %llu, \"triangles_left\": %llu, "
                 "\"unpaired_after_parts\": %llu, \"repaired\": %llu, \"cut_adjacencies\": %llu, "
                 "\"band_faces\": %llu, \"band_graph_faces\": %llu, \"repair_radius\": %u, "
                 "\"closed\": %s, \"perfect_certified\": %s, \"parts_certified\": %s, "
                 "\"temp_bytes\": %llu, \"read_pair_seconds\": %.3f, "
                 "\"cut_seconds\": %.3f, \"repair_seconds\": %.3f, \"write_seconds\": %.3f, "
                 "\"total_seconds\": %.3f}\n",
                 (unsigned long long)s.vertices, (unsigned long long)s.triangles,
                 (unsigned long long)s.parts, (unsigned long long)s.part_triangles,
                 (unsigned long long)s.pairs, (unsigned long long)s.triangles_left,
                 (unsigned long long)s.unpaired_after_parts, (unsigned long long)s.repaired,
                 (unsigned long long)s.cut_adjacencies, (unsigned long long)s.band_faces,
                 (unsigned long long)s.band_graph_faces, s.repair_radius,
                 s.closed ? "true" : "false", s.perfect_certified ? "true" : "false",
                 s.parts_certified ? "true" : "false", (unsigned long long)s.temp_bytes,
                 s.read_pair_seconds, s.cut_seconds, s.repair_seconds, s.write_seconds,
                 s.total_seconds);
  });
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
                                               const std::string& memory_limit) {
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
  const double needed = double(bytes) / kPlyBytesPerTriangle * kInMemoryBytesPerTriangle;
  if (!available || needed <= double(*available)) return std::nullopt;
  std::fprintf(stderr,
               "petersen: %s needs about %.1f GB in memory, %.1f GB are available: converting out "
               "of core with --memory-limit %.1fG\n",
               input.c_str(), needed / 1e9, double(*available) / 1e9,
               double(*available / 2) / double(1u << 30));
  return *available / 2;
}

int quad_out_of_core_command(const OutOfCoreArgs& args) {
  const auto augment = parse_augment(args.augment);
  if (!augment) throw CLI::ValidationError("--augment", "unknown augmentation " + args.augment);
  if (!ends_with_nocase(args.output, ".ply")) {
    throw CLI::ValidationError("OUT", "the out-of-core conversion writes binary PLY (.ply)");
  }
  // Each part's arrays are the next part's: kept in the pool up to the limit, they are not
  // faulted in afresh for every part (fresh pages are the slow ones on a virtual machine,
  // huge_pages.hpp). The pool stays off where the environment switches it off.
  const char* pool = std::getenv("PETERSEN_HUGE_PAGE_POOL");
  if (pool == nullptr || std::string_view(pool) != "off")
    huge_pages::enable_pool(args.memory_limit);
  const OutOfCoreStats s = quad_out_of_core(args.input, args.output,
                                            {.memory_limit = args.memory_limit,
                                             .part_triangles = args.part_triangles,
                                             .augment = *augment,
                                             .threads = args.threads});
  std::printf("%s: %llu triangles in %llu part%s of %llu, out of core\n", args.input.c_str(),
              (unsigned long long)s.triangles, (unsigned long long)s.parts, s.parts == 1 ? "" : "s",
              (unsigned long long)s.part_triangles);
  std::printf(
      "pairs: %llu, triangles left: %llu (unpaired after the parts: %llu, paired across "
      "the cuts: %llu; band graph %llu faces, radius %u)\n",
      (unsigned long long)s.pairs, (unsigned long long)s.triangles_left,
      (unsigned long long)s.unpaired_after_parts, (unsigned long long)(2 * s.repaired),
      (unsigned long long)s.band_graph_faces, s.repair_radius);
  std::printf("certified: %s\n",
              s.perfect_certified
                  ? "perfect (closed mesh, every triangle paired, every pair checked)"
              : s.parts_certified ? "every pair checked; each part's and the band's pairing maximum"
                                  : "every pair checked");
  std::printf(
      "time: %.2f s (read and pair %.2f, cut %.2f, repair %.2f, write %.2f); temporary "
      "files %.2f GB\n",
      s.total_seconds, s.read_pair_seconds, s.cut_seconds, s.repair_seconds, s.write_seconds,
      double(s.temp_bytes) / 1e9);
  std::printf("%s written\n", args.output.c_str());
  if (!args.stats_json.empty()) write_stats_json(args.stats_json, s);
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
