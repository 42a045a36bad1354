#pragma once
// `petersen match IN OUT`: a matching of a graph file, written as the matched edges.

#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>

namespace petersen::cli {

struct MatchArgs {
  std::string input, output, format, algorithm = "auto", augment = "local", objective = "size",
                                     stats_json;
  std::uint64_t seed = 1;
  bool require_perfect = false;
};

/// Exit code of `match --require-perfect` on a graph without a perfect matching.
inline constexpr int kNoPerfectMatching = 3;

/// Adds the subcommand and its options to `app`, filling `args` when parsed.
CLI::App* add_match_command(CLI::App& app, MatchArgs& args);

/// Runs it: 0, or kNoPerfectMatching; throws on bad input (GraphError naming file:line).
int run_match(const MatchArgs& args);

}  // namespace petersen::cli
