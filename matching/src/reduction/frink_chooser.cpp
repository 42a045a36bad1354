#include "reduction/frink_chooser.hpp"

#include "reduction/brute_force.hpp"

namespace petersen::reduction {

bool FrinkChooser::choose_h1(const ReductionGraph& graph, const Step& step) {
  return is_connected_bridgeless(graph, components_, &step, true);
}

}  // namespace petersen::reduction
