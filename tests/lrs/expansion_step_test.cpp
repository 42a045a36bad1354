// The expansion step (paper §3.3.1, Algorithms 3.1–3.4) on generated closed surfaces of genus 0
// to 30: K is a triangulation of the same surface on the same vertices, M pairs every face but
// the faces of T′, the flips are exactly the edges K does not share with T, and augmenting M gives
// a perfect matching whose quads pass the quad check.

#include "expansion_step.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <span>
#include <utility>

#include "contraction_step.hpp"
#include "dual_rows.hpp"
#include "petersen/generators/surface_generators.hpp"
#include "petersen/matching/augment.hpp"
#include "petersen/matching/perfect_partners.hpp"
#include "petersen/mesh/mesh_report.hpp"
#include "petersen/testing/arbitrary.hpp"
#include "quad_mesh_check.hpp"
#include "small_meshes.hpp"

namespace petersen::lrs {
namespace {

std::vector<std::pair<VertexId, VertexId>> edge_set(const PolygonMesh& mesh) {
  std::vector<std::pair<VertexId, VertexId>> edges;
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    const auto t = mesh.face(f);
    for (int k = 0; k < 3; ++k) {
      const VertexId a = t[k], b = t[(k + 1) % 3];
      if (a < b) edges.emplace_back(a, b);
    }
  }
  std::sort(edges.begin(), edges.end());
  return edges;
}

// `tri` is the triangulation of `mesh`, from from_mesh or from_dual.
void check_expansion(const PolygonMesh& mesh, Triangulation tri, std::uint32_t genus) {
  const std::uint32_t vertices = tri.live_vertices(), faces = tri.live_faces();
  const ContractionResult contraction = contract_to_irreducible(tri);
  const std::uint32_t irreducible_faces = tri.live_faces();
  const ExpansionResult expansion = expand_and_match(tri, contraction.stack);

  RC_ASSERT(tri.check() == "");
  RC_ASSERT(tri.live_vertices() == vertices);
  RC_ASSERT(tri.live_faces() == faces);
  RC_ASSERT(tri.genus() == genus);
  const PolygonMesh k = tri.to_mesh(mesh.positions);
  const MeshReport report = inspect_mesh(k);
  RC_ASSERT(report.closed());
  RC_ASSERT(report.pinched_vertices.empty());
  RC_ASSERT(report.components == 1u);
  RC_ASSERT(report.genus == std::optional<std::uint32_t>(genus));
  RC_ASSERT(report.vertices == vertices);

  // The flipped edges are exactly the edges of K that T does not have.
  const auto t_edges = edge_set(mesh), k_edges = edge_set(k);
  std::vector<std::pair<VertexId, VertexId>> new_edges;
  std::set_difference(k_edges.begin(), k_edges.end(), t_edges.begin(), t_edges.end(),
                      std::back_inserter(new_edges));
  RC_ASSERT(new_edges.size() == std::size_t{expansion.flipped_edges});

  // from_incidence checks the dual; M may not pair a face twice.
  const CubicGraph dual = testing::dual_graph_of(tri);
  Matching matching = testing::matching_of(dual, expansion);
  RC_ASSERT(verify_matching(dual, matching).ok());
  RC_ASSERT(matching.unmatched_count() == irreducible_faces);
  if (genus == 0) RC_ASSERT(matching.unmatched_count() == 4u);
  if (genus > 0) RC_ASSERT(matching.unmatched_count() <= 56 * genus - 12);

  // The lean form of the same: K's dual as rows, M as partners, K's triangles.
  ExpansionResult states = expansion;
  DualRows rows = into_dual_rows(std::move(tri), std::move(states));
  RC_ASSERT(rows.unpaired == matching.unmatched_count());
  RC_ASSERT(rows.triangles.size() == k.face_count());
  for (NodeId f = 0; f < dual.node_count(); ++f) {
    const auto kf = k.face(f);
    RC_ASSERT((rows.triangles[f] == std::array<VertexId, 3>{kf[0], kf[1], kf[2]}));
    for (int i = 0; i < 3; ++i) {
      RC_ASSERT(rows.rows[3 * f + i] == dual.other_end(dual.incident_edges(f)[i], f));
    }
    const EdgeId mate = matching.mate_edge[f];
    RC_ASSERT(rows.partner[f] == (mate == kNoEdge ? kNoNode : dual.other_end(mate, f)));
  }

  augment_matching(dual, matching);
  RC_ASSERT(verify_perfect_matching(dual, matching).ok());
  RC_ASSERT(petersen::testing::quad_mesh_problem(
                mesh, petersen::testing::quads_of_matching(k, dual, matching)) == "");
  augment_partners(rows.rows, rows.partner);
  RC_ASSERT(verify_perfect_partners(rows.rows, rows.partner).ok());
}

RC_GTEST_PROP(ExpansionStep, RandomClosedSurfacesOfGenusUpTo30, ()) {
  const auto genus = *rc::gen::inRange<std::uint32_t>(0, 31);
  const PolygonMesh mesh = *petersen::testing::closed_triangulations(genus);
  check_expansion(mesh, testing::from_triangles(mesh), genus);
}

// The same steps on the triangulation built from the dual (numbered spatially, as the quad front
// door builds it): the same guarantees.
RC_GTEST_PROP(ExpansionStep, FromTheDualOfRandomClosedSurfaces, ()) {
  const auto genus = *rc::gen::inRange<std::uint32_t>(0, 31);
  const PolygonMesh mesh = *petersen::testing::closed_triangulations(genus);
  check_expansion(mesh, testing::from_dual_of(mesh), genus);
}

RC_GTEST_PROP(ExpansionStep, VoxelPlates, ()) {
  PlateSpec spec;
  spec.holes_x = *rc::gen::inRange<std::uint32_t>(1, 4);
  spec.holes_y = *rc::gen::inRange<std::uint32_t>(1, 4);
  spec.subdivision = *rc::gen::inRange<std::uint32_t>(1, 4);
  spec.dents = *rc::gen::arbitrary<bool>();
  const PolygonMesh mesh = voxel_plate(spec);
  const std::uint32_t genus = spec.dents ? 0 : spec.holes_x * spec.holes_y;
  check_expansion(mesh, testing::from_triangles(mesh), genus);
  check_expansion(mesh, testing::from_dual_of(mesh), genus);
}

TEST(ExpansionStep, OctahedronLeavesTheFourTetrahedronFaces) {
  Triangulation tri = testing::from_triangles(testing::octahedron());
  const ContractionResult contraction = contract_to_irreducible(tri);
  const ExpansionResult expansion = expand_and_match(tri, contraction.stack);
  EXPECT_EQ(tri.check(), "");
  EXPECT_EQ(expansion.matched_edges, 2u);
  EXPECT_EQ(testing::matching_of(testing::dual_graph_of(tri), expansion).unmatched_count(), 4u);
}

}  // namespace
}  // namespace petersen::lrs
