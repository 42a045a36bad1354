#pragma once
// What perfect_matching is asked to do and what it reports: the algorithms, the options and the
// statistics. C++17, like everything it includes, so that the LEMON adaptor (whose Debian headers
// do not compile as C++20) can take a PerfectMatchingOptions.

#include <cstdint>
#include <memory_resource>
#include <optional>
#include <string_view>

namespace petersen {

/// The algorithms perfect_matching runs on a cubic bridgeless graph. lrs, which contracts and flips
/// a triangulation, is chosen at the mesh front door (PairingAlgorithm,
/// petersen/quadrangulate/quadrangulate.hpp).
enum class Algorithm {
  automatic,  ///< "auto": the fastest pairing in PS's place (the ordered sweep where the numbering
              ///< is local, PerfectMatchingStats::ordered_sweep; Schrijver's exact matching on a
              ///< bipartite graph where that leaves nodes, PerfectMatchingStats::schrijver; PS
              ///< where neither stands), then augmenting paths
  sg,         ///< simple greedy pairing (paper §3.1), then augmenting paths
  ps,         ///< Puli–Segal priority greedy as the paper describes it (§3.1), then augmenting
              ///< paths
  ds,         ///< Frink reductions, Diks–Stańczyk choice over dynamic connectivity (paper §3.2)
  gw,         ///< Frink reductions, Gawrychowski–Wasylkiewicz choice over link-cut trees
  frink,      ///< Frink reductions, bridge test from scratch: O(n^2), a test oracle
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

struct PerfectMatchingOptions {
  Algorithm algorithm = Algorithm::automatic;
  Augment augment = Augment::local;
  std::uint64_t seed = 1;
  /// Check connectivity-per-component and bridgelessness at the door (O(n), one DFS).
  bool validate = true;
  /// Where the matching and the algorithm's large arrays are allocated.
  std::pmr::memory_resource* memory = std::pmr::get_default_resource();
};

/// Statistics of one run, in the columns of the paper's Table 4.3 plus per-algorithm counts.
struct PerfectMatchingStats {
  double validate_seconds = 0;
  double initial_seconds = 0;  ///< (a) initial pairing, or the whole one-step algorithm
  std::uint32_t unpaired_after_initial = 0;  ///< (c)
  double augment_seconds = 0;                ///< (d) time to make the initial pairing perfect
  std::uint64_t augmenting_paths = 0;
  std::uint64_t blossoms = 0;
  std::uint64_t nodes_labelled = 0;
  std::uint64_t reductions = 0;             ///< Frink reductions (ds, gw, frink)
  std::uint64_t lift_cases[3] = {0, 0, 0};  ///< Appendix A cases (i), (ii), (iii)
  std::uint64_t replacement_searches = 0;   ///< ds: dynamic-connectivity replacement searches
  std::uint64_t cover_swaps = 0;            ///< gw: tree edges swapped for a covering non-tree edge
  /// automatic: Schrijver's algorithm matched the graph perfectly in PS's place, nothing left to
  /// augment.
  /// It runs where the ordered sweep leaves nodes or does not run, and matches every bipartite
  /// graph (where PS leaves patches of one colour, bench/RESULTS.md); it gives up at the first
  /// odd cycle its walk meets, and the sweep's pairing or PS's stands.
  bool schrijver = false;
  /// automatic: the ordered sweep's pairing is the initial one: the numbering was local, and the
  /// sweep paired every node or the graph was not bipartite.
  bool ordered_sweep = false;

  double matching_seconds() const { return initial_seconds + augment_seconds; }  ///< (e)
  double paired_percent(std::uint32_t node_count) const {                        ///< (b)
    return node_count == 0 ? 100.0
                           : 100.0 * (node_count - unpaired_after_initial) / double(node_count);
  }
};

}  // namespace petersen
