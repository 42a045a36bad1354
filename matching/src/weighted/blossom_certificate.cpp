#include <vector>

#include "blossom_solver.hpp"

namespace petersen::weighted_detail {

/// The matching and the dual solution in the input's ids (input node v is node new_node[v]
/// here); run() must have returned. Returns the matching's total cost, exact: the doubled
/// graph of min_cost_maximum_matching may take it past 2^63 (n edges of cost up to 2^52), so
/// the caller decides what it needs of it. O(n + blossoms). Written straight in the input's
/// order, each node's record requested 16 nodes ahead: a third faster than a certificate in the
/// solver's order mapped afterwards (27-32 ms against 40-54 on rocker-arm-sub3's dual).
WideCost BlossomSolver::write_result(std::span<const NodeId> new_node,
                                     MinCostResult& result) const {
  MatchingCertificate& c = result.certificate;
  const auto ids = static_cast<std::uint32_t>(rec_.size());  // the blossom ids ever used
  // index[b - n]: blossom b's set in the certificate (a blossom of dual zero has none).
  std::vector<std::uint32_t> index(ids - n_, kNoSet);
  for (std::uint32_t b = n_; b < ids; ++b) {
    if (children_[b - n_].empty() || rec_[b].y == 0) continue;
    index[b - n_] = static_cast<std::uint32_t>(c.set_dual.size());
    c.set_dual.push_back(rec_[b].y);
  }
  // The innermost set holding blossom b (b's own, if it has one): a walk up to a blossom
  // known or with a set (or past the top), whose answer the walked ones take.
  constexpr std::uint32_t kUnknown = kNoSet - 1;
  std::vector<std::uint32_t> holding(ids - n_, kUnknown);
  std::vector<std::uint32_t> chain;
  auto set_holding = [&](std::uint32_t b) {
    chain.clear();
    std::uint32_t found = kNoSet;
    for (std::uint32_t at = b; at != kNone; at = rec_[at].parent) {
      if (holding[at - n_] != kUnknown) {
        found = holding[at - n_];
        break;
      }
      if (index[at - n_] != kNoSet) {
        found = index[at - n_];
        holding[at - n_] = found;
        break;
      }
      chain.push_back(at);
    }
    for (std::uint32_t x : chain) holding[x - n_] = found;
    return found;
  };
  c.set_parent.resize(c.set_dual.size());
  for (std::uint32_t b = n_; b < ids; ++b) {
    if (index[b - n_] == kNoSet) continue;
    const std::uint32_t p = rec_[b].parent;
    c.set_parent[index[b - n_]] = p == kNone ? kNoSet : set_holding(p);
  }
  const auto n = static_cast<std::uint32_t>(new_node.size());
  result.matching = Matching(n, result.matching.mate_edge.get_allocator().resource());
  c.node_dual.resize(n);
  c.node_set.resize(n);
  for (NodeId v = 0; v < n; ++v) {
    if (v + 16 < n) __builtin_prefetch(&rec_[new_node[v + 16]]);
    const Record& r = rec_[new_node[v]];
    result.matching.mate_edge[v] = r.mate.edge;
    c.node_dual[v] = r.y;
    c.node_set[v] = r.parent == kNone ? kNoSet : set_holding(r.parent);
  }
  // The cost, from each matched edge's slot at its smaller end, in this order (the slots
  // are read in sequence).
  WideCost total = 0;
  for (NodeId v = 0; v < n_; ++v) {
    const Mate m = rec_[v].mate;
    if (m.node < v) continue;
    for (const Slot& slot : slots_of(v)) {
      if (slot.edge == m.edge) {
        total += slot.cost2 / 2;
        break;
      }
    }
  }
  return total;
}

}  // namespace petersen::weighted_detail
