// The contraction step (paper §3.3) on generated closed surfaces of genus 0 to 30: T′ is
// irreducible (brute force), of the right size, and the recorded stack undoes exactly.

#include "contraction_step.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "petersen/generators/surface_generators.hpp"
#include "petersen/testing/arbitrary.hpp"
#include "small_meshes.hpp"

namespace petersen::lrs {
namespace {

void check_contraction(const PolygonMesh& mesh, std::uint32_t genus) {
  const Triangulation original = testing::from_triangles(mesh);
  RC_ASSERT(original.genus() == genus);
  Triangulation tri = original;
  const ContractionResult result = contract_to_irreducible(tri);
  RC_ASSERT(tri.check() == "");
  RC_ASSERT(tri.genus() == genus);
  RC_ASSERT(result.stack.size() == original.live_vertices() - tri.live_vertices());
  RC_ASSERT(result.processed.size() == std::size_t{tri.live_vertices()});
  for (const VertexId u : result.processed) RC_ASSERT(tri.vertex_alive(u));
  // Irreducible: no live edge passes the link condition, tested from both ends.
  VertexMarks marks(tri.vertex_capacity());
  for (EdgeId e = 0; e < tri.edge_capacity(); ++e) {
    if (!tri.edge_alive(e)) continue;
    RC_ASSERT(!is_contractible(tri, 2 * e, marks));
    RC_ASSERT(!is_contractible(tri, 2 * e + 1, marks));
  }
  if (genus == 0) {
    RC_ASSERT(tri.live_vertices() == 4u);  // the tetrahedron (Proposition 3.1)
    RC_ASSERT(tri.live_faces() == 4u);
  } else {
    RC_ASSERT(tri.live_vertices() <= 26 * genus - 4);  // Theorem 3.1
  }
  for (auto it = result.stack.rbegin(); it != result.stack.rend(); ++it) split(tri, *it);
  RC_ASSERT(testing::identical(tri, original));
}

RC_GTEST_PROP(ContractionStep, RandomClosedSurfacesOfGenusUpTo30, ()) {
  const auto genus = *rc::gen::inRange<std::uint32_t>(0, 31);
  const PolygonMesh mesh = *petersen::testing::closed_triangulations(genus);
  check_contraction(mesh, genus);
}

RC_GTEST_PROP(ContractionStep, VoxelPlates, ()) {
  PlateSpec spec;
  spec.holes_x = *rc::gen::inRange<std::uint32_t>(1, 4);
  spec.holes_y = *rc::gen::inRange<std::uint32_t>(1, 4);
  spec.subdivision = *rc::gen::inRange<std::uint32_t>(1, 4);
  spec.dents = *rc::gen::arbitrary<bool>();
  check_contraction(voxel_plate(spec), spec.dents ? 0 : spec.holes_x * spec.holes_y);
}

TEST(ContractionStep, TetrahedronIsAlreadyIrreducible) {
  Triangulation tri = testing::from_triangles(testing::tetrahedron());
  const ContractionResult result = contract_to_irreducible(tri);
  EXPECT_TRUE(result.stack.empty());
  EXPECT_EQ(result.processed, (std::pmr::vector<VertexId>{0, 1, 2, 3}));
}

TEST(ContractionStep, OctahedronShrinksToTheTetrahedron) {
  Triangulation tri = testing::from_triangles(testing::octahedron());
  const ContractionResult result = contract_to_irreducible(tri);
  EXPECT_EQ(result.stack.size(), 2u);
  EXPECT_EQ(tri.live_vertices(), 4u);
  EXPECT_EQ(tri.check(), "");
  EXPECT_EQ(result.processed.front(), 0u);  // vertex 0 is processed first and survives
}

}  // namespace
}  // namespace petersen::lrs
