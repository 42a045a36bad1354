#pragma once
// Cubic bridgeless (multi)graphs for tests and benchmarks; every random one is seeded.
// Duals of triangulated surfaces live in dualize (surface_generators.hpp).

#include "petersen/graph/cubic_graph.hpp"

namespace petersen {

CubicGraph theta_graph();     ///< 2 nodes, 3 parallel edges: the smallest cubic bridgeless graph
CubicGraph complete_k4();     ///< K4
CubicGraph complete_k33();    ///< K3,3
CubicGraph petersen_graph();  ///< the Petersen graph (10 nodes)
/// The prism over a k-cycle (2k nodes, k >= 2; k = 2 has parallel edges).
CubicGraph prism(std::uint32_t k);
/// A ring of k >= 1 diamonds (4k nodes): every ring edge lies on a 2-edge cut, so every Frink
/// reduction near the ring is constrained.
CubicGraph necklace(std::uint32_t k);
/// A uniformly shuffled cubic multigraph on n nodes (n even, n >= 2), by the configuration model
/// with loops, bridges and disconnection rejected; parallel edges stay. Expected O(n).
CubicGraph random_cubic_bridgeless(std::uint32_t n, std::uint64_t seed);

}  // namespace petersen
