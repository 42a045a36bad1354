#include "petersen/matching/avoiding.hpp"

#include <string>
#include <utility>

#include "petersen/graph/connectivity.hpp"
#include "reduction/match_by_reductions.hpp"

namespace petersen {

namespace {
constexpr std::pair<ReductionChooser, std::string_view> kChooserNames[] = {
    {ReductionChooser::frink, "frink"}, {ReductionChooser::ds, "ds"}, {ReductionChooser::gw, "gw"}};
}  // namespace

std::string_view to_string(ReductionChooser chooser) {
  for (auto [c, name] : kChooserNames)
    if (c == chooser) return name;
  return "?";
}

std::optional<ReductionChooser> parse_reduction_chooser(std::string_view name) {
  for (auto [c, n] : kChooserNames)
    if (n == name) return c;
  return std::nullopt;
}

ReductionResult perfect_matching_avoiding(const CubicGraph& graph, EdgeId forbidden,
                                          const ReductionOptions& options) {
  if (forbidden != kNoEdge && forbidden >= graph.edge_count())
    throw GraphError("perfect_matching_avoiding: forbidden edge " + std::to_string(forbidden) +
                     " is out of range (the graph has " + std::to_string(graph.edge_count()) +
                     " edges)");
  validate_bridgeless(graph);
  return reduction::match_by_reductions(graph, forbidden, options);
}

}  // namespace petersen
