#pragma once
// Perfect matchings that avoid a named edge, by Frink's reductions (paper §3.2 and Appendix A)
// under the forbidden-edge rule of Biedl, Bose, Demaine and Lubiw (J. Algorithms 38, 2001).

#include <cstdint>
#include <optional>
#include <string_view>

#include "petersen/matching/matching.hpp"
#include "petersen/matching/perfect_matching.hpp"

namespace petersen {

/// How the reductions choose between Frink's two graphs H1 and H2 (the same names as the
/// Algorithm that runs each).
enum class ReductionChooser {
  frink,  ///< bridge test from scratch, O(n^2)
  ds,     ///< Diks–Stańczyk: dynamic connectivity and link-cut trees, O(n log^2 n) amortized
  gw,     ///< Gawrychowski–Wasylkiewicz: link-cut trees with a cover per tree edge, O(n log n)
};
std::string_view to_string(ReductionChooser chooser);
std::optional<ReductionChooser> parse_reduction_chooser(std::string_view name);

struct ReductionOptions {
  ReductionChooser chooser = ReductionChooser::ds;
  /// Debug mode: after every reduction, verify by brute force (O(n)) that the reduced graph is
  /// still bridgeless with as many components as the input; throws std::logic_error otherwise.
  bool check_each_step = false;
};

/// What one run of the reductions did.
struct ReductionStats {
  std::uint64_t reductions = 0;        ///< Frink reductions (two nodes removed each)
  std::uint64_t digon_reductions = 0;  ///< forced digon contractions (both ends of f on a digon)
  std::uint64_t lift_cases[3] = {0, 0, 0};  ///< Appendix A cases (i), (ii), (iii); (iv) never
  std::uint64_t replacement_searches = 0;   ///< ds: dynamic-connectivity replacement searches
  std::uint64_t cover_swaps = 0;            ///< gw: tree edges swapped for a covering non-tree edge
  double setup_seconds = 0;                 ///< components and the chooser's data structures
  double reduce_seconds = 0;  ///< all reductions, down to one theta graph per component
  double lift_seconds = 0;    ///< undoing the reductions, O(1) each
};

struct ReductionResult {
  Matching matching;
  ReductionStats stats;
};

/// A perfect matching of a bridgeless cubic multigraph that does not contain `forbidden`
/// (kNoEdge: no constraint). Components are matched independently. Each reduction removes an
/// edge adjacent to the forbidden edge, which then travels to a new edge, so Frink's case (iv)
/// never arises and every lift is O(1). Throws GraphError if the graph has a bridge or
/// `forbidden` is out of range,
ReductionResult perfect_matching_avoiding(const CubicGraph& graph, EdgeId forbidden,
                                          const ReductionOptions& options = {});

}  // namespace petersen
