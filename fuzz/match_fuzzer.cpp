// libFuzzer target for `petersen match` on any graph: the input is an edge list (with or without
// costs), its last byte choosing the algorithm for a cubic bridgeless graph. What does not parse
// is the reader's business (its own target); what parses must be matched: a maximum matching
// (match_any_graph, a perfect one by the chosen algorithm when the graph is cubic and bridgeless)
// and, with costs, the cheapest maximum one (cheapest_matching_any_graph). Both verify their own
// answers before returning (std::logic_error otherwise); on top, this target checks what a caller
// reads: every mate edge names an edge at its node and is named by the other end too, the sizes
// are the mates counted, the two matchings are equally large, and the total is the matched
// edges' costs. The one refusal allowed is the documented one of the cheapest matching (costs
// too far apart for the reduction, see below); any other exception, a crash, a sanitizer report,
// a hang or a huge allocation is a finding.

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "petersen/io/read_graph.hpp"
#include "petersen/matching/any_graph.hpp"
#include "require.hpp"

namespace {

using namespace petersen;

constexpr std::uint32_t kFree = 0xFFFFFFFFu;

// The matching's size, after checking that mate_edge is a matching of `edges`.
std::uint32_t checked_size(const GraphFile& graph, const std::vector<std::uint32_t>& mate_edge) {
  REQUIRE(mate_edge.size() == graph.node_count);
  std::uint32_t matched = 0;
  for (std::uint32_t v = 0; v < graph.node_count; ++v) {
    const std::uint32_t e = mate_edge[v];
    if (e == kFree) continue;
    REQUIRE(e < graph.edges.size());
    const auto [a, b] = graph.edges[e];
    REQUIRE(a != b && (a == v || b == v));
    REQUIRE(mate_edge[a == v ? b : a] == e);
    ++matched;
  }
  return matched / 2;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  GraphFile graph;
  try {
    graph = parse_graph(bytes, GraphFormat::edges, "fuzz");
  } catch (const FileError&) {
    return 0;
  }
  // The reader allows 2^24 isolated nodes past what the edges touch; a matching of those is
  // nothing to learn and only fills memory.
  if (graph.node_count > (1u << 16)) return 0;
  constexpr Algorithm kAlgorithms[] = {Algorithm::automatic, Algorithm::ps, Algorithm::sg,
                                       Algorithm::ds,        Algorithm::gw, Algorithm::frink};
  PerfectMatchingOptions options;
  options.algorithm = kAlgorithms[data[size - 1] % 6];
  const AnyGraphMatching maximum = match_any_graph(graph.node_count, graph.edges, options);
  REQUIRE(checked_size(graph, maximum.mate_edge) == maximum.size);
  REQUIRE(maximum.perfect == (2 * std::uint64_t{maximum.size} == graph.node_count));
  REQUIRE(maximum.cubic_bridgeless == maximum.note.empty());
  REQUIRE(!maximum.cubic_bridgeless || maximum.perfect);
  if (graph.costs.empty()) return 0;
  AnyGraphCheapestMatching cheapest;
  try {
    cheapest =
        cheapest_matching_any_graph(graph.node_count, graph.edges, graph.costs, 1 + data[0] % 2);
  } catch (const std::invalid_argument&) {
    // The one documented refusal for costs in range: no perfect matching, and the reduction's
    // K = 1 + ν̄·(max(0, most) − min(0, least)) past 2^52 (min_cost_matching.hpp).
    std::vector<bool> touched(graph.node_count, false);
    std::uint64_t edges = 0;
    std::int64_t most = 0, least = 0;
    for (std::size_t e = 0; e < graph.edges.size(); ++e) {
      const auto [a, b] = graph.edges[e];
      if (a == b) continue;
      touched[a] = touched[b] = true;
      ++edges;
      most = std::max(most, graph.costs[e]);
      least = std::min(least, graph.costs[e]);
    }
    const auto nodes = static_cast<std::uint64_t>(std::count(touched.begin(), touched.end(), true));
    const auto k = 1 + static_cast<unsigned __int128>(std::min(nodes / 2, edges)) *
                           static_cast<std::uint64_t>(most - least);
    REQUIRE(!maximum.perfect && k >= (std::uint64_t{1} << 52));
    return 0;
  }
  REQUIRE(checked_size(graph, cheapest.mate_edge) == cheapest.size);
  REQUIRE(cheapest.size == maximum.size);
  REQUIRE(cheapest.perfect == maximum.perfect);
  std::int64_t total = 0;
  for (std::uint32_t v = 0; v < graph.node_count; ++v) {
    const std::uint32_t e = cheapest.mate_edge[v];
    if (e != kFree && graph.edges[e][0] == v) total += graph.costs[e];
  }
  REQUIRE(total == cheapest.total_cost);
  return 0;
}
