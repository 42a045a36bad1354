// The certificate check, written apart from the solver: its own laminar-family walk, its own
// doubled graph, 128-bit sums.

#include "petersen/matching/verify_min_cost.hpp"

#include <algorithm>
#include <cstdint>
#include <memory_resource>
#include <numeric>
#include <vector>

namespace petersen {

namespace {

// __extension__: 128-bit integers are a GNU extension (g++ and clang), named once here.
__extension__ using Wide = __int128;
__extension__ using UWide = unsigned __int128;

std::string str(Wide value) {
  const bool negative = value < 0;
  UWide magnitude = negative ? -static_cast<UWide>(value) : static_cast<UWide>(value);
  std::string digits;
  do {
    digits.push_back(static_cast<char>('0' + static_cast<int>(magnitude % 10)));
    magnitude /= 10;
  } while (magnitude != 0);
  if (negative) digits.push_back('-');
  return {digits.rbegin(), digits.rend()};
}

CertificateCheck fail(std::string problem) {
  return {std::move(problem)};
}

// The matching: perfect and consistent, of total cost `total_cost`; its cost goes to `primal`.
CertificateCheck check_matching(std::uint32_t n, std::span<const NodeId> edge_ends,
                                std::span<const Cost> costs, const Matching& matching,
                                Wide total_cost, Wide& primal) {
  const std::size_t m = edge_ends.size() / 2;
  if (edge_ends.size() % 2 != 0) return fail("odd number of edge ends");
  if (costs.size() != m)
    return fail("costs: " + std::to_string(costs.size()) + " for " + std::to_string(m) + " edges");
  if (matching.mate_edge.size() != n) return fail("matching has the wrong size");
  primal = 0;
  for (NodeId v = 0; v < n; ++v) {
    const EdgeId e = matching.mate_edge[v];
    if (e >= m)
      return fail("node " + std::to_string(v) + " is unmatched or names edge out of range");
    const NodeId a = edge_ends[2 * std::size_t{e}], b = edge_ends[2 * std::size_t{e} + 1];
    if (a != v && b != v)
      return fail("node " + std::to_string(v) + " names edge " + std::to_string(e) +
                  ", not incident");
    const NodeId w = a == v ? b : a;
    if (matching.mate_edge[w] != e)
      return fail("edge " + std::to_string(e) + " is matched at node " + std::to_string(v) +
                  " only");
    if (a == v) primal += costs[e];
  }
  if (primal != total_cost) {
    return fail("the matched edges cost " + str(primal) + ", not " + str(total_cost));
  }
  return {};
}

// The certificate's laminar family, as check_sets reads it: each set's depth, the sets by
// depth (parents before children), its node count, the values of it and every set above it,
// and its outermost ancestor.
struct Laminar {
  explicit Laminar(std::pmr::memory_resource* memory)
      : depth(memory), order(memory), size(memory), chain(memory), outermost(memory) {}
  std::pmr::vector<std::uint32_t> depth, order;
  std::pmr::vector<std::uint64_t> size;
  std::pmr::vector<Wide> chain;
  std::pmr::vector<std::uint32_t> outermost;
};

// The sets: a forest by their parents (any family of sets given this way is laminar), each
// odd, of 3+ nodes, with a value >= 0, and none equal to its only child.
CertificateCheck check_sets(std::uint32_t n, const MatchingCertificate& c, Laminar& family) {
  if (c.node_dual.size() != n || c.node_set.size() != n)
    return fail("node arrays have the wrong size");
  const std::size_t sets = c.set_dual.size();
  if (c.set_parent.size() != sets) return fail("set_parent has the wrong size");
  for (std::size_t s = 0; s < sets; ++s) {
    if (c.set_parent[s] != kNoSet && c.set_parent[s] >= sets)
      return fail("set " + std::to_string(s) + " has a parent out of range");
    if (c.set_dual[s] < 0) return fail("set " + std::to_string(s) + " has a negative value");
  }
  const std::vector<std::uint32_t>& parent = c.set_parent;
  const std::vector<std::uint32_t>& innermost = c.node_set;
  // Depths, walking each set up to a set of known depth; a walk longer than the number of sets
  // is a cycle.
  constexpr std::uint32_t kUnknown = 0xFFFFFFFFu;
  std::pmr::vector<std::uint32_t>& depth = family.depth;
  depth.assign(sets, kUnknown);
  std::pmr::vector<std::uint32_t> walk(depth.get_allocator());
  for (std::size_t s = 0; s < sets; ++s) {
    walk.clear();
    std::uint32_t at = static_cast<std::uint32_t>(s);
    while (at != kNoSet && depth[at] == kUnknown) {
      if (walk.size() > sets)
        return fail("set_parent has a cycle through set " + std::to_string(s));
      walk.push_back(at);
      at = parent[at];
    }
    std::uint32_t d = at == kNoSet ? 0 : depth[at] + 1;
    for (std::size_t i = walk.size(); i-- > 0;) depth[walk[i]] = d++;
  }
  std::pmr::vector<std::uint32_t>& order = family.order;
  order.resize(sets);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return depth[a] < depth[b]; });
  std::pmr::vector<std::uint64_t>& size = family.size;
  size.assign(sets, 0);
  std::pmr::vector<std::uint64_t> largest_child(sets, 0, depth.get_allocator());
  for (NodeId v = 0; v < n; ++v) {
    if (innermost[v] == kNoSet) continue;
    if (innermost[v] >= sets)
      return fail("node " + std::to_string(v) + " names a set out of range");
    ++size[innermost[v]];
  }
  for (std::size_t i = sets; i-- > 0;) {  // deepest first: children before parents
    const std::uint32_t s = order[i];
    if (size[s] < 3 || size[s] % 2 == 0)
      return fail("set " + std::to_string(s) + " has " + std::to_string(size[s]) +
                  " nodes, not an odd 3+");
    if (largest_child[s] == size[s])
      return fail("set " + std::to_string(s) + " equals one of its subsets");
    if (parent[s] != kNoSet) {
      size[parent[s]] += size[s];
      largest_child[parent[s]] = std::max(largest_child[parent[s]], size[s]);
    }
  }
  std::pmr::vector<Wide>& chain = family.chain;
  chain.assign(sets, 0);
  std::pmr::vector<std::uint32_t>& outermost = family.outermost;
  outermost.resize(sets);
  for (std::uint32_t s : order) {
    chain[s] = c.set_dual[s] + (parent[s] == kNoSet ? 0 : chain[parent[s]]);
    outermost[s] = parent[s] == kNoSet ? s : outermost[parent[s]];
  }
  return {};
}

// Complementary slackness: every reduced cost >= 0, matched edges tight, every set of positive
// value holding (size - 1) / 2 matched edges, and the values summing to twice the cost.
CertificateCheck check_duals(std::uint32_t n, std::span<const NodeId> edge_ends,
                             std::span<const Cost> costs, const Matching& matching, Wide primal,
                             const MatchingCertificate& c, const Laminar& family) {
  const std::size_t m = edge_ends.size() / 2;
  const std::size_t sets = c.set_dual.size();
  const std::vector<std::uint32_t>& parent = c.set_parent;
  const std::vector<std::uint32_t>& innermost = c.node_set;
  const auto& [depth, order, size, chain, outermost] = family;
  // The smallest set holding both u and v (kNoSet: none). Sets under different outermost ones
  // share none, nor does a set with no set: most edges leaving a set are settled so, where the
  // walk up from the deeper end would make the whole check 2.2-2.4x slower on the duals of
  // fertility-sub3 and rocker-arm-sub3, whose blossoms nest deeply.
  auto common = [&](NodeId u, NodeId v) {
    std::uint32_t a = innermost[u], b = innermost[v];
    if (a == b) return a;
    if (a == kNoSet || b == kNoSet || outermost[a] != outermost[b]) return kNoSet;
    while (a != b) {
      if (a == kNoSet || (b != kNoSet && depth[b] > depth[a])) std::swap(a, b);
      a = parent[a];
    }
    return a;
  };
  auto total_over = [&](NodeId v) {
    return Wide{c.node_dual[v]} + (innermost[v] == kNoSet ? 0 : chain[innermost[v]]);
  };
  // Reduced costs; matched edges are tight; count the matched edges inside each set.
  std::pmr::vector<std::uint64_t> inside(sets, 0, family.depth.get_allocator());
  for (std::size_t e = 0; e < m; ++e) {
    const NodeId u = edge_ends[2 * e], v = edge_ends[2 * e + 1];
    if (u >= n || v >= n || u == v) return fail("edge " + std::to_string(e) + " has bad ends");
    const std::uint32_t both = common(u, v);
    const Wide shared = both == kNoSet ? 0 : chain[both];
    const Wide reduced = 2 * Wide{costs[e]} - (total_over(u) + total_over(v) - 2 * shared);
    if (reduced < 0)
      return fail("edge " + std::to_string(e) + " has reduced cost " + str(reduced) + " < 0");
    const bool matched = matching.mate_edge[u] == e;
    if (matched && reduced != 0)
      return fail("matched edge " + std::to_string(e) + " is not tight (reduced cost " +
                  str(reduced) + ")");
    if (matched && both != kNoSet) ++inside[both];
  }
  // Children before parents: each set's count includes its subsets'.
  for (std::size_t i = sets; i-- > 0;) {
    const std::uint32_t s = order[i];
    if (parent[s] != kNoSet) inside[parent[s]] += inside[s];
    if (c.set_dual[s] > 0 && inside[s] != (size[s] - 1) / 2) {
      return fail("set " + std::to_string(s) + " has a positive value but holds " +
                  std::to_string(inside[s]) + " matched edges, not " +
                  std::to_string((size[s] - 1) / 2));
    }
  }
  Wide dual = 0;
  for (std::int64_t y : c.node_dual) dual += y;
  for (std::int64_t y : c.set_dual) dual += y;
  if (dual != 2 * primal)
    return fail("the values sum to " + str(dual) + ", not 2·cost = " + str(2 * primal));
  return {};
}

// The perfect-matching check with a 128-bit claimed total (the doubled graph's may pass 2^63).
CertificateCheck check_perfect(std::uint32_t n, std::span<const NodeId> edge_ends,
                               std::span<const Cost> costs, const Matching& matching,
                               Wide total_cost, const MatchingCertificate& certificate,
                               std::pmr::memory_resource* memory) {
  Wide primal = 0;
  if (CertificateCheck check = check_matching(n, edge_ends, costs, matching, total_cost, primal);
      !check.ok())
    return check;
  Laminar family(memory);
  if (CertificateCheck check = check_sets(n, certificate, family); !check.ok()) return check;
  return check_duals(n, edge_ends, costs, matching, primal, certificate, family);
}

// The free nodes of a matching of the right size.
std::uint64_t free_count(const Matching& matching) {
  return static_cast<std::uint64_t>(
      std::count(matching.mate_edge.begin(), matching.mate_edge.end(), kNoEdge));
}

// The doubled graph H: G on 0..n-1 (edge e), G' on n..2n-1 (edge m + e), v–v' (edge 2m + v) at
// pair_costs[v]; the perfect matching M ∪ M' ∪ {v–v' : v free in M}, checked with the certificate
// at total h_total. The caller has checked the sizes of costs and matching.
CertificateCheck check_doubled(std::uint32_t n, std::span<const NodeId> edge_ends,
                               std::span<const Cost> costs, std::span<const Cost> pair_costs,
                               const Matching& matching, Wide h_total,
                               const MatchingCertificate& certificate,
                               std::pmr::memory_resource* memory) {
  const std::size_t m = edge_ends.size() / 2;
  std::pmr::vector<NodeId> ends(memory);
  ends.reserve(4 * m + 2 * n);
  for (std::size_t i = 0; i < 2 * m; ++i) ends.push_back(edge_ends[i]);
  for (std::size_t i = 0; i < 2 * m; ++i) ends.push_back(n + edge_ends[i]);
  for (NodeId v = 0; v < n; ++v) {
    ends.push_back(v);
    ends.push_back(n + v);
  }
  std::pmr::vector<Cost> h_costs(memory);
  h_costs.reserve(2 * m + n);
  h_costs.insert(h_costs.end(), costs.begin(), costs.end());
  h_costs.insert(h_costs.end(), costs.begin(), costs.end());
  h_costs.insert(h_costs.end(), pair_costs.begin(), pair_costs.end());
  Matching h(2 * n, memory);
  for (NodeId v = 0; v < n; ++v) {
    const EdgeId e = matching.mate_edge[v];
    if (e == kNoEdge) {
      h.mate_edge[v] = h.mate_edge[n + v] = static_cast<EdgeId>(2 * m + v);
    } else if (e >= m) {
      return fail("node " + std::to_string(v) + " names edge " + std::to_string(e) +
                  " out of range");
    } else {
      h.mate_edge[v] = e;
      h.mate_edge[n + v] = static_cast<EdgeId>(m + e);
    }
  }
  CertificateCheck check = check_perfect(2 * n, ends, h_costs, h, h_total, certificate, memory);
  if (!check.ok()) check.problem = "doubled graph: " + check.problem;
  return check;
}

}  // namespace

CertificateCheck verify_min_cost_perfect_matching(std::uint32_t n,
                                                  std::span<const NodeId> edge_ends,
                                                  std::span<const Cost> costs,
                                                  const Matching& matching, Cost total_cost,
                                                  const MatchingCertificate& certificate,
                                                  std::pmr::memory_resource* memory) {
  return check_perfect(n, edge_ends, costs, matching, total_cost, certificate, memory);
}

CertificateCheck verify_min_cost_maximum_matching(
    std::uint32_t n, std::span<const NodeId> edge_ends, std::span<const Cost> costs,
    const Matching& matching, Cost total_cost, Cost unmatched_cost,
    const MatchingCertificate& certificate, std::pmr::memory_resource* memory) {
  const std::size_t m = edge_ends.size() / 2;
  if (costs.size() != m) return fail("costs: wrong size");
  if (matching.mate_edge.size() != n) return fail("matching has the wrong size");
  Wide most = 0, least = 0;
  for (Cost x : costs) {
    most = std::max<Wide>(most, x);
    least = std::min<Wide>(least, x);
  }
  // K must exceed the cost difference of any two matchings: at most ν·(most − least), ν their
  // size, at most half the nodes some edge (not a loop) touches and at most those edges.
  std::pmr::vector<std::uint8_t> touched(n, 0, memory);
  std::uint64_t edges = 0;
  for (std::size_t e = 0; e < m; ++e) {
    const NodeId a = edge_ends[2 * e], b = edge_ends[2 * e + 1];
    if (a == b || a >= n || b >= n) continue;
    touched[a] = touched[b] = 1;
    ++edges;
  }
  const auto touched_count =
      static_cast<std::uint64_t>(std::count(touched.begin(), touched.end(), 1));
  const Wide needed = 1 + Wide{std::min(touched_count / 2, edges)} * (most - least);
  if (Wide{unmatched_cost} < needed) {
    return fail("unmatched cost " + std::to_string(unmatched_cost) + " is below " + str(needed));
  }
  const Wide h_total = 2 * Wide{total_cost} + Wide{unmatched_cost} * free_count(matching);
  const std::pmr::vector<Cost> pair_costs(n, unmatched_cost, memory);
  return check_doubled(n, edge_ends, costs, pair_costs, matching, h_total, certificate, memory);
}

CertificateCheck verify_min_cost_matching(std::uint32_t n, std::span<const NodeId> edge_ends,
                                          std::span<const Cost> costs,
                                          std::span<const Cost> unmatched_cost,
                                          const Matching& matching, Cost total,
                                          const MatchingCertificate& certificate,
                                          std::pmr::memory_resource* memory) {
  const std::size_t m = edge_ends.size() / 2;
  if (costs.size() != m) return fail("costs: wrong size");
  if (matching.mate_edge.size() != n) return fail("matching has the wrong size");
  if (unmatched_cost.size() != n && unmatched_cost.size() != 1)
    return fail("unmatched costs: " + std::to_string(unmatched_cost.size()) + " for " +
                std::to_string(n) + " nodes");
  // The objective: the matched edges (counted at their first end) and the free nodes' prices.
  std::pmr::vector<Cost> pair_costs(n, memory);
  Wide objective = 0;
  for (NodeId v = 0; v < n; ++v) {
    const Cost price = unmatched_cost[unmatched_cost.size() == 1 ? 0 : v];
    if (price > INT64_MAX / 2 || price < INT64_MIN / 2)
      return fail("node " + std::to_string(v) + " has price " + std::to_string(price) +
                  ", past 2^62");
    pair_costs[v] = 2 * price;
    const EdgeId e = matching.mate_edge[v];
    if (e == kNoEdge) {
      objective += price;
    } else if (e < m && edge_ends[2 * std::size_t{e}] == v) {
      objective += costs[e];
    }
  }
  if (objective != total)
    return fail("the matched costs and unmatched prices sum to " + str(objective) + ", not " +
                str(total));
  return check_doubled(n, edge_ends, costs, pair_costs, matching, 2 * Wide{total}, certificate,
                       memory);
}

}  // namespace petersen
