#pragma once
// RapidCheck generators of cubic bridgeless multigraphs for the SG/PS and augmentation tests.

#include <rapidcheck.h>

#include <array>
#include <vector>

#include "petersen/dualize/dual.hpp"
#include "petersen/dualize/surface_generators.hpp"
#include "petersen/graph/generators.hpp"

namespace petersen::testing {

/// One graph from every family the issue names: random multigraphs, necklaces, prisms (k = 2
/// has parallel edges), the theta graph, Petersen, K4, K3,3, and duals of random closed
/// triangulations of genus 0 to 30.
inline CubicGraph any_cubic_bridgeless() {
  switch (*rc::gen::inRange(0, 8)) {
    case 0:
      return random_cubic_bridgeless(2 * *rc::gen::inRange<std::uint32_t>(1, 200),
                                     *rc::gen::arbitrary<std::uint64_t>());
    case 1:
      return necklace(*rc::gen::inRange<std::uint32_t>(1, 40));
    case 2:
      return prism(*rc::gen::inRange<std::uint32_t>(2, 60));
    case 3:
      return *rc::gen::element(theta_graph(), petersen_graph(), complete_k4(), complete_k33());
    default:
      return dual_graph(random_closed_surface(
          *rc::gen::inRange<std::uint32_t>(0, 31), *rc::gen::inRange<std::uint32_t>(0, 300),
          *rc::gen::inRange<std::uint32_t>(0, 300), *rc::gen::arbitrary<std::uint64_t>()));
  }
}

inline std::vector<std::array<std::uint32_t, 2>> edge_list(const CubicGraph& g) {
  std::vector<std::array<std::uint32_t, 2>> edges(g.edge_count());
  for (EdgeId e = 0; e < g.edge_count(); ++e) edges[e] = g.endpoints(e);
  return edges;
}

}  // namespace petersen::testing
