#pragma once
// Diks and Stańczyk's chooser (SOFSEM 2010, LNCS 5901; paper §3.2): a spanning forest of the
// current graph kept by fully dynamic connectivity, mirrored in link-cut trees, read as a
// quartet topology of x1..x4 in H' = H − {u, v}.
//
// Why the quartet decides (H connected and bridgeless, e = {u, v} simple). Each component of H'
// has at least two of the four attachment edges to {u, v} (else H has a bridge), and one from
// each of u and v (else e is a bridge); so H' has one component, or two split 13|24 or 14|23,
// and then the reduction that pairs across the split is the connected one. If H' is connected,
// H1 = H' + x1x3 + x2x4 is bridgeless iff every bridge of H' lies on a cycle through a new edge,
// i.e. separates x1 from x3 or x2 from x4; every side of a bridge of H' holds an attachment
// (else it is a bridge of H), so H1 fails iff some bridge splits {x1, x3} | {x2, x4}. Bridges
// lie in every spanning tree T, and a tree edge splits 13|24 only when T's quartet topology on
// x1..x4 is 13|24. Hence: if T's quartet is 13|24, take H2; otherwise H1 is safe. No bridge
// needs to be found; the topology is read with three LCA queries after evert(x1).

#include "petersen/graph/dynamic_connectivity.hpp"
#include "petersen/graph/link_cut_tree.hpp"
#include "reduction/chooser.hpp"

namespace petersen::reduction {

class DsChooser final : public Chooser {
 public:
  /// Inserts every edge of `graph`; `edge_capacity` bounds the ids of edges added later.
  DsChooser(const CubicGraph& graph, std::uint32_t edge_capacity);
  void remove(const ReductionGraph& graph, std::span<const EdgeId> edges) override;
  bool choose_h1(const ReductionGraph& graph, const Step& step) override;
  void add(const ReductionGraph& graph, std::span<const EdgeId> edges) override;
  std::uint64_t replacement_searches() const override {
    return connectivity_.replacement_searches();
  }

 private:
  void insert(EdgeId e, NodeId a, NodeId b);

  DynamicConnectivity connectivity_;
  LinkCutTree forest_;  // F_0 of connectivity_
};

}  // namespace petersen::reduction
