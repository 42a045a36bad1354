// The LRS entry: quads on generated and shared surfaces, from a mesh and from its dual's arrays,
// statistics in the paper's terms, and clear refusals of inputs that are not closed orientable
// manifold surfaces.

#include "petersen/lrs/lrs.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cstdio>

#include "petersen/dualize/pairable_graph.hpp"
#include "petersen/generators/surface_generators.hpp"
#include "petersen/io/read_mesh.hpp"
#include "petersen/testing/arbitrary.hpp"
#include "quad_check.hpp"
#include "shared_meshes.hpp"
#include "small_meshes.hpp"

namespace petersen {
namespace {

#ifdef PETERSEN_SANITIZE
constexpr std::uint32_t kMaxTriangles = 200000;
#else
constexpr std::uint32_t kMaxTriangles = 0xFFFFFFFFu;
#endif

void check_result(const PolygonMesh& mesh, const LrsPairing& result, std::uint32_t genus) {
  const LrsStats& s = result.stats;
  const std::string problem = lrs::testing::quad_problem(mesh, result);
  RC_ASSERT(problem == "");
  RC_ASSERT(s.genus == genus);
  RC_ASSERT(s.unpaired_after_expansion == s.irreducible_faces);
  RC_ASSERT(s.augmenting_paths == s.unpaired_after_expansion / 2);
  RC_ASSERT(s.contractions == std::uint64_t{s.vertices} - s.irreducible_vertices);
  if (genus == 0) {
    RC_ASSERT(s.irreducible_vertices == 4u);
    RC_ASSERT(s.unpaired_after_expansion == 4u);
  } else {
    RC_ASSERT(s.irreducible_vertices <= 26 * genus - 4);
    RC_ASSERT(s.unpaired_after_expansion <= 56 * genus - 12);
  }
  RC_ASSERT(s.expansion_cases[0] + s.expansion_cases[1] + s.expansion_cases[2] +
                s.expansion_cases[3] ==
            s.contractions);
  RC_ASSERT(s.total_seconds >= s.matching_seconds());
}

// The dual-arrays entry on the mesh's pairable graph (its dual: the mesh is closed and oriented).
LrsPairing pair_from_dual(const PolygonMesh& mesh, const LrsOptions& options = {}) {
  PairableGraph graph = build_pairable_graph(mesh);
  return pair_closed_component_by_lrs(LrsDualInput{.positions = mesh.positions,
                                                   .corners = mesh.corners,
                                                   .node_edges = std::move(graph.node_edges),
                                                   .edge_ends = std::move(graph.edge_ends)},
                                      options);
}

RC_GTEST_PROP(Lrs, RandomClosedSurfacesOfGenusUpTo30, ()) {
  const auto genus = *rc::gen::inRange<std::uint32_t>(0, 31);
  const PolygonMesh mesh = *petersen::testing::closed_triangulations(genus);
  const auto augment = *rc::gen::element(Augment::local, Augment::faithful);
  check_result(mesh, pair_closed_component_by_lrs(mesh, {.augment = augment}), genus);
  check_result(mesh, pair_from_dual(mesh, {.augment = augment}), genus);
}

RC_GTEST_PROP(Lrs, VoxelPlates, ()) {
  PlateSpec spec;
  spec.holes_x = *rc::gen::inRange<std::uint32_t>(1, 4);
  spec.holes_y = *rc::gen::inRange<std::uint32_t>(1, 4);
  spec.subdivision = *rc::gen::inRange<std::uint32_t>(1, 4);
  spec.dents = *rc::gen::arbitrary<bool>();
  const PolygonMesh mesh = voxel_plate(spec);
  const std::uint32_t genus = spec.dents ? 0 : spec.holes_x * spec.holes_y;
  check_result(mesh, pair_closed_component_by_lrs(mesh), genus);
  check_result(mesh, pair_from_dual(mesh), genus);
}

// Without sources every quad names no input triangle, and the caller's corners_read runs once.
TEST(Lrs, WithoutSourcesTheCornersAreReleasedOnce) {
  const PolygonMesh mesh = random_closed_surface(2, 400, 400, 3);
  PairableGraph graph = build_pairable_graph(mesh);
  int calls = 0;
  const LrsPairing result =
      pair_closed_component_by_lrs(LrsDualInput{.positions = mesh.positions,
                                                .corners = mesh.corners,
                                                .node_edges = std::move(graph.node_edges),
                                                .edge_ends = std::move(graph.edge_ends),
                                                .corners_read = [&] { ++calls; }},
                                   {.sources = false});
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(2 * result.quads.size(), mesh.face_count());
  for (const LrsQuad& quad : result.quads) {
    EXPECT_EQ(quad.sources, (std::array<FaceId, 2>{kNoFace, kNoFace}));
  }
}

TEST(Lrs, EveryExpansionCaseRunsOnAnIrregularSphere) {
  const PolygonMesh mesh = random_closed_surface(0, 3000, 3000, 7);
  const LrsPairing result = pair_closed_component_by_lrs(mesh);
  for (int c = 0; c < 4; ++c) EXPECT_GT(result.stats.expansion_cases[c], 0u) << "case " << c;
  EXPECT_GT(result.stats.flipped_edges, 0u);
  EXPECT_EQ(lrs::testing::quad_problem(mesh, result), "");
  // A flipped triangle is no input triangle: some quads name fewer than two sources.
  EXPECT_TRUE(std::any_of(result.quads.begin(), result.quads.end(), [](const LrsQuad& quad) {
    return quad.sources[0] == kNoFace || quad.sources[1] == kNoFace;
  }));
}

TEST(Lrs, RefusesWhatIsNotAClosedOrientableManifold) {
  const auto refuses = [](const PolygonMesh& mesh, const std::string& names) {
    try {
      pair_closed_component_by_lrs((mesh));
      ADD_FAILURE() << "accepted a mesh that should name " << names;
    } catch (const MeshError& error) {
      EXPECT_NE(std::string(error.what()).find(names), std::string::npos) << error.what();
    }
  };
  // Two tetrahedra sharing vertex 0.
  refuses(
      lrs::testing::mesh_of(
          7,
          {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}, {0, 5, 4}, {0, 4, 6}, {4, 5, 6}, {0, 6, 5}}),
      "vertex 0");
  PolygonMesh open = lrs::testing::tetrahedron();
  open.corners.resize(open.corners.size() - 3);
  refuses(open, "edge");
  PolygonMesh flipped = lrs::testing::tetrahedron();
  std::swap(flipped.corners[3 * 3 + 1], flipped.corners[3 * 3 + 2]);
  refuses(flipped, "edge");
  // Two disjoint tetrahedra.
  refuses(
      lrs::testing::mesh_of(
          8,
          {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}, {4, 6, 5}, {4, 5, 7}, {5, 6, 7}, {4, 7, 6}}),
      "component");
}

TEST(Lrs, SharedMeshesConvert) {
  const auto dir = testing::shared_mesh_dir();
  if (!dir) GTEST_SKIP() << "no ../shared/meshes (set PETERSEN_SHARED_MESHES)";
  for (const auto& expected : testing::shared_meshes_up_to(kMaxTriangles)) {
    SCOPED_TRACE(expected.file);
    const PolygonMesh mesh = read_mesh(*dir + "/" + expected.file);
    const LrsPairing result = pair_closed_component_by_lrs(mesh);
    const LrsStats& s = result.stats;
    EXPECT_EQ(lrs::testing::quad_problem(mesh, result), "");
    EXPECT_EQ(s.genus, expected.genus);
    if (expected.genus == 0) {
      EXPECT_EQ(s.unpaired_after_expansion, 4u);
    } else {
      EXPECT_LE(s.unpaired_after_expansion, 56 * expected.genus - 12);
    }
    std::printf(
        "%-24s g=%-3u F=%-8u |T'|=%-4u l=%-4u flipped=%u (%.2f%% of edges) "
        "contract %.3fs expand %.3fs augment %.3fs total %.3fs\n",
        expected.file.c_str(), s.genus, s.faces, s.irreducible_vertices, s.unpaired_after_expansion,
        s.flipped_edges, s.flipped_percent(), s.contraction_seconds, s.expansion_seconds,
        s.augment_seconds, s.total_seconds);
  }
}

}  // namespace
}  // namespace petersen
