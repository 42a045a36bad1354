// libFuzzer target for one graph-file reader (PETERSEN_FUZZ_GRAPH_FORMAT: dimacs or edges). Bad
// bytes must give a FileError; any other exception, a crash, a sanitizer report, a hang or a
// huge allocation is a finding. What parses must be a graph its users can index: every end below
// the node count, a cost per edge or none, each within the bound, and no more isolated nodes than
// the reader allows.

#include <cstdint>
#include <string_view>

#include "petersen/io/read_graph.hpp"
#include "require.hpp"

namespace {

using namespace petersen;

constexpr GraphFormat kFormat = GraphFormat::PETERSEN_FUZZ_GRAPH_FORMAT;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  GraphFile graph;
  try {
    graph = parse_graph(bytes, kFormat, "fuzz");
  } catch (const FileError&) {
    return 0;
  }
  for (const auto& [a, b] : graph.edges) REQUIRE(a < graph.node_count && b < graph.node_count);
  REQUIRE(graph.costs.empty() || graph.costs.size() == graph.edges.size());
  for (std::int64_t cost : graph.costs) REQUIRE(cost >= -kMaxFileCost && cost <= kMaxFileCost);
  REQUIRE(graph.node_count <= 2 * std::uint64_t{graph.edges.size()} + (std::uint64_t{1} << 24));
  REQUIRE(graph.first_id == (kFormat == GraphFormat::dimacs ? 1u : 0u));
  return 0;
}
