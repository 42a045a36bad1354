#pragma once
// What leaving each triangle costs under Objective::quads: the one price the options give, or a
// lower one for a triangle that looks like a model's own beside good quads.

#include <cstdint>
#include <memory_resource>
#include <span>
#include <vector>

#include "petersen/matching/min_cost_matching.hpp"

namespace petersen {

/// A triangle whose neighbours all have a pair of at most this share of the price (halves of
/// good quads) ...
inline constexpr double kOwnTriangleNeighbourShare = 1.0 / 3.0;
/// ... and whose every pair would cost the neighbour it takes at least this share of the price
/// more than that neighbour's cheapest pair ...
inline constexpr double kOwnTriangleRegretShare = 2.0 / 3.0;
/// ... may stay for this share of the price.
inline constexpr double kOwnTrianglePriceShare = 0.6;

/// Each node's price for staying unpaired, in the costs' units, over the graph of `edge_ends`
/// (edge e joins nodes edge_ends[2e] and edge_ends[2e + 1]) with `costs` per edge: `price`, or
/// kOwnTrianglePriceShare of it for a node v with edges whose neighbours' cheapest pairs all cost
/// at most kOwnTriangleNeighbourShare of it and whose regret, the least over its edges (v, u) of
/// cost(v, u) − u's cheapest pair, is at least kOwnTriangleRegretShare of it (a node without
/// edges keeps `price`).
///
/// Why: a model's own triangle among the halves of good quads (a bevel's corner beside its
/// rectangles) can pair only by taking a neighbour from a far better quad; two of them, at the
/// full price, still cost more than the two poor quads made by breaking one good one between them
/// (a chamfered cube: 180° against 2 × 65°), so every own triangle would be routed through the
/// model's quads. A scan's triangle is seldom in that place: its neighbours' best pairs are
/// rarely much better than the ones it offers them, so its price stays, and a scan keeps pairing
/// nearly all of its triangles. Neighbours in good quads only: a sliver whose every pair is
/// hopeless (a fanned pentagon's) beside mediocre quads protects none, and letting it stay
/// cheaply only moves the optimum elsewhere. The rule reads the node's two rings of the graph
/// only, so a piece of a mesh prices its nodes as the whole does wherever those rings lie inside
/// it. O(n + m).
std::pmr::vector<Cost> triangle_prices(
    std::uint32_t node_count, std::span<const NodeId> edge_ends, std::span<const Cost> costs,
    Cost price, std::pmr::memory_resource* memory = std::pmr::get_default_resource());

}  // namespace petersen
