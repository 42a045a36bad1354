#pragma once
// What a reduction engine asks of a chooser: keep its data structures in step with the graph, and
// decide between Frink's two graphs H1 = H' + {x1x3, x2x4} and H2 = H' + {x1x4, x2x3}.

#include <cstdint>
#include <span>

#include "reduction/reduction_graph.hpp"

namespace petersen::reduction {

class Chooser {
 public:
  virtual ~Chooser() = default;
  /// `edges` leave the graph (called before ReductionGraph::apply; the graph is unchanged yet).
  virtual void remove(const ReductionGraph& graph, std::span<const EdgeId> edges) = 0;
  /// For a Frink step whose five edges were just removed: true when H1 (b3 paired with a1) is
  /// connected and bridgeless, false when H2 is. Frink proved one of them always is.
  virtual bool choose_h1(const ReductionGraph& graph, const Step& step) = 0;
  /// `edges` were just added by ReductionGraph::apply.
  virtual void add(const ReductionGraph& graph, std::span<const EdgeId> edges) = 0;
  /// Replacement-edge searches of the dynamic-connectivity structure (ds), if any.
  virtual std::uint64_t replacement_searches() const { return 0; }
  /// Tree edges swapped for the non-tree edge covering them (gw), if any.
  virtual std::uint64_t cover_swaps() const { return 0; }
  /// Debug mode, after every step: throws std::logic_error if the chooser's own structures no
  /// longer describe `graph` (brute force; choosers without checkable invariants do nothing).
  virtual void verify(const ReductionGraph& /*graph*/) {}
};

}  // namespace petersen::reduction
