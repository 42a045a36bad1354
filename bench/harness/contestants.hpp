#pragma once
// The contestants of the bench: every matching algorithm petersen builds, the peers a user would
// pick instead (LEMON, Boost), and a plain breadth-first search as the floor.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "measures.hpp"
#include "petersen/dualize/dual.hpp"

namespace petersen::bench {

/// What every contestant runs on: a closed triangle mesh and its dual graph.
struct BenchInput {
  const PolygonMesh& mesh;
  const Dual& dual;
};

struct Contestant {
  std::string name;        ///< e.g. "auto-local", "lemon", "bfs"
  std::string paper_name;  ///< the paper's name for it ("SG", "PS", "DS", "LRS"), or empty
  bool seeded = false;     ///< runs differ by seed (randomized order), as SG and PS in the paper
  bool floor = false;      ///< the BFS every total is compared with
  std::uint32_t max_nodes = 0xFFFFFFFFu;  ///< larger inputs are skipped (quadratic oracles)
  /// Runs once and returns the measures; every matching is checked by verify_perfect_matching
  /// first, and a failure throws VerificationError.
  std::function<Measures(const BenchInput&, std::uint64_t seed)> run;
};

/// All contestants, floor first. `frink_max_nodes` bounds the O(n^2) Frink oracle.
std::vector<Contestant> all_contestants(std::uint32_t frink_max_nodes);

}  // namespace petersen::bench
