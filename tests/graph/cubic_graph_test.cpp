#include "petersen/graph/cubic_graph.hpp"

#include <gtest/gtest.h>

#include "petersen/generators/graph_generators.hpp"

namespace petersen {
namespace {

using EdgeList = std::vector<std::array<NodeId, 2>>;

TEST(CubicGraph, BuildsThetaWithParallelEdges) {
  EdgeList edges = {{0, 1}, {0, 1}, {1, 0}};
  CubicGraph g = CubicGraph::from_edges(2, edges);
  EXPECT_EQ(g.node_count(), 2u);
  EXPECT_EQ(g.edge_count(), 3u);
  for (EdgeId e = 0; e < 3; ++e) {
    EXPECT_EQ(g.other_end(e, 0), 1u);
    EXPECT_EQ(g.other_end(e, 1), 0u);
  }
  EXPECT_EQ(g.incident_edge(1, 2), 2u);
}

TEST(CubicGraph, IncidentEdgesKeepEdgeListOrder) {
  EdgeList edges = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  CubicGraph g = CubicGraph::from_edges(4, edges);
  auto at0 = g.incident_edges(0);
  EXPECT_EQ((std::vector<EdgeId>(at0.begin(), at0.end())), (std::vector<EdgeId>{0, 1, 2}));
  EXPECT_EQ(g.endpoints(5), (std::array<NodeId, 2>{2, 3}));
}

TEST(CubicGraph, RejectsLoopNamingTheEdge) {
  EdgeList edges = {{0, 1}, {0, 1}, {0, 0}};
  try {
    CubicGraph::from_edges(2, edges);
    FAIL() << "a loop was accepted";
  } catch (const GraphError& e) {
    EXPECT_NE(std::string(e.what()).find("edge 2 is a loop"), std::string::npos) << e.what();
  }
}

TEST(CubicGraph, RejectsWrongDegreeNamingTheNode) {
  EdgeList edges = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}};
  try {
    CubicGraph::from_edges(4, edges);
    FAIL() << "a non-cubic graph was accepted";
  } catch (const GraphError& e) {
    EXPECT_NE(std::string(e.what()).find("node 2 has degree 2"), std::string::npos) << e.what();
  }
  EdgeList too_many = {{0, 1}, {0, 1}, {0, 1}, {0, 1}};
  EXPECT_THROW(CubicGraph::from_edges(2, too_many), GraphError);
}

TEST(CubicGraph, RejectsEndpointOutOfRange) {
  EdgeList edges = {{0, 1}, {0, 1}, {0, 7}};
  EXPECT_THROW(CubicGraph::from_edges(2, edges), GraphError);
}

TEST(CubicGraph, FromIncidenceKeepsTheCallersSlotOrder) {
  // Theta graph with node 1 listing its edges in reverse.
  CubicGraph g = CubicGraph::from_incidence({0, 1, 2, 2, 1, 0}, {0, 1, 0, 1, 0, 1});
  EXPECT_EQ(g.incident_edge(1, 0), 2u);
  EXPECT_EQ(g.other_end(2, 1), 0u);
}

TEST(CubicGraph, FromIncidenceRejectsInconsistentSlots) {
  // Node 0 lists edge 0 twice and node 1 never lists it.
  EXPECT_THROW(CubicGraph::from_incidence({0, 0, 1, 1, 2, 2}, {0, 1, 0, 1, 0, 1}), GraphError);
  // Node 1 lists edge 0, which joins 0 and 2 only.
  EXPECT_THROW(CubicGraph::from_incidence({0, 1, 2, 0, 3, 4, 1, 5, 3, 2, 4, 5},
                                          {0, 2, 0, 2, 0, 3, 1, 2, 1, 3, 2, 3}),
               GraphError);
  EXPECT_THROW(CubicGraph::from_incidence({0, 1, 2, 0, 1, 2}, {0, 0, 0, 1, 0, 1}), GraphError);
  EXPECT_THROW(CubicGraph::from_incidence({0, 1}, {0, 1}), GraphError);
}

TEST(CubicGraph, NeighbourRowsNameTheOtherEndOfEachSlot) {
  // Large enough for the read-ahead, with parallel edges (the configuration model keeps them).
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    CubicGraph g = random_cubic_bridgeless(1000, seed);
    std::vector<NodeId> expected;
    for (NodeId v = 0; v < g.node_count(); ++v)
      for (EdgeId e : g.incident_edges(v)) expected.push_back(g.other_end(e, v));
    const std::pmr::vector<NodeId> rows = std::move(g).into_neighbour_rows();
    EXPECT_EQ(std::vector<NodeId>(rows.begin(), rows.end()), expected);
  }
  const std::pmr::vector<NodeId> theta =
      CubicGraph::from_incidence({0, 1, 2, 2, 1, 0}, {0, 1, 0, 1, 0, 1}).into_neighbour_rows();
  EXPECT_EQ(std::vector<NodeId>(theta.begin(), theta.end()),
            (std::vector<NodeId>{1, 1, 1, 0, 0, 0}));
}

TEST(CubicGraph, NeighbourRowsWithWorkBesideReadTheEdgesBeforeTheyAreFreed) {
  for (std::uint32_t threads : {1u, 2u, 3u}) {
    CubicGraph g = random_cubic_bridgeless(1000, threads);
    const std::vector<NodeId> ends(g.edge_ends().begin(), g.edge_ends().end());
    std::vector<NodeId> expected;
    for (NodeId v = 0; v < g.node_count(); ++v)
      for (EdgeId e : g.incident_edges(v)) expected.push_back(g.other_end(e, v));
    std::vector<NodeId> seen;
    const std::pmr::vector<NodeId> rows =
        std::move(g).into_neighbour_rows(threads, [&](std::span<const NodeId> edge_ends) {
          seen.assign(edge_ends.begin(), edge_ends.end());
        });
    EXPECT_EQ(std::vector<NodeId>(rows.begin(), rows.end()), expected);
    EXPECT_EQ(seen, ends);
  }
  // The work's exception reaches the caller.
  EXPECT_THROW(CubicGraph::from_incidence({0, 1, 2, 2, 1, 0}, {0, 1, 0, 1, 0, 1})
                   .into_neighbour_rows(2, [](std::span<const NodeId>) { throw GraphError("x"); }),
               GraphError);
}

}  // namespace
}  // namespace petersen
