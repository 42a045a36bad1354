#include "reduction/match_by_reductions.hpp"

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>

#include "petersen/graph/connectivity.hpp"
#include "reduction/ds_chooser.hpp"
#include "reduction/engine.hpp"
#include "reduction/frink_chooser.hpp"
#include "reduction/gw_chooser.hpp"
#include "stopwatch.hpp"

namespace petersen::reduction {

ReductionResult match_by_reductions(const CubicGraph& graph, EdgeId forbidden,
                                    const ReductionOptions& options) {
  ReductionResult result;
  Stopwatch setup;
  const std::vector<std::uint32_t> component = component_ids(graph);
  const std::uint32_t components =
      component.empty() ? 0 : *std::max_element(component.begin(), component.end()) + 1;
  std::unique_ptr<Chooser> chooser;
  switch (options.chooser) {
    case Algorithm::frink:
      chooser = std::make_unique<FrinkChooser>(components);
      break;
    case Algorithm::ds:
      chooser = std::make_unique<DsChooser>(graph, graph.edge_count() + graph.node_count());
      break;
    case Algorithm::gw:
      chooser = std::make_unique<GwChooser>(graph, graph.edge_count() + graph.node_count());
      break;
    default:
      throw std::invalid_argument("perfect_matching_avoiding: chooser '" +
                                  std::string(to_string(options.chooser)) + "' is not available");
  }
  result.stats.setup_seconds = setup.seconds();
  result.matching = reduce_and_lift(graph, component, components, forbidden, *chooser,
                                    options.check_each_step, result.stats);
  return result;
}

}  // namespace petersen::reduction
