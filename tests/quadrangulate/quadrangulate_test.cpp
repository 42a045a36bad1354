// The mesh front door on every kind of mesh: closed, open, polygons, non-manifold edges, flipped
// faces, several components; every answer checked by result_check (independent of the code).

#include "petersen/quadrangulate/quadrangulate.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "petersen/dualize/quad_quality.hpp"
#include "petersen/generators/polygon_generators.hpp"
#include "petersen/generators/surface_generators.hpp"
#include "petersen/matching/min_cost_matching.hpp"
#include "petersen/mesh/mesh_report.hpp"
#include "petersen/testing/arbitrary.hpp"
#include "petersen/testing/random_attributes.hpp"
#include "result_check.hpp"
#include "shuffled_faces.hpp"

namespace petersen {
namespace {

using testing::check_attributes_kept;
using testing::check_quad_result;

constexpr PairingAlgorithm kAlgorithms[] = {
    Algorithm::automatic, Algorithm::sg,    Algorithm::ps, Algorithm::ds,
    Algorithm::gw,        Algorithm::frink, kLrs};

PolygonMesh mesh_of(std::vector<std::array<double, 3>> positions,
                    std::vector<std::vector<VertexId>> faces) {
  PolygonMesh mesh;
  for (const auto& p : positions) mesh.positions.push_back(p);
  for (const auto& f : faces) mesh.add_face(f);
  return mesh;
}

void expect_correct(const PolygonMesh& mesh, bool all_quad = false) {
  for (const PairingAlgorithm& algorithm : kAlgorithms) {
    SCOPED_TRACE(std::string(to_string(algorithm)));
    const QuadResult result = quadrangulate(
        mesh, {.objective = Objective::pairs, .algorithm = algorithm, .all_quad = all_quad});
    EXPECT_TRUE(result.stats.maximum_certified);
    EXPECT_EQ(check_quad_result(mesh, result, all_quad, std::holds_alternative<Lrs>(algorithm)),
              "");
  }
}

// A square of two triangles, a lone triangle beside it, and a quad: one pair, one left, one kept.
TEST(Quadrangulate, PairsWhatItCanAndKeepsTheRest) {
  const PolygonMesh mesh = mesh_of({{0, 0, 0},
                                    {1, 0, 0},
                                    {1, 1, 0},
                                    {0, 1, 0},
                                    {2, 0, 0},
                                    {3, 0, 0},
                                    {3, 1, 0},
                                    {2, 1, 0},
                                    {5, 0, 0}},
                                   {{0, 1, 2}, {0, 2, 3}, {4, 5, 6, 7}, {5, 8, 6}});
  const QuadResult result = quadrangulate(mesh);
  EXPECT_EQ(result.stats.pairs, 1u);
  EXPECT_EQ(result.stats.triangles_left, 1u);
  EXPECT_EQ(result.stats.polygons_kept, 1u);
  EXPECT_EQ(result.stats.cuts.by_cause[int(CutCause::polygon)], 1u);
  ASSERT_EQ(result.mesh.face_count(), 3u);
  const std::vector<VertexId> quad(result.mesh.face(0).begin(), result.mesh.face(0).end());
  // Triangle 0 = (0, 1, 2) meets triangle 1 across 2 -> 0; the quad starts there, in 0's order.
  EXPECT_EQ(quad, (std::vector<VertexId>{2, 3, 0, 1}));
  expect_correct(mesh);
}

// auto on a regular plate, whose dual is bipartite: in the generator's order the ordered sweep
// pairs every triangle; with the triangles shuffled, Schrijver's exact matching does (nothing left
// to augment either way); on the same plate made irregular (odd cycles in the dual) PS runs, and
// the summary says which ran.
TEST(Quadrangulate, ReportsHowABipartiteDualWasPaired) {
  const PolygonMesh plate = voxel_plate({.holes_x = 2, .holes_y = 1, .subdivision = 3});
  // The paper's algorithms: objective pairs.
  const QuadOptions pairs{.objective = Objective::pairs};
  const QuadResult in_order = quadrangulate(plate, pairs);
  EXPECT_TRUE(in_order.stats.matching.ordered_sweep);
  EXPECT_EQ(in_order.stats.matching.unpaired_after_initial, 0u);
  const QuadResult regular = quadrangulate(testing::shuffled_faces(plate, 11), pairs);
  EXPECT_TRUE(regular.stats.matching.schrijver);
  EXPECT_EQ(regular.stats.matching.unpaired_after_initial, 0u);
  EXPECT_EQ(regular.stats.triangles_left, 0u);
  EXPECT_TRUE(regular.stats.maximum_certified);
  const QuadResult irregular = quadrangulate(randomize_triangulation(plate, 7, 200, 1), pairs);
  EXPECT_FALSE(irregular.stats.matching.schrijver);
  EXPECT_EQ(irregular.stats.triangles_left, 0u);
  EXPECT_TRUE(irregular.stats.maximum_certified);
}

// lrs's augmentation reports its searches like ps's: on irregular plates whose expansion leaves
// triangles unpaired, the labels given are counted (at least one root per path), not only the
// paths.
TEST(Quadrangulate, LrsReportsItsAugmentationsLabels) {
  int augmented = 0;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const PolygonMesh plate = randomize_triangulation(
        voxel_plate({.holes_x = 2, .holes_y = 1, .subdivision = 4}), 300, 300, seed);
    const QuadResult r = quadrangulate(plate, {.objective = Objective::pairs, .algorithm = kLrs});
    ASSERT_TRUE(r.stats.maximum_certified);
    ASSERT_EQ(r.stats.triangles_left, 0u);
    EXPECT_GE(r.stats.matching.nodes_labelled, r.stats.matching.augmenting_paths);
    augmented += r.stats.matching.augmenting_paths > 0;
  }
  EXPECT_GT(augmented, 0);
}

TEST(Quadrangulate, KeepsAMeshOfQuadsAsItIs) {
  const PolygonMesh mesh =
      mesh_of({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}, {2, 1, 0}},
              {{0, 1, 2, 3}, {1, 4, 5, 2}});
  const QuadResult result = quadrangulate(mesh, {.all_quad = true});
  EXPECT_EQ(result.stats.triangles, 0u);
  EXPECT_EQ(result.stats.polygons_kept, 2u);
  EXPECT_EQ(result.mesh.corners, mesh.corners);
  EXPECT_EQ(check_quad_result(mesh, result, true, false), "");
}

// Three triangles on one edge: no pair crosses it.
TEST(Quadrangulate, NeverPairsAcrossANonManifoldEdge) {
  const PolygonMesh mesh = mesh_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}},
                                   {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
  const QuadResult result = quadrangulate(mesh);
  EXPECT_EQ(result.stats.pairs, 0u);
  EXPECT_EQ(result.stats.cuts.by_cause[int(CutCause::non_manifold)], 1u);
  expect_correct(mesh);
}

// A star of triangles whose maximum matching leaves some unpaired: the witness proves it.
TEST(Quadrangulate, CertifiesAMaximumThatIsNotPerfect) {
  // Triangle 0 in the middle, three triangles on its sides: only one of them can pair with it.
  const PolygonMesh mesh =
      mesh_of({{0, 0, 0}, {2, 0, 0}, {1, 2, 0}, {1, -1, 0}, {2.5, 1.5, 0}, {-0.5, 1.5, 0}},
              {{0, 1, 2}, {1, 0, 3}, {2, 1, 4}, {0, 2, 5}});
  const QuadResult result = quadrangulate(mesh, {.objective = Objective::pairs});
  EXPECT_EQ(result.stats.pairs, 1u);
  EXPECT_EQ(result.stats.triangles_left, 2u);
  EXPECT_EQ(result.tutte_set.size(), 1u);  // the middle triangle
  expect_correct(mesh);
  expect_correct(mesh, /*all_quad=*/true);
}

// Two cases the grouping and the numbering must survive (under UBSan too): a face whose corners
// are all one vertex has only loops, so the grouping of halfedges gets an empty slice; and in a
// mesh mostly of quads, the numbering of the pairable edges reads ahead over the quads'
// halfedges, which have no slot in the dual.
TEST(Quadrangulate, DegenerateFacesAndQuadsAroundTriangles) {
  expect_correct(mesh_of({{0, 0, 0}, {0, 1, 0}}, {{0, 0, 0, 0}}));
  expect_correct(mesh_of({{0, 0, 0}, {0, 1, 0}}, {{0, 0, 0, 0}}), /*all_quad=*/true);
  // A 6 x 6 grid of unit squares, all quads but the middle one, cut into two triangles.
  std::vector<std::array<double, 3>> positions;
  for (int y = 0; y <= 6; ++y)
    for (int x = 0; x <= 6; ++x) positions.push_back({double(x), double(y), 0});
  std::vector<std::vector<VertexId>> faces;
  for (VertexId y = 0; y < 6; ++y) {
    for (VertexId x = 0; x < 6; ++x) {
      const VertexId a = 7 * y + x, b = a + 1, c = a + 8, d = a + 7;
      if (x == 3 && y == 3) {
        faces.push_back({a, b, c});
        faces.push_back({a, c, d});
      } else {
        faces.push_back({a, b, c, d});
      }
    }
  }
  const PolygonMesh grid = mesh_of(positions, faces);
  const QuadResult result = quadrangulate(grid);
  EXPECT_EQ(result.stats.pairs, 1u);
  EXPECT_EQ(result.stats.polygons_kept, 35u);
  expect_correct(grid);
  expect_correct(grid, /*all_quad=*/true);
}

TEST(Quadrangulate, RefusesCornersOutOfRangeAndShortFaces) {
  PolygonMesh bad = mesh_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 7}});
  EXPECT_THROW(quadrangulate(bad), MeshError);
  bad = mesh_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1}});
  EXPECT_THROW(quadrangulate(bad), MeshError);
}

// A closed mesh takes the fast path: every triangle paired by every algorithm.
TEST(Quadrangulate, ClosedMeshesArePerfect) {
  const PolygonMesh mesh = random_closed_surface(2, 40, 200, 5);
  for (const PairingAlgorithm& algorithm : kAlgorithms) {
    const QuadResult result =
        quadrangulate(mesh, {.objective = Objective::pairs, .algorithm = algorithm});
    EXPECT_EQ(result.stats.triangles_left, 0u) << to_string(algorithm);
    EXPECT_EQ(result.stats.pairs, mesh.face_count() / 2);
  }
  expect_correct(mesh);
}

// Non-orientable closed surfaces: every graph algorithm pairs them perfectly (their dual is cubic
// and bridgeless); lrs, which needs an orientable manifold, hands them to auto and says so.
TEST(Quadrangulate, KleinBottleAndProjectivePlane) {
  for (const PolygonMesh& mesh : {klein_bottle(7, 9), projective_plane(2)}) {
    expect_correct(mesh);
    expect_correct(mesh, /*all_quad=*/true);
    for (const PairingAlgorithm& algorithm : kAlgorithms) {
      const QuadResult result =
          quadrangulate(mesh, {.objective = Objective::pairs, .algorithm = algorithm});
      EXPECT_EQ(result.stats.triangles_left, 0u) << to_string(algorithm);
      EXPECT_EQ(result.stats.inconsistent_edges > 0, true);
      if (std::holds_alternative<Lrs>(algorithm)) {
        EXPECT_EQ(result.stats.lrs_fallback_components, 1u);
        EXPECT_NE(result.stats.lrs_fallback_reason, "");
      }
    }
  }
  // The minimal projective plane has 10 triangles; every one is paired.
  EXPECT_EQ(quadrangulate(projective_plane(0), {.objective = Objective::pairs}).stats.pairs, 5u);
}

// A whole closed mesh whose pairable graph is its dual goes to lrs on that graph; one with a
// pinched vertex (a cylinder of 2 x 4 squares whose end circles are closed by cones with one apex,
// vertex 12) is refused there and paired by auto on the graph made again: the same quads as auto.
TEST(Quadrangulate, LrsGivesAPinchedClosedMeshToAuto) {
  std::vector<std::array<double, 3>> positions;
  for (VertexId row = 0; row < 3; ++row) {
    for (VertexId i = 0; i < 4; ++i) {
      positions.push_back({std::cos(i * M_PI / 2), std::sin(i * M_PI / 2), double(row)});
    }
  }
  positions.push_back({0, 0, 1});
  std::vector<std::vector<VertexId>> faces;
  for (VertexId row = 0; row < 2; ++row) {
    for (VertexId i = 0; i < 4; ++i) {
      const VertexId a = 4 * row + i, b = 4 * row + (i + 1) % 4, c = a + 4, d = b + 4;
      faces.push_back({a, b, d});
      faces.push_back({a, d, c});
    }
  }
  for (VertexId i = 0; i < 4; ++i) {
    faces.push_back({(i + 1) % 4, i, 12});
    faces.push_back({8 + i, 8 + (i + 1) % 4, 12});
  }
  const PolygonMesh pinched = mesh_of(positions, faces);
  const QuadResult lrs = quadrangulate(pinched, {.objective = Objective::pairs, .algorithm = kLrs});
  const QuadResult by_auto =
      quadrangulate(pinched, {.objective = Objective::pairs, .algorithm = Algorithm::automatic});
  EXPECT_EQ(lrs.stats.lrs_fallback_components, 1u);
  EXPECT_EQ(lrs.stats.lrs_fallback_reason,
            "pinched vertex 12 (its triangles form more than one fan)");
  EXPECT_EQ(lrs.stats.pairs, 12u);
  EXPECT_EQ(lrs.mesh.corners, by_auto.mesh.corners);
  EXPECT_EQ(lrs.sources, by_auto.sources);
  EXPECT_EQ(check_quad_result(pinched, lrs, false, true), "");
  // The consuming door without sources lets lrs free the corners once its triangulation has read
  // them: the pinch is refused before that, and auto pairs the corners as they were.
  const QuadResult consumed = quadrangulate(
      PolygonMesh(pinched), {.objective = Objective::pairs, .algorithm = kLrs, .sources = false});
  EXPECT_EQ(consumed.stats.lrs_fallback_components, 1u);
  EXPECT_EQ(consumed.mesh.corners, by_auto.mesh.corners);
  // Without the pinch (vertex 12 split into one apex per cone) lrs pairs it, with flips allowed.
  positions.push_back({0, 0, 1.5});
  for (VertexId i = 0; i < 4; ++i) faces[16 + 2 * i + 1][2] = 13;
  const PolygonMesh sphere = mesh_of(positions, faces);
  const QuadResult split =
      quadrangulate(sphere, {.objective = Objective::pairs, .algorithm = kLrs});
  EXPECT_EQ(split.stats.lrs_fallback_components, 0u);
  EXPECT_EQ(split.stats.pairs, 12u);
  EXPECT_EQ(split.stats.irreducible_vertices, 4u);
  EXPECT_EQ(check_quad_result(sphere, split, false, true), "");
}

// Each extra cut on two triangles that would otherwise pair: the square (0, 1, 2, 3) cut along
// its diagonal 0-2, folded by 90 degrees when vertex 3 is lifted.
TEST(Quadrangulate, ExtraCutsKeepTriangles) {
  const PolygonMesh flat =
      mesh_of({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}});
  const PolygonMesh folded =
      mesh_of({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0.5, 0.5, 1}}, {{0, 1, 2}, {0, 2, 3}});
  auto left = [](const PolygonMesh& mesh, const CutOptions& cuts, CutCause cause) {
    const QuadResult result = quadrangulate(mesh, {.cuts = cuts});
    EXPECT_EQ(result.stats.cuts.by_cause[int(cause)], result.stats.triangles_left / 2);
    EXPECT_EQ(check_quad_result(mesh, result, false, false, cuts), "");
    return result.stats.triangles_left;
  };
  EXPECT_EQ(left(flat, {}, CutCause::user), 0u);
  const std::array<VertexId, 2> diagonal[] = {{2, 0}};
  EXPECT_EQ(left(flat, {.user_edges = diagonal}, CutCause::user), 2u);
  EXPECT_EQ(left(flat, {.sharp_angle_degrees = 30}, CutCause::sharp), 0u);
  EXPECT_EQ(left(folded, {.sharp_angle_degrees = 30}, CutCause::sharp), 2u);
  EXPECT_EQ(left(folded, {.sharp_angle_degrees = 100}, CutCause::sharp), 0u);
  const std::uint32_t same_uv[] = {0, 1, 2, 0, 2, 3}, seam_uv[] = {0, 1, 2, 4, 2, 3};
  EXPECT_EQ(left(flat, {.corner_uv = same_uv}, CutCause::uv_seam), 0u);
  EXPECT_EQ(left(flat, {.corner_uv = seam_uv}, CutCause::uv_seam), 2u);
  EXPECT_EQ(left(flat, {.corner_normal = seam_uv}, CutCause::normal_seam), 2u);
  const std::uint32_t materials[] = {0, 1};
  EXPECT_EQ(left(flat, {.face_material = materials}, CutCause::material), 2u);
  EXPECT_EQ(left(flat, {.face_group = materials}, CutCause::group), 2u);
  EXPECT_EQ(left(flat, {.face_smoothing = materials}, CutCause::smoothing), 2u);
  const std::uint32_t wrong_size[] = {0};
  CutOptions wrong;
  wrong.face_material = wrong_size;
  EXPECT_THROW(quadrangulate(flat, {.cuts = wrong}), MeshError);
}

// Materials among up to three per face and up to four of the caller's edges (sides of random
// faces), drawn inside a property.
struct ChosenCuts {
  std::vector<std::uint32_t> material;
  std::vector<std::array<VertexId, 2>> user;
};
ChosenCuts random_chosen_cuts(const PolygonMesh& mesh) {
  const auto faces = static_cast<std::uint32_t>(mesh.face_count());
  ChosenCuts cuts;
  cuts.material = *rc::gen::container<std::vector<std::uint32_t>>(
      faces, rc::gen::inRange<std::uint32_t>(0, *rc::gen::inRange<std::uint32_t>(1, 4)));
  for (int k = *rc::gen::inRange(0, 5); k > 0; --k) {
    const FaceId f = *rc::gen::inRange<std::uint32_t>(0, faces);
    cuts.user.push_back({mesh.face(f)[0], mesh.face(f)[1]});
  }
  return cuts;
}

// Random seams, materials, user edges and a fold threshold on mixed meshes: no pair crosses a
// cut and the pairing is still the maximum of what is left.
RC_GTEST_PROP(Quadrangulate, NoPairCrossesACut, ()) {
  const auto seed = *rc::gen::inRange<std::uint64_t>(0, 1u << 30);
  const PolygonMesh mesh = random_mixed_mesh(seed, *rc::gen::inRange<std::uint32_t>(4, 300));
  const auto corners = static_cast<std::uint32_t>(mesh.corners.size());
  // UV ids: the vertex id, except at a few corners (seams); materials among three.
  std::vector<std::uint32_t> uv(mesh.corners.begin(), mesh.corners.end());
  for (std::uint32_t c : *rc::gen::container<std::vector<std::uint32_t>>(
           *rc::gen::inRange<std::size_t>(0, 6), rc::gen::inRange<std::uint32_t>(0, corners))) {
    uv[c] += corners;
  }
  const auto [material, user] = random_chosen_cuts(mesh);
  CutOptions cuts{.user_edges = user, .corner_uv = uv, .face_material = material};
  // Thresholds between whole degrees: generated grids fold by exact angles (60, 90, ...), where
  // two correct computations of the fold may round to either side of an equal threshold.
  if (*rc::gen::arbitrary<bool>()) cuts.sharp_angle_degrees = *rc::gen::inRange(10, 170) + 0.5;
  const Algorithm algorithm =
      *rc::gen::elementOf(std::vector<Algorithm>{Algorithm::ps, Algorithm::gw, Algorithm::sg});
  const QuadResult result =
      quadrangulate(mesh, {.objective = Objective::pairs, .algorithm = algorithm, .cuts = cuts});
  RC_ASSERT(result.stats.maximum_certified);
  const std::string problem = check_quad_result(mesh, result, false, false, cuts);
  RC_LOG() << problem;
  RC_ASSERT(problem.empty());
}

// The consuming front door moves the positions into the output instead of copying them; the
// answer, with --all-quad's new vertices and every attribute carried, is the copying one's.
RC_GTEST_PROP(Quadrangulate, ConsumingTheMeshGivesTheSameAnswer, ()) {
  const PolygonMesh mesh = *testing::meshes_with_attributes(testing::AttributeSet::all);
  const QuadOptions options{.all_quad = *rc::gen::arbitrary<bool>()};
  QuadResult copied;
  try {
    copied = quadrangulate(mesh, options);
  } catch (const MeshError&) {
    PolygonMesh consumed = mesh;
    RC_ASSERT_THROWS_AS(quadrangulate(std::move(consumed), options), MeshError);
    return;
  }
  PolygonMesh consumed = mesh;
  const QuadResult moved = quadrangulate(std::move(consumed), options);
  RC_ASSERT(moved.mesh.positions == copied.mesh.positions);
  RC_ASSERT(moved.mesh.corners == copied.mesh.corners);
  RC_ASSERT(moved.mesh.face_start == copied.mesh.face_start);
  RC_ASSERT(moved.sources == copied.sources);
  const MeshAttributes &a = moved.mesh.attributes, &b = copied.mesh.attributes;
  RC_ASSERT(a.corner_texcoord == b.corner_texcoord && a.texcoords == b.texcoords);
  RC_ASSERT(a.corner_normal == b.corner_normal && a.normals == b.normals);
  RC_ASSERT(a.face_material == b.face_material && a.face_smoothing == b.face_smoothing);
  RC_ASSERT(a.vertex_properties.size() == b.vertex_properties.size());
  for (std::size_t k = 0; k < a.vertex_properties.size(); ++k) {
    RC_ASSERT(a.vertex_properties[k].values == b.vertex_properties[k].values);
  }
}

// Without sources asked for, the same output mesh and stats, and no sources: on closed surfaces
// through lrs's whole-mesh path (whose consuming door frees the input's corners early) and on
// mixed meshes through the others, by either door.
RC_GTEST_PROP(Quadrangulate, WithoutSourcesTheSameMesh, ()) {
  const bool closed = *rc::gen::arbitrary<bool>();
  const PolygonMesh mesh = closed ? *testing::closed_triangulations_up_to(3)
                                  : random_mixed_mesh(*rc::gen::inRange<std::uint64_t>(0, 1u << 30),
                                                      *rc::gen::inRange<std::uint32_t>(4, 300));
  const PairingAlgorithm algorithm =
      *rc::gen::elementOf(std::vector<PairingAlgorithm>{kLrs, Algorithm::ps});
  const QuadOptions with{.objective = Objective::pairs, .algorithm = algorithm};
  QuadOptions without = with;
  without.sources = false;
  const QuadResult expected = quadrangulate(mesh, with);
  PolygonMesh consumed = mesh;
  const bool consume = *rc::gen::arbitrary<bool>();
  const QuadResult result =
      consume ? quadrangulate(std::move(consumed), without) : quadrangulate(mesh, without);
  RC_ASSERT(result.sources.empty());
  RC_ASSERT(result.mesh.positions == expected.mesh.positions);
  RC_ASSERT(result.mesh.corners == expected.mesh.corners);
  RC_ASSERT(result.mesh.face_start == expected.mesh.face_start);
  RC_ASSERT(result.stats.pairs == expected.stats.pairs);
  RC_ASSERT(result.stats.triangles_left == expected.stats.triangles_left);
  RC_ASSERT(result.stats.flipped_edges == expected.stats.flipped_edges);
  RC_ASSERT(result.stats.quality_median == expected.stats.quality_median);
  RC_ASSERT(result.stats.maximum_certified);
}

// Chosen cuts (materials, seams, the caller's edges, a shape threshold) refuse pairs but leave the
// surface as it is: a closed surface of genus g still reports genus g, as `petersen info`'s own
// count from the mesh does, even where the cuts split its pairable graph into pieces.
RC_GTEST_PROP(Quadrangulate, ChosenCutsKeepTheGenus, ()) {
  const auto genus = *rc::gen::inRange<std::uint32_t>(0, 5);
  const PolygonMesh mesh = *testing::closed_triangulations(genus);
  const auto [material, user] = random_chosen_cuts(mesh);
  QuadOptions options{.cuts = {.user_edges = user, .face_material = material}};
  if (*rc::gen::arbitrary<bool>()) options.max_corner_deviation = *rc::gen::inRange(10, 170) + 0.5;
  const QuadResult result = quadrangulate(mesh, options);
  RC_ASSERT(result.stats.genus == std::optional<std::int64_t>(genus));
  RC_ASSERT(result.stats.genus == inspect_mesh(mesh).genus);
}

// Texture coordinates are compared by value: two entries with the same coordinates make no seam;
// a seam cuts unless crossed; material names are compared as strings.
TEST(Quadrangulate, AttributeCutsCompareValues) {
  PolygonMesh mesh = mesh_of({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}});
  MeshAttributes& a = mesh.attributes;
  // Entry 3 repeats entry 0's value: corner 0 of face 1 holds the same coordinates as vertex 0's.
  a.texcoords = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {0, 1, 0}};
  a.corner_texcoord = {0, 1, 2, 3, 2, 4};
  a.material_names = {"steel", "steel"};
  a.face_material = {0, 1};
  QuadResult result = quadrangulate(mesh);
  EXPECT_EQ(result.stats.pairs, 1u);
  EXPECT_EQ(result.stats.cuts.total(), 4u);  // the four boundary edges
  EXPECT_EQ(check_quad_result(mesh, result, false, false), "");
  EXPECT_EQ(check_attributes_kept(mesh, result), "");
  // The quad (2, 3, 0, 1): its corners' coordinates are those of the triangles' corners.
  ASSERT_EQ(result.mesh.attributes.corner_texcoord.size(), 4u);
  const std::array<double, 3> expected[] = {{1, 1, 0}, {0, 1, 0}, {0, 0, 0}, {1, 0, 0}};
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(result.mesh.attributes.texcoords[result.mesh.attributes.corner_texcoord[k]],
              expected[k]);
  }
  EXPECT_EQ(result.mesh.attributes.material_names[result.mesh.attributes.face_material[0]],
            "steel");

  a.texcoords[3] = {0.5, 0, 0};  // now a seam at vertex 0
  result = quadrangulate(mesh);
  EXPECT_EQ(result.stats.pairs, 0u);
  EXPECT_EQ(result.stats.cuts.by_cause[int(CutCause::uv_seam)], 1u);
  EXPECT_EQ(check_quad_result(mesh, result, false, false), "");
  const CutCause cross_uv[] = {CutCause::uv_seam};
  result = quadrangulate(mesh, {.cross = {CutCause::uv_seam}});
  EXPECT_EQ(result.stats.pairs, 1u);
  EXPECT_EQ(check_quad_result(mesh, result, false, false, {}, cross_uv), "");
  EXPECT_EQ(check_attributes_kept(mesh, result), "");

  a.texcoords[3] = {0, 0, 0};
  a.material_names = {"steel", "glass"};
  result = quadrangulate(mesh);
  EXPECT_EQ(result.stats.cuts.by_cause[int(CutCause::material)], 1u);
  EXPECT_EQ(result.stats.triangles_left, 2u);
  // The caller's own ids win over the attributes'.
  const std::uint32_t one_material[] = {7, 7};
  result = quadrangulate(mesh, {.cuts = {.face_material = one_material}});
  EXPECT_EQ(result.stats.pairs, 1u);
  EXPECT_THROW(quadrangulate(mesh, {.cross = {CutCause::boundary}}), std::invalid_argument);
  EXPECT_THROW(quadrangulate(mesh, {.cross = {CutCause::shape}}), std::invalid_argument);
  a.face_material = {0, 5};  // no such name
  EXPECT_THROW(quadrangulate(mesh), MeshError);
}

// all_quad on a lone triangle: a midpoint on one of its sides (each is a minimum), with the
// side's corner values averaged, its vertex colour rounded, and the normal they share kept.
TEST(Quadrangulate, AllQuadInterpolatesAttributes) {
  PolygonMesh mesh = mesh_of({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}}, {{0, 1, 2}});
  MeshAttributes& a = mesh.attributes;
  a.texcoords = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  a.corner_texcoord = {0, 1, 2};
  a.normals = {{0, 0, 1}};
  a.corner_normal = {0, 0, 0};
  a.vertex_properties.push_back({"red", ScalarType::uint8, {}});
  a.vertex_properties[0].values = {0, 255, 10};
  a.face_smoothing = {3};
  const QuadResult result = quadrangulate(mesh, {.all_quad = true});
  ASSERT_EQ(result.mesh.face_count(), 1u);
  EXPECT_EQ(result.stats.added_vertices, 1u);
  EXPECT_TRUE(result.stats.all_quad_certified);
  const std::vector<VertexId> quad(result.mesh.face(0).begin(), result.mesh.face(0).end());
  ASSERT_EQ(quad.size(), 4u);
  const std::size_t m = std::find(quad.begin(), quad.end(), VertexId{3}) - quad.begin();
  ASSERT_LT(m, 4u);
  const VertexId before = quad[(m + 3) % 4], after = quad[(m + 1) % 4];
  EXPECT_EQ(after, (before + 1) % 3);  // the triangle's corners in order around the midpoint
  const MeshAttributes& b = result.mesh.attributes;
  std::array<double, 3> texcoord;
  for (int d = 0; d < 3; ++d) texcoord[d] = (a.texcoords[before][d] + a.texcoords[after][d]) / 2;
  EXPECT_EQ(b.texcoords[b.corner_texcoord[m]], texcoord);
  EXPECT_EQ(b.texcoords.size(), 4u);
  EXPECT_EQ(b.corner_normal, (std::pmr::vector<std::uint32_t>{0, 0, 0, 0}));
  const double red =
      (a.vertex_properties[0].values[before] + a.vertex_properties[0].values[after]) / 2;
  EXPECT_EQ(b.vertex_properties[0].values[3], std::round(red));
  EXPECT_EQ(b.face_smoothing[0], 3u);
  EXPECT_EQ(check_quad_result(mesh, result, true, false), "");
  EXPECT_EQ(check_attributes_kept(mesh, result), "");
  a.vertex_properties[0].values.pop_back();  // a column one short: refused, not read past
  EXPECT_THROW(quadrangulate(mesh, {.all_quad = true}), MeshError);
}

// A float PLY is written back as float: all_quad's new vertices and float properties are held
// as floats, so that the result is what the file holds (the midpoint of 1 and 1 + 2^-23 needs 25
// bits: rounded only on the way out, the file would differ from the result in memory).
TEST(Quadrangulate, AllQuadHoldsFloatPositionsAndPropertiesAsFloats) {
  const double one_up = 1 + std::ldexp(1.0, -23);
  PolygonMesh mesh = mesh_of({{1, 0, 0}, {one_up, 3, 0}, {0, 1, one_up}}, {{0, 1, 2}});
  mesh.attributes.position_type = ScalarType::float32;
  mesh.attributes.vertex_properties.push_back({"quality", ScalarType::float32, {}});
  mesh.attributes.vertex_properties[0].values = {1, one_up, 0.1f};
  const QuadResult result = quadrangulate(mesh, {.all_quad = true});
  ASSERT_GT(result.stats.added_vertices, 0u);
  for (const auto& p : result.mesh.positions) {
    for (double x : p) EXPECT_EQ(double(float(x)), x);
  }
  for (double x : result.mesh.attributes.vertex_properties[0].values) {
    EXPECT_EQ(double(float(x)), x);
  }
  EXPECT_EQ(result.mesh.attributes.position_type, ScalarType::float32);
  EXPECT_EQ(check_quad_result(mesh, result, true, false), "");
  EXPECT_EQ(check_attributes_kept(mesh, result), "");
}

// Random attributes for `mesh`, drawn inside a property; each kind present or not at random.
// Texture coordinates and normals follow the vertex, but a few corners get another value (a
// seam) and a few another entry of the same value (no seam); materials among names one of which
// is repeated, groups, objects (some faces without), smoothing groups, a face property, an 8-bit
// colour and a float per vertex.
MeshAttributes arbitrary_attributes(const PolygonMesh& mesh) {
  MeshAttributes a;
  const auto corners = static_cast<std::uint32_t>(mesh.corners.size());
  const auto faces = static_cast<std::uint32_t>(mesh.face_count());
  auto some_corners = [&] {
    return *rc::gen::container<std::vector<std::uint32_t>>(
        *rc::gen::inRange<std::size_t>(0, 8), rc::gen::inRange<std::uint32_t>(0, corners));
  };
  auto per_corner = [&](std::pmr::vector<std::array<double, 3>>& values,
                        std::pmr::vector<std::uint32_t>& index, bool unit) {
    if (!*rc::gen::arbitrary<bool>()) return;
    for (const auto& p : mesh.positions) {
      std::array<double, 3> x{p[0] * 0.5, p[1] * 0.25 + 1, unit ? p[2] + 3 : 0};
      if (unit) {
        const double length = std::hypot(x[0], x[1], x[2]);
        for (double& c : x) c /= length;
      }
      values.push_back(x);
    }
    index.assign(mesh.corners.begin(), mesh.corners.end());
    for (std::uint32_t c : some_corners()) {  // seams
      auto x = values[index[c]];
      x[0] += 1;
      values.push_back(x);
      index[c] = static_cast<std::uint32_t>(values.size() - 1);
    }
    for (std::uint32_t c : some_corners()) {  // equal values under other indices
      values.push_back(values[index[c]]);
      index[c] = static_cast<std::uint32_t>(values.size() - 1);
    }
    if (*rc::gen::inRange(0, 4) == 0)
      index[*rc::gen::inRange<std::uint32_t>(0, corners)] = kNoAttribute;
  };
  per_corner(a.texcoords, a.corner_texcoord, false);
  per_corner(a.normals, a.corner_normal, true);
  auto per_face = [&](std::pmr::vector<std::uint32_t>& ids, std::uint32_t choices, bool may_lack) {
    if (!*rc::gen::arbitrary<bool>()) return;
    const auto most = *rc::gen::inRange<std::uint32_t>(1, choices + 1);
    for (std::uint32_t f = 0; f < faces; ++f) {
      const auto id = *rc::gen::inRange<std::uint32_t>(0, most + may_lack);
      ids.push_back(id == most ? kNoAttribute : id);
    }
  };
  a.material_names = {"red", "green", "red"};
  per_face(a.face_material, 3, true);
  a.group_names = {"body", "lid"};
  per_face(a.face_group, 2, false);
  a.object_names = {"teapot"};
  per_face(a.face_object, 1, true);
  per_face(a.face_smoothing, 3, false);
  if (*rc::gen::arbitrary<bool>()) {
    a.face_properties.push_back({"flags", ScalarType::uint8, {}});
    a.face_properties.push_back({"weight", ScalarType::float32, {}});
    for (std::uint32_t f = 0; f < faces; ++f) {
      a.face_properties[0].values.push_back(*rc::gen::inRange(0, 2));
      a.face_properties[1].values.push_back(*rc::gen::inRange(0, 2) * 0.5);
    }
  }
  if (*rc::gen::arbitrary<bool>()) {
    a.vertex_properties.push_back({"red", ScalarType::uint8, {}});
    a.vertex_properties.push_back({"confidence", ScalarType::float64, {}});
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      a.vertex_properties[0].values.push_back(*rc::gen::inRange(0, 256));
      a.vertex_properties[1].values.push_back(*rc::gen::inRange(0, 1000) / 7.0);
    }
  }
  if (*rc::gen::arbitrary<bool>()) a.material_libraries = {"scene.mtl"};
  return a;
}

// Random seams, materials, groups, objects, smoothing groups and properties on closed, open and
// mixed meshes, some crossed: no pair crosses a cut left on (judged from the values), the pairing
// is the maximum of what is left, and every corner, face and vertex keeps its values (all_quad's
// new ones interpolated).
RC_GTEST_PROP(Quadrangulate, AttributesCutAndSurvive, ()) {
  PolygonMesh mesh =
      *rc::gen::oneOf(testing::mixed_meshes(), testing::closed_triangulations_up_to(2));
  mesh.attributes = arbitrary_attributes(mesh);
  const MeshAttributes& a = mesh.attributes;
  std::vector<CutCause> cross;
  for (CutCause cause :
       {CutCause::uv_seam, CutCause::normal_seam, CutCause::material, CutCause::group,
        CutCause::object, CutCause::smoothing, CutCause::face_property}) {
    if (*rc::gen::inRange(0, 4) == 0) cross.push_back(cause);
  }
  const Objective objective =
      *rc::gen::element(Objective::quads, Objective::pairs, Objective::quality);
  // The algorithm is the pairs objective's choice: the others refuse any but automatic.
  const PairingAlgorithm algorithm = objective == Objective::pairs
                                         ? *rc::gen::elementOf(std::vector<PairingAlgorithm>(
                                               std::begin(kAlgorithms), std::end(kAlgorithms)))
                                         : PairingAlgorithm{Algorithm::automatic};
  const bool all_quad = *rc::gen::arbitrary<bool>();
  const QuadOptions options{
      .objective = objective, .algorithm = algorithm, .all_quad = all_quad, .cross = cross};
  QuadResult result;
  try {
    result = quadrangulate(mesh, options);
  } catch (const MeshError& e) {
    RC_ASSERT(all_quad);
    RC_ASSERT(std::string(e.what()).find("--all-quad") != std::string::npos);
    RC_TAG("all-quad refused");
    return;
  }
  const bool per_face = a.has_corner_attributes() || a.has_face_attributes();
  RC_CLASSIFY(result.stats.cuts.by_cause[int(CutCause::uv_seam)] > 0, "uv seams");
  RC_CLASSIFY(result.stats.cuts.by_cause[int(CutCause::material)] > 0, "material borders");
  RC_CLASSIFY(result.stats.added_vertices > 0, "split");
  RC_ASSERT(result.stats.maximum_certified || objective == Objective::quads);
  if (std::holds_alternative<Lrs>(algorithm) && per_face)
    RC_ASSERT(result.stats.flipped_edges == 0u);
  std::string problem = check_quad_result(mesh, result, options);
  if (problem.empty()) problem = check_attributes_kept(mesh, result);
  RC_LOG() << problem;
  RC_ASSERT(problem.empty());
}

// The generators' mixed meshes: closed or open, polygons, fins, pinches, flips, components.
RC_GTEST_PROP(Quadrangulate, MaximumAndCertifiedOnMixedMeshes, ()) {
  const PolygonMesh mesh = *testing::mixed_meshes();
  const auto seed = *rc::gen::inRange<std::uint64_t>(0, 1u << 30);
  const Objective objective =
      *rc::gen::element(Objective::quads, Objective::pairs, Objective::quality);
  const PairingAlgorithm algorithm = objective == Objective::pairs
                                         ? *rc::gen::elementOf(std::vector<PairingAlgorithm>(
                                               std::begin(kAlgorithms), std::end(kAlgorithms)))
                                         : PairingAlgorithm{Algorithm::automatic};
  const bool all_quad = *rc::gen::arbitrary<bool>();
  const QuadOptions options{
      .objective = objective, .algorithm = algorithm, .seed = seed, .all_quad = all_quad};
  QuadResult result;
  try {
    result = quadrangulate(mesh, options);
  } catch (const MeshError& e) {
    RC_ASSERT(all_quad);
    RC_ASSERT(std::string(e.what()).find("--all-quad") != std::string::npos);
    RC_TAG("all-quad refused");
    return;
  }
  RC_CLASSIFY(result.stats.polygons_kept > 0, "polygons");
  RC_CLASSIFY(result.stats.cuts.by_cause[int(CutCause::non_manifold)] > 0, "non-manifold");
  RC_CLASSIFY(result.stats.added_vertices > 0, "split");
  RC_ASSERT(result.stats.optimality_certified == (objective != Objective::pairs));
  const std::string problem = check_quad_result(mesh, result, options);
  RC_LOG() << problem;
  RC_ASSERT(problem.empty());
  // The summary's initial pairing: what the greedy passes left, each augmenting path pairing two
  // of them (auto, ps and sg: their paths are the only step after the initial pairing).
  const Algorithm* graph = std::get_if<Algorithm>(&algorithm);
  if (graph &&
      (*graph == Algorithm::automatic || *graph == Algorithm::ps || *graph == Algorithm::sg) &&
      objective == Objective::pairs) {
    RC_ASSERT(result.stats.matching.unpaired_after_initial ==
              result.stats.triangles_left + 2 * result.stats.matching.augmenting_paths);
  }
}

}  // namespace
// Threads split the grouping into vertex slices and the quads' measure into blocks: the answer
// (faces, sources, witness) and every count and quality figure are those of one thread.
RC_GTEST_PROP(Quadrangulate, ThreadsDoNotChangeTheAnswer, ()) {
  const PolygonMesh mesh = *testing::mixed_meshes();
  const std::uint32_t threads = *rc::gen::inRange<std::uint32_t>(2, 6);
  const bool all_quad = *rc::gen::arbitrary<bool>();
  const Objective objective = *rc::gen::element(Objective::pairs, Objective::quality);
  QuadOptions options{.objective = objective, .all_quad = all_quad};
  QuadResult one, many;
  try {
    one = quadrangulate(mesh, options);
  } catch (const MeshError&) {
    RC_ASSERT(all_quad);
    options.threads = threads;
    RC_ASSERT_THROWS_AS(quadrangulate(mesh, options), MeshError);
    return;
  }
  options.threads = threads;
  many = quadrangulate(mesh, options);
  RC_ASSERT(many.mesh.corners == one.mesh.corners);
  RC_ASSERT(many.mesh.face_start == one.mesh.face_start);
  RC_ASSERT(many.sources == one.sources);
  RC_ASSERT(many.tutte_set == one.tutte_set);
  const QuadStats &a = one.stats, &b = many.stats;
  RC_ASSERT(b.pairs == a.pairs && b.triangles_left == a.triangles_left);
  RC_ASSERT(b.mesh_edges == a.mesh_edges && b.cuts.by_cause == a.cuts.by_cause);
  RC_ASSERT(b.inconsistent_edges == a.inconsistent_edges && b.components == a.components);
  RC_ASSERT(b.euler_characteristic == a.euler_characteristic && b.genus == a.genus);
  RC_ASSERT(b.quality_median == a.quality_median && b.quality_p95 == a.quality_p95);
  RC_ASSERT(b.nonconvex_quads == a.nonconvex_quads && b.objective_total == a.objective_total);
  if (objective == Objective::quality && !all_quad) {
    // The certified optimum is the quads' own summed cost, each rounded to the solver's units.
    double sum = 0;
    for (FaceId o = 0; o < many.mesh.face_count(); ++o) {
      if (many.sources[o][1] == kNoFace) continue;
      const auto c = many.mesh.face(o);
      const auto& p = many.mesh.positions;
      sum += quad_corner_deviation(p[c[0]], p[c[1]], p[c[2]], p[c[3]]);
    }
    RC_ASSERT(std::abs(b.objective_total - sum) <= double(b.pairs + 1) / kDefaultCostScale);
  }
}

}  // namespace petersen
