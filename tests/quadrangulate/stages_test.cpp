// Each stage of the front door (stages.hpp) run alone, on meshes of every class, against what the
// test works out by itself: the pairable pairs and their costs from the faces (quad_of,
// quad_corner_deviation), the pairing's total from its pairs and the price, the output faces from
// the pairing, the figures from the output's quads. Then the stages composed by hand give
// quadrangulate()'s answer.

#include "petersen/quadrangulate/stages.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "petersen/dualize/quad_of.hpp"
#include "petersen/dualize/quad_quality.hpp"
#include "petersen/generators/polygon_generators.hpp"
#include "petersen/matching/min_cost_matching.hpp"
#include "petersen/quadrangulate/triangle_prices.hpp"
#include "petersen/testing/mesh_classes.hpp"
#include "result_check.hpp"

namespace petersen {
namespace {

rc::Gen<PolygonMesh> any_mesh() {
  return rc::gen::mapcat(rc::gen::elementOf(std::vector<testing::MeshClass>(
                             testing::kMeshClasses.begin(), testing::kMeshClasses.end())),
                         [](testing::MeshClass c) { return testing::meshes_of_class(c, 80); });
}

double deviation_of_pair(const PolygonMesh& mesh, FaceId a, FaceId b) {
  const auto q = quad_of(mesh.face(a), mesh.face(b));
  const auto& p = mesh.positions;
  return quad_corner_deviation(p[q[0]], p[q[1]], p[q[2]], p[q[3]]);
}

std::set<VertexId> corners_of(std::span<const VertexId> face) {
  return {face.begin(), face.end()};
}

RC_GTEST_PROP(PairableMeshStage, OneNodePerTriangleAndEachPairsOwnCost, ()) {
  const PolygonMesh mesh = *any_mesh();
  QuadStats stats;
  const PairableMesh pairable = pairable_mesh(mesh, {}, stats);
  const PairableGraph& graph = pairable.graph;
  std::uint32_t triangles = 0;
  for (FaceId f = 0; f < mesh.face_count(); ++f) triangles += mesh.arity(f) == 3;
  RC_ASSERT(graph.node_count == triangles);
  RC_ASSERT(stats.triangles == triangles);
  RC_ASSERT(pairable.costs.size() == graph.edge_count());
  for (EdgeId e = 0; e < graph.edge_count(); ++e) {
    const FaceId a = graph.face_of(graph.edge_ends[2 * e]);
    const FaceId b = graph.face_of(graph.edge_ends[2 * e + 1]);
    // The two faces share an edge: their union has four distinct corners.
    std::set<VertexId> both = corners_of(mesh.face(a));
    for (VertexId v : mesh.face(b)) both.insert(v);
    RC_ASSERT(both.size() == 4u);
    RC_ASSERT(std::abs(pairable.costs[e] - deviation_of_pair(mesh, a, b)) < 1e-9);
  }
}

RC_GTEST_PROP(PairableMeshStage, ThresholdCutsExactlyThePairsAboveIt, ()) {
  const PolygonMesh mesh = *any_mesh();
  const double limit = *rc::gen::element(10.0, 30.0, 60.0);
  QuadStats all_stats, cut_stats;
  const PairableMesh all = pairable_mesh(mesh, {.objective = Objective::pairs}, all_stats);
  RC_ASSERT(all.costs.empty());  // the pairs objective without a threshold measures nothing
  const PairableMesh cut = pairable_mesh(
      mesh, {.objective = Objective::pairs, .max_corner_deviation = limit}, cut_stats);
  std::size_t above = 0;
  for (EdgeId e = 0; e < all.graph.edge_count(); ++e) {
    const FaceId a = all.graph.face_of(all.graph.edge_ends[2 * e]);
    const FaceId b = all.graph.face_of(all.graph.edge_ends[2 * e + 1]);
    above += deviation_of_pair(mesh, a, b) > limit;
  }
  RC_ASSERT(cut.graph.edge_count() + above == all.graph.edge_count());
  RC_ASSERT(cut_stats.cuts.by_cause[static_cast<int>(CutCause::shape)] == above);
  for (double c : cut.costs) RC_ASSERT(c <= limit);
}

RC_GTEST_PROP(PairTrianglesStage, PairsNeighboursAtTheTotalItCertifies, ()) {
  const PolygonMesh mesh = *any_mesh();
  const QuadOptions options{.triangle_cost = *rc::gen::element(20.0, kDefaultTriangleCost)};
  QuadStats stats;
  PairableMesh pairable = pairable_mesh(mesh, options, stats);
  // The pairs' scaled costs by node pair, read before the pairing takes the graph's arrays.
  std::set<std::pair<NodeId, NodeId>> edges;
  std::vector<std::tuple<NodeId, NodeId, Cost>> costed;
  const std::pmr::vector<Cost> scaled = scale_costs(pairable.costs);
  for (EdgeId e = 0; e < pairable.graph.edge_count(); ++e) {
    const NodeId a = pairable.graph.edge_ends[2 * e], b = pairable.graph.edge_ends[2 * e + 1];
    edges.insert({std::min(a, b), std::max(a, b)});
    costed.emplace_back(std::min(a, b), std::max(a, b), scaled[e]);
  }
  const NodeId nodes = pairable.graph.node_count;
  const std::pmr::vector<Cost> prices =
      triangle_prices(nodes, pairable.graph.edge_ends, scaled,
                      std::llround(options.triangle_cost * kDefaultCostScale));
  const TrianglePairing pairing =
      pair_triangles(pairable.graph, mesh, nullptr, pairable.costs, options, stats);
  RC_ASSERT(stats.optimality_certified);
  RC_ASSERT(pairing.partner.size() == nodes);
  Cost total = 0;
  for (NodeId v = 0; v < nodes; ++v) {
    const NodeId w = pairing.partner[v];
    if (w == kNoNode) {
      total += prices[v];
      continue;
    }
    RC_ASSERT(pairing.partner[w] == v);
    RC_ASSERT(edges.count({std::min(v, w), std::max(v, w)}) == 1u);
    if (v < w) {
      // The cheapest of parallel pairs between the two (the solver takes the cheapest).
      Cost cheapest = INT64_MAX;
      for (const auto& [a, b, c] : costed)
        if (a == v && b == w) cheapest = std::min(cheapest, c);
      total += cheapest;
    }
  }
  RC_ASSERT(total == pairing.objective_units);
}

// The stages up to the output, by hand: the output and its kinds, with the pairing they came from.
struct Staged {
  std::vector<NodeId> partner;
  PairableGraph graph;
  OutputFaces out;
  QuadStats stats;
};
Staged stage_to_output(const PolygonMesh& mesh, const QuadOptions& options, bool with_sources) {
  Staged staged;
  PairableMesh pairable = pairable_mesh(mesh, options, staged.stats);
  TrianglePairing pairing =
      pair_triangles(pairable.graph, mesh, nullptr, pairable.costs, options, staged.stats);
  staged.partner.assign(pairing.partner.begin(), pairing.partner.end());
  staged.out = output_faces(mesh, pairable.graph, std::move(pairing), mesh.positions, with_sources,
                            staged.stats);
  staged.graph = std::move(pairable.graph);
  return staged;
}

RC_GTEST_PROP(OutputFacesStage, EachPairOneQuadOfItsTrianglesTheRestAsTheyWere, ()) {
  const PolygonMesh mesh = *any_mesh();
  const Staged staged = stage_to_output(mesh, {}, true);
  const QuadResult& result = staged.out.result;
  std::size_t paired = 0;
  for (NodeId w : staged.partner) paired += w != kNoNode;
  RC_ASSERT(result.mesh.face_count() == mesh.face_count() - paired / 2);
  RC_ASSERT(staged.out.kinds.size() == result.mesh.face_count());
  RC_ASSERT(result.sources.size() == result.mesh.face_count());
  RC_ASSERT(staged.stats.pairs == paired / 2);
  RC_ASSERT(staged.stats.triangles_left == staged.graph.node_count - paired);
  for (FaceId o = 0; o < result.mesh.face_count(); ++o) {
    const auto [first, second] = result.sources[o];
    const FaceKind kind = staged.out.kinds[o];
    if (kind == FaceKind::pair) {
      std::set<VertexId> both = corners_of(mesh.face(first));
      for (VertexId v : mesh.face(second)) both.insert(v);
      RC_ASSERT(corners_of(result.mesh.face(o)) == both);
      RC_ASSERT(result.mesh.arity(o) == 4u);
    } else {
      RC_ASSERT(second == kNoFace);
      const auto in = mesh.face(first), now = result.mesh.face(o);
      RC_ASSERT(std::equal(in.begin(), in.end(), now.begin(), now.end()));
      RC_ASSERT((kind == FaceKind::left) == (mesh.arity(first) == 3));
    }
  }
}

RC_GTEST_PROP(MeasureQuadsStage, TheQuadsFiguresOnAnyThreads, ()) {
  const PolygonMesh mesh = *any_mesh();
  const Staged staged = stage_to_output(mesh, {.objective = Objective::pairs}, false);
  const PolygonMesh& out = staged.out.result.mesh;
  std::vector<double> costs;
  for (FaceId o = 0; o < out.face_count(); ++o) {
    if (staged.out.kinds[o] != FaceKind::pair) continue;
    const auto c = out.face(o);
    costs.push_back(quad_corner_deviation(out.positions[c[0]], out.positions[c[1]],
                                          out.positions[c[2]], out.positions[c[3]]));
  }
  const QualityFigures expected = quality_figures(costs);
  for (std::uint32_t threads : {1u, 3u}) {
    const QualityFigures got = measure_quads(out, staged.out.kinds, threads);
    RC_ASSERT(got.median == expected.median);
    RC_ASSERT(got.p95 == expected.p95);
    RC_ASSERT(got.nonconvex == expected.nonconvex);
    RC_ASSERT(std::abs(got.total - expected.total) <= 1e-9 * (1 + std::abs(expected.total)));
  }
}

RC_GTEST_PROP(AttributesOfPairsStage, EachQuadCarriesItsTrianglesValues, ()) {
  const PolygonMesh mesh = *testing::meshes_of_class(testing::MeshClass::textured, 80);
  const Staged staged = stage_to_output(mesh, {}, true);
  QuadResult result = staged.out.result;
  result.mesh.attributes = attributes_of_pairs(mesh, result.mesh, result.sources);
  RC_ASSERT(testing::check_attributes_kept(mesh, result) == "");
}

TEST(SplitLeftoversStage, MakesEveryFaceOfAnOutputAQuad) {
  // An open grid with holes, paired by the default: triangles are left beside the holes.
  const PolygonMesh mesh = punch_holes(open_grid(9, 7), 4, 3);
  const QuadOptions options{.all_quad = true, .sources = true};
  Staged staged = stage_to_output(mesh, options, true);
  ASSERT_GT(staged.stats.triangles_left, 0u);
  QuadResult& result = staged.out.result;
  result.stats = staged.stats;
  split_leftovers(result, staged.out.kinds, options);
  for (FaceId o = 0; o < result.mesh.face_count(); ++o) EXPECT_EQ(result.mesh.arity(o), 4u);
  EXPECT_TRUE(result.stats.all_quad_certified);
  EXPECT_EQ(result.stats.added_vertices, result.stats.split_edges + result.stats.centre_vertices);
  EXPECT_EQ(result.mesh.positions.size(), mesh.positions.size() + result.stats.added_vertices);
  EXPECT_EQ(testing::check_quad_result(mesh, result, options), "");
}

RC_GTEST_PROP(Stages, ComposedByHandGiveTheFrontDoorsAnswer, ()) {
  const PolygonMesh mesh = *any_mesh();
  const QuadOptions options{
      .objective = *rc::gen::element(Objective::quads, Objective::pairs, Objective::quality)};
  const QuadResult door = quadrangulate(mesh, options);
  const Staged staged = stage_to_output(mesh, options, false);
  const PolygonMesh& out = staged.out.result.mesh;
  RC_ASSERT(out.corners == door.mesh.corners);
  RC_ASSERT(out.face_start == door.mesh.face_start);
  RC_ASSERT(staged.stats.pairs == door.stats.pairs);
  RC_ASSERT(staged.stats.triangles_left == door.stats.triangles_left);
}

}  // namespace
}  // namespace petersen
