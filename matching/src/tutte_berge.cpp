#include "petersen/matching/tutte_berge.hpp"

#include <string>
#include <vector>

#include "petersen/graph/component_forest.hpp"

namespace petersen {

MatchingCheck verify_maximum_matching(const CsrGraph& graph, const Matching& matching,
                                      std::span<const NodeId> tutte_set) {
  using Problem = MatchingCheck::Problem;
  if (MatchingCheck check = verify_matching(graph, matching); !check.ok()) return check;
  const std::uint32_t n = graph.node_count();
  std::vector<std::uint8_t> in_set(n, 0);
  for (NodeId v : tutte_set) {
    if (v >= n || in_set[v]) {
      return {Problem::bad_witness, v, kNoEdge,
              "Tutte set names node " + std::to_string(v) +
                  (v >= n ? " out of range (" + std::to_string(n) + " nodes)" : " twice")};
    }
    in_set[v] = 1;
  }
  // Components of G − A by disjoint sets.
  ComponentForest components(n);
  for (EdgeId e = 0; e < graph.edge_count(); ++e) {
    const auto [a, b] = graph.endpoints(e);
    if (!in_set[a] && !in_set[b]) components.unite(a, b);
  }
  std::vector<std::uint8_t> parity(n, 0);
  for (NodeId v = 0; v < n; ++v)
    if (!in_set[v]) parity[components.find(v)] ^= 1;
  std::int64_t odd_components = 0;
  for (NodeId v = 0; v < n; ++v)
    odd_components += !in_set[v] && components.find(v) == v && parity[v];
  const std::int64_t bound = odd_components - static_cast<std::int64_t>(tutte_set.size());
  const std::int64_t unmatched = matching.unmatched_count();
  if (unmatched != bound) {
    return {Problem::not_maximum, kNoNode, kNoEdge,
            "the matching leaves " + std::to_string(unmatched) +
                " nodes free, but the Tutte set (" + std::to_string(tutte_set.size()) + " nodes, " +
                std::to_string(odd_components) +
                " odd components left) proves only that at least " + std::to_string(bound) +
                " must be"};
  }
  return {};
}

}  // namespace petersen
