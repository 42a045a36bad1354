#include "petersen/matching/matching.hpp"

#include <algorithm>
#include <span>
#include <string>

namespace petersen {

std::uint32_t Matching::unmatched_count() const {
  return static_cast<std::uint32_t>(std::count(mate_edge.begin(), mate_edge.end(), kNoEdge));
}

namespace {

template <class Graph>
MatchingCheck check(const Graph& graph, const Matching& matching, bool require_perfect) {
  using Problem = MatchingCheck::Problem;
  auto fail = [](Problem p, NodeId v, EdgeId e, std::string message) {
    return MatchingCheck{p, v, e, std::move(message)};
  };
  const std::uint32_t n = graph.node_count();
  if (matching.mate_edge.size() != n) {
    return fail(Problem::wrong_size, kNoNode, kNoEdge,
                "matching has " + std::to_string(matching.mate_edge.size()) + " entries for " +
                    std::to_string(n) + " nodes");
  }
  for (NodeId v = 0; v < n; ++v) {
    EdgeId e = matching.mate_edge[v];
    if (e == kNoEdge) {
      if (require_perfect) {
        return fail(Problem::unmatched, v, e, "node " + std::to_string(v) + " is unmatched");
      }
      continue;
    }
    if (e >= graph.edge_count()) {
      return fail(Problem::edge_out_of_range, v, e,
                  "node " + std::to_string(v) + " names edge " + std::to_string(e) +
                      ", out of range (" + std::to_string(graph.edge_count()) + " edges)");
    }
    auto [a, b] = graph.endpoints(e);
    if (a != v && b != v) {
      return fail(Problem::not_incident, v, e,
                  "node " + std::to_string(v) + " names edge " + std::to_string(e) +
                      ", which joins " + std::to_string(a) + " and " + std::to_string(b));
    }
    NodeId w = graph.other_end(e, v);
    if (matching.mate_edge[w] != e) {
      return fail(Problem::inconsistent, v, e,
                  "node " + std::to_string(v) + " is matched by edge " + std::to_string(e) +
                      " but its other end " + std::to_string(w) + " names edge " +
                      (matching.mate_edge[w] == kNoEdge ? std::string("none")
                                                        : std::to_string(matching.mate_edge[w])) +
                      " (matched twice or not at all)");
    }
  }
  return {};
}

}  // namespace

MatchingCheck verify_perfect_matching(const CubicGraph& graph, const Matching& matching) {
  return check(graph, matching, true);
}

MatchingCheck verify_matching(const CubicGraph& graph, const Matching& matching) {
  return check(graph, matching, false);
}

MatchingCheck verify_matching(const CsrGraph& graph, const Matching& matching) {
  return check(graph, matching, false);
}

MatchingCheck verify_perfect_partners(std::span<const NodeId> rows,
                                      std::span<const NodeId> partner) {
  using Problem = MatchingCheck::Problem;
  const std::size_t n = rows.size() / 3;
  if (partner.size() != n || rows.size() % 3 != 0) {
    return {Problem::wrong_size, kNoNode, kNoEdge,
            "matching has " + std::to_string(partner.size()) + " partners for " +
                std::to_string(rows.size()) + " neighbour slots (3 per node)"};
  }
  for (NodeId v = 0; v < n; ++v) {
    const NodeId p = partner[v];
    auto node = [v] { return "node " + std::to_string(v); };  // for a message only
    if (p == kNoNode) return {Problem::unmatched, v, kNoEdge, node() + " is unmatched"};
    if (p >= n) {
      return {Problem::edge_out_of_range, v, p,
              node() + " names partner " + std::to_string(p) + ", out of range (" +
                  std::to_string(n) + " nodes)"};
    }
    const NodeId* row = &rows[3 * std::size_t{v}];
    if (row[0] != p && row[1] != p && row[2] != p) {
      return {Problem::not_incident, v, p,
              node() + " names partner " + std::to_string(p) + ", which is not a neighbour"};
    }
    if (partner[p] != v) {
      return {Problem::inconsistent, v, p,
              node() + " names partner " + std::to_string(p) + ", whose partner is " +
                  (partner[p] == kNoNode ? std::string("none") : std::to_string(partner[p]))};
    }
  }
  return {};
}

}  // namespace petersen
