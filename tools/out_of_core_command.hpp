#pragma once
// `petersen quad` past the machine's memory (--memory-limit, or an input too large to hold), and
// `petersen generate --kind streamed-plate`: the out-of-core paths of the command-line tool.

#include <cstdint>
#include <optional>
#include <string>

#include "petersen/partition/partition.hpp"

namespace petersen::cli {

/// "3G", "512M", "2.5GiB", "1000000" (bytes): the size in bytes. Throws CLI::ValidationError.
std::uint64_t parse_memory_size(const std::string& text);

/// The memory limit of the out-of-core path for this input: --memory-limit when given; otherwise,
/// for a binary PLY whose in-memory conversion by `objective` would need more than the memory
/// available now (/proc/meminfo), half of what is available, said in one line on stderr;
/// otherwise none (the in-memory path runs).
std::optional<std::uint64_t> out_of_core_limit(const std::string& input,
                                               const std::string& memory_limit,
                                               Objective objective);

struct OutOfCoreArgs {
  std::string input, output, augment = "local", stats_json;
  PartCosts costs = {};
  std::uint64_t memory_limit = 0;
  std::uint64_t part_triangles = 0;
  std::uint32_t threads = 1;
  bool all_quad = false, keep_polygons = false;
};

/// Runs quad_out_of_core and prints its summary (and --stats-json). 0 when every pair checked out.
int quad_out_of_core_command(const OutOfCoreArgs& args);

/// Writes the closed plate of about `triangles` triangles (streamed_plate.hpp) to a binary PLY,
/// streamed: O(1) memory whatever its size.
int generate_streamed_plate(const std::string& output, std::uint64_t triangles);

}  // namespace petersen::cli
