#pragma once
// The front door: one free function computing a perfect matching of a cubic bridgeless graph.

#include <optional>
#include <string_view>

#include "petersen/matching/matching.hpp"

namespace petersen {

enum class Algorithm {
  sg,     ///< simple greedy pairing (paper §3.1), then augmenting paths
  ps,     ///< Puli–Segal priority greedy (paper §3.1), then augmenting paths
  ds,     ///< Frink reductions, Diks–Stańczyk choice over dynamic connectivity (paper §3.2)
  gw,     ///< Frink reductions, Gawrychowski–Wasylkiewicz choice over link-cut trees
  frink,  ///< Frink reductions, bridge test from scratch: O(n^2), a test oracle
  lemon,  ///< LEMON's MaxMatching on a copy of the graph: the peer, for comparison
  lrs,    ///< contraction and expansion with flips (paper §3.3): needs a mesh, so it is run by
          ///< quadrangulate (petersen/quadrangulate), not by perfect_matching
};

/// How augmenting paths are searched (paper §3.1, Tarjan's procedure).
enum class Augment {
  local,     ///< each search resets only what it labelled: cost follows the region explored
  faithful,  ///< the paper's: a full O(n) reset before every search
};

std::string_view to_string(Algorithm algorithm);
std::optional<Algorithm> parse_algorithm(std::string_view name);
std::string_view to_string(Augment augment);
std::optional<Augment> parse_augment(std::string_view name);

struct Options {
  Algorithm algorithm = Algorithm::ps;
  Augment augment = Augment::local;
  std::uint64_t seed = 1;
  /// Check connectivity-per-component and bridgelessness at the door (O(n), one DFS).
  bool validate = true;
};

/// Statistics of one run, in the columns of the paper's Table 4.3 plus per-algorithm counts.
struct Stats {
  double validate_seconds = 0;
  double initial_seconds = 0;  ///< (a) initial pairing, or the whole one-step algorithm
  std::uint32_t unpaired_after_initial = 0;  ///< (c)
  double augment_seconds = 0;                ///< (d) time to make the initial pairing perfect
  std::uint64_t augmenting_paths = 0;
  std::uint64_t blossoms = 0;
  std::uint64_t nodes_labelled = 0;
  std::uint64_t reductions = 0;             ///< Frink reductions (ds, gw, frink)
  std::uint64_t lift_cases[3] = {0, 0, 0};  ///< Appendix A cases (i), (ii), (iii)
  std::uint64_t replacement_searches = 0;   ///< dynamic-connectivity replacement searches (ds)

  double matching_seconds() const { return initial_seconds + augment_seconds; }  ///< (e)
  double paired_percent(std::uint32_t node_count) const {                        ///< (b)
    return node_count == 0 ? 100.0
                           : 100.0 * (node_count - unpaired_after_initial) / double(node_count);
  }
};

struct Result {
  Matching matching;
  Stats stats;
};

/// A perfect matching of a cubic bridgeless (multi)graph, by the chosen algorithm. Components are
/// matched independently. Throws GraphError if `options.validate` and the graph has a bridge,
/// std::invalid_argument for Algorithm::lrs (which works on a triangulation, not a graph).
Result perfect_matching(const CubicGraph& graph, const Options& options = {});

}  // namespace petersen
