#pragma once
// RapidCheck generators of petersen's inputs, for property-based tests (target petersen::testing):
//
//   #include <petersen/testing/arbitrary.hpp>
//   RC_GTEST_PROP(MyMatching, IsPerfect, (const petersen::CubicGraph& g)) {
//     const petersen::PerfectMatchingResult r = petersen::perfect_matching(g);
//     RC_ASSERT(petersen::verify_perfect_matching(g, r.matching).ok());
//   }
//
// Every generator is seeded by RapidCheck and shrinks towards small inputs; the graphs and meshes
// themselves come from petersen's seeded generators, so a failing case replays exactly.

#include <rapidcheck.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <ostream>
#include <vector>

#include "petersen/dualize/dual.hpp"
#include "petersen/generators/graph_generators.hpp"
#include "petersen/generators/polygon_generators.hpp"
#include "petersen/generators/surface_generators.hpp"
#include "petersen/graph/cubic_graph.hpp"
#include "petersen/mesh/mesh.hpp"

namespace petersen {

/// Prints the node count and the edges (RapidCheck's counterexample report).
inline void showValue(const CubicGraph& graph, std::ostream& os) {
  os << "CubicGraph with " << graph.node_count() << " nodes, edges";
  for (EdgeId e = 0; e < graph.edge_count(); ++e) {
    const auto [a, b] = graph.endpoints(e);
    os << (e == 0 ? " " : ", ") << a << '-' << b;
  }
}

/// Prints the vertex and face counts and the faces' corners.
inline void showValue(const PolygonMesh& mesh, std::ostream& os) {
  os << "polygon mesh with " << mesh.positions.size() << " vertices, " << mesh.face_count()
     << " faces";
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    os << (f == 0 ? ": " : ", ");
    for (std::size_t k = 0; k < mesh.arity(f); ++k) os << (k == 0 ? "" : " ") << mesh.face(f)[k];
  }
}

namespace testing {

/// A cubic graph with one bridge planted: two cubic bridgeless halves, one edge of each
/// subdivided, the two new nodes joined by `bridge`. For tests that must refuse it.
struct GraphWithBridge {
  CubicGraph graph;
  EdgeId bridge = kNoEdge;
};

inline void showValue(const GraphWithBridge& value, std::ostream& os) {
  os << "bridge " << value.bridge << " in ";
  petersen::showValue(value.graph, os);
}

/// Random cubic bridgeless multigraphs (configuration model, parallel edges kept) of 2 to
/// 2 + 4·size nodes; shrinks towards 2 nodes (the theta graph's size).
inline rc::Gen<CubicGraph> random_cubic_graphs() {
  return rc::gen::withSize([](int size) {
    return rc::gen::apply(
        [](std::uint32_t half, std::uint64_t seed) {
          return random_cubic_bridgeless(2 * half, seed);
        },
        rc::gen::inRange<std::uint32_t>(1, 2 + 2 * static_cast<std::uint32_t>(size)),
        rc::gen::arbitrary<std::uint64_t>());
  });
}

/// Closed, oriented, irregular triangulations (all-triangle polygon meshes) of the given genus (a
/// plate with `genus` holes, or a cube for 0, then up to 3·size random triangle splits and edge
/// flips); shrinks towards the plate itself.
inline rc::Gen<PolygonMesh> closed_triangulations(std::uint32_t genus) {
  return rc::gen::withSize([genus](int size) {
    const auto most = 1 + 3 * static_cast<std::uint32_t>(size);
    return rc::gen::apply(
        [genus](std::uint32_t splits, std::uint32_t flips, std::uint64_t seed) {
          return random_closed_surface(genus, splits, flips, seed);
        },
        rc::gen::inRange<std::uint32_t>(0, most), rc::gen::inRange<std::uint32_t>(0, most),
        rc::gen::arbitrary<std::uint64_t>());
  });
}

/// Closed triangulations of any genus from 0 to `max_genus`; shrinks towards genus 0.
inline rc::Gen<PolygonMesh> closed_triangulations_up_to(std::uint32_t max_genus) {
  return rc::gen::mapcat(rc::gen::inRange<std::uint32_t>(0, max_genus + 1),
                         [](std::uint32_t genus) { return closed_triangulations(genus); });
}

/// Every kind of mesh a user has (petersen::random_mixed_mesh): closed surfaces of genus 0 to 3,
/// Klein bottles, projective planes and open grids, then holes, polygons (quads, pentagons),
/// non-manifold fins, pinched vertices, flipped faces and several components, each at random;
/// from a few faces to about 40·size. Shrinks towards small meshes.
inline rc::Gen<PolygonMesh> mixed_meshes() {
  return rc::gen::withSize([](int size) {
    return rc::gen::apply(
        [](std::uint64_t seed, std::uint32_t faces) { return random_mixed_mesh(seed, faces); },
        rc::gen::arbitrary<std::uint64_t>(),
        rc::gen::inRange<std::uint32_t>(4, 5 + 40 * static_cast<std::uint32_t>(size)));
  });
}

/// Cubic bridgeless multigraphs from every family petersen is tested on: random multigraphs,
/// necklaces of diamonds (2-edge cuts everywhere), prisms (k = 2 has parallel edges), the theta
/// graph, K4, K3,3, the Petersen graph, and duals of closed triangulations of genus 0 to 30.
inline rc::Gen<CubicGraph> cubic_bridgeless_graphs() {
  // Half of the draws are duals of triangulations, the graphs petersen is mostly used on.
  return rc::gen::weightedOneOf<CubicGraph>({
      {1, rc::gen::element(theta_graph(), complete_k4(), complete_k33(), petersen_graph())},
      {1, random_cubic_graphs()},
      {1, rc::gen::map(rc::gen::inRange<std::uint32_t>(1, 40),
                       [](std::uint32_t k) { return necklace(k); })},
      {1, rc::gen::map(rc::gen::inRange<std::uint32_t>(2, 60),
                       [](std::uint32_t k) { return prism(k); })},
      {4, rc::gen::map(closed_triangulations_up_to(30),
                       [](const PolygonMesh& mesh) { return dual_graph(mesh); })},
  });
}

/// A multigraph of any degrees as an edge list (edge e joins edges[e][0] and edges[e][1]).
struct EdgeListGraph {
  std::uint32_t node_count = 0;
  std::vector<std::array<NodeId, 2>> edges;
};

inline void showValue(const EdgeListGraph& graph, std::ostream& os) {
  os << "graph with " << graph.node_count << " nodes, edges";
  for (std::size_t e = 0; e < graph.edges.size(); ++e)
    os << (e == 0 ? " " : ", ") << graph.edges[e][0] << '-' << graph.edges[e][1];
}

/// General multigraphs for the maximum-matching fallback: 1 to 79 nodes, isolated nodes,
/// components of both parities (edges fall inside random blocks of nodes), parallel edges, any
/// degrees, no loops.
inline rc::Gen<EdgeListGraph> general_graphs() {
  return rc::gen::exec([] {
    EdgeListGraph g{*rc::gen::inRange<std::uint32_t>(1, 80), {}};
    const auto m = *rc::gen::inRange<std::uint32_t>(0, 3 * g.node_count);
    const auto block = *rc::gen::inRange<std::uint32_t>(1, g.node_count + 1);
    for (std::uint32_t i = 0; i < m; ++i) {
      const auto a = *rc::gen::inRange<std::uint32_t>(0, g.node_count);
      const auto lo = a / block * block;
      const auto b = *rc::gen::inRange<std::uint32_t>(lo, std::min(lo + block, g.node_count));
      if (a != b) g.edges.push_back({a, b});
    }
    return g;
  });
}

/// Cubic graphs with a planted bridge (see GraphWithBridge), halves of 2 to 2 + 2·size nodes.
inline rc::Gen<GraphWithBridge> cubic_graphs_with_a_bridge() {
  return rc::gen::apply(
      [](const CubicGraph& left, const CubicGraph& right) {
        std::vector<std::array<NodeId, 2>> edges;
        const NodeId offset = left.node_count(), n = left.node_count() + right.node_count();
        const NodeId s = n, t = n + 1;  // the new nodes on left's edge 0 and right's edge 0
        for (EdgeId e = 0; e < left.edge_count(); ++e) {
          const auto [a, b] = left.endpoints(e);
          if (e == 0) {
            edges.push_back({a, s});
            edges.push_back({s, b});
          } else {
            edges.push_back({a, b});
          }
        }
        for (EdgeId e = 0; e < right.edge_count(); ++e) {
          const auto [a, b] = right.endpoints(e);
          if (e == 0) {
            edges.push_back({a + offset, t});
            edges.push_back({t, b + offset});
          } else {
            edges.push_back({a + offset, b + offset});
          }
        }
        edges.push_back({s, t});
        return GraphWithBridge{CubicGraph::from_edges(n + 2, edges),
                               static_cast<EdgeId>(edges.size() - 1)};
      },
      random_cubic_graphs(), random_cubic_graphs());
}

}  // namespace testing
}  // namespace petersen

namespace rc {

/// rc::gen::arbitrary<petersen::CubicGraph>(): testing::cubic_bridgeless_graphs().
template <>
struct Arbitrary<petersen::CubicGraph> {
  static Gen<petersen::CubicGraph> arbitrary() {
    return petersen::testing::cubic_bridgeless_graphs();
  }
};

}  // namespace rc
