// RapidCheck: every generated closed surface goes mesh -> surface check -> dual -> LEMON matching
// -> quads, and every step is verified.

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "peers.hpp"
#include "petersen/dualize/dual.hpp"
#include "petersen/generators/surface_generators.hpp"
#include "petersen/graph/connectivity.hpp"
#include "petersen/mesh/mesh_report.hpp"
#include "petersen/testing/arbitrary.hpp"
#include "quad_mesh_check.hpp"

namespace petersen {
namespace {

void check_pipeline(const PolygonMesh& mesh, std::uint32_t genus) {
  require_closed_surface(mesh,
                         {.allow_pinched_vertices = false, .allow_several_components = false});
  const MeshReport report = inspect_mesh(mesh);
  RC_ASSERT(report.genus == std::optional<std::uint32_t>(genus));
  RC_ASSERT(report.euler_characteristic == 2 - 2 * std::int64_t{genus});
  const Dual dual = build_dual(mesh);
  validate_connected_bridgeless(dual.graph);
  for (FaceId t = 0; t < mesh.face_count(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const EdgeId e = dual.dual_edge(t, k);
      RC_ASSERT(dual.side(e, 0) == 3 * t + k || dual.side(e, 1) == 3 * t + k);
    }
  }
  const Matching matching = testing::lemon_matching(dual.graph);
  RC_ASSERT(verify_perfect_matching(dual.graph, matching).ok());
  RC_ASSERT(testing::quad_mesh_problem(
                mesh, testing::quads_of_matching(mesh, dual.graph, matching)) == "");
}

RC_GTEST_PROP(SurfacePipeline, RandomClosedSurfacesOfGenusUpTo30, ()) {
  const auto genus = *rc::gen::inRange<std::uint32_t>(0, 31);
  const PolygonMesh mesh = *petersen::testing::closed_triangulations(genus);
  check_pipeline(mesh, genus);
}

RC_GTEST_PROP(SurfacePipeline, VoxelPlates, ()) {
  PlateSpec spec;
  spec.holes_x = *rc::gen::inRange<std::uint32_t>(1, 4);
  spec.holes_y = *rc::gen::inRange<std::uint32_t>(1, 4);
  spec.subdivision = *rc::gen::inRange<std::uint32_t>(1, 4);
  spec.dents = *rc::gen::arbitrary<bool>();
  check_pipeline(voxel_plate(spec), spec.dents ? 0 : spec.holes_x * spec.holes_y);
}

}  // namespace
}  // namespace petersen
