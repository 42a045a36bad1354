// The composition matrix: every class of mesh (testing/mesh_classes.hpp) with every option set
// of the front door, alone and combined at random, each output checked by the independent checks
// (check_quad_result with the run's options, check_attributes_kept) and, on these small meshes,
// all_quad's minimum by the brute force (split_minimum.hpp). A refusal of all_quad must be a true
// one: the brute force finds no set of splits for the same pairing.

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <array>
#include <set>
#include <string>
#include <vector>

#include "petersen/generators/polygon_generators.hpp"
#include "petersen/quadrangulate/quadrangulate.hpp"
#include "petersen/testing/mesh_classes.hpp"
#include "result_check.hpp"
#include "split_minimum.hpp"

namespace petersen {
namespace {

using testing::MeshClass;

// Meshes of up to this many faces: the brute force and the peers stay quick under ASan.
#ifdef PETERSEN_SANITIZE
constexpr std::uint32_t kMostFaces = 30;
#else
constexpr std::uint32_t kMostFaces = 60;
#endif

// The caller's kept edges: a few sides of the mesh's faces, drawn by RapidCheck.
std::vector<std::array<VertexId, 2>> some_edges(const PolygonMesh& mesh) {
  std::vector<std::array<VertexId, 2>> edges;
  const auto count = *rc::gen::inRange<std::uint32_t>(1, 4);
  for (std::uint32_t k = 0; k < count; ++k) {
    const auto f = *rc::gen::inRange<FaceId>(0, static_cast<FaceId>(mesh.face_count()));
    const auto c = mesh.face(f);
    const auto side = *rc::gen::inRange<std::size_t>(0, c.size());
    edges.push_back({c[side], c[(side + 1) % c.size()]});
  }
  return edges;
}

// The named option sets of the matrix; `kept` holds the storage of the kept edges' span.
std::vector<std::pair<std::string, QuadOptions>> option_sets(
    const std::vector<std::array<VertexId, 2>>& kept) {
  std::vector<std::pair<std::string, QuadOptions>> sets;
  for (bool all_quad : {false, true}) {
    const std::string tag = all_quad ? "all-quad " : "";
    const QuadOptions base{.all_quad = all_quad};
    sets.push_back({tag + "plain", base});
    QuadOptions o = base;
    o.objective = Objective::quality;
    sets.push_back({tag + "quality", o});
    o.objective = Objective::pairs;
    sets.push_back({tag + "pairs", o});
    o = base;
    o.max_corner_deviation = 30.0;
    sets.push_back({tag + "max_corner_deviation 30", o});
    o = base;
    o.cuts.sharp_angle_degrees = 30.0;
    sets.push_back({tag + "sharp_angle 30", o});
    o = base;
    o.cuts.user_edges = kept;
    sets.push_back({tag + "kept edges", o});
    o = base;
    o.cross = attribute_causes();
    sets.push_back({tag + "cross all", o});
    if (all_quad) {
      o = base;
      o.keep_polygons = true;
      sets.push_back({tag + "keep_polygons", o});
    }
    for (const PairingAlgorithm& a : std::vector<PairingAlgorithm>{
             Algorithm::sg, Algorithm::ps, Algorithm::ds, Algorithm::gw, kLrs}) {
      o = base;
      o.objective = Objective::pairs;
      o.algorithm = a;
      sets.push_back({tag + std::string(to_string(a)), o});
    }
  }
  return sets;
}

// Every option drawn at random: one combination of the whole matrix.
QuadOptions random_options(const std::vector<std::array<VertexId, 2>>& kept) {
  QuadOptions o;
  o.objective = *rc::gen::element(Objective::quads, Objective::pairs, Objective::quality);
  if (o.objective == Objective::pairs) {
    o.algorithm = *rc::gen::elementOf(std::vector<PairingAlgorithm>{
        Algorithm::automatic, Algorithm::sg, Algorithm::ps, Algorithm::ds, Algorithm::gw, kLrs});
  }
  o.all_quad = *rc::gen::arbitrary<bool>();
  o.keep_polygons = *rc::gen::arbitrary<bool>();
  if (*rc::gen::arbitrary<bool>()) o.max_corner_deviation = 30.0;
  if (*rc::gen::arbitrary<bool>()) o.cuts.sharp_angle_degrees = 30.0;
  if (*rc::gen::arbitrary<bool>()) o.cuts.user_edges = kept;
  for (CutCause cause : attribute_causes())
    if (*rc::gen::arbitrary<bool>()) o.cross.push_back(cause);
  return o;
}

// One run checked; the problem, or empty.
std::string run_and_check(const PolygonMesh& mesh, const QuadOptions& options) {
  const bool lrs = std::holds_alternative<Lrs>(options.algorithm);
  QuadResult result;
  try {
    result = quadrangulate(mesh, options);
  } catch (const MeshError& e) {
    if (!options.all_quad) return std::string("refused: ") + e.what();
    // Only a pairing that no splits can make all quads may be refused.
    QuadOptions plain = options;
    plain.all_quad = false;
    const QuadResult pairing = quadrangulate(mesh, plain);
    const auto minimum = testing::fewest_splits(mesh, pairing, options.keep_polygons, lrs);
    if (minimum.status != testing::SplitMinimum::Status::infeasible)
      return std::string("all_quad refused a pairing that has splits: ") + e.what();
    return {};
  }
  if (!result.stats.maximum_certified && options.objective != Objective::quads)
    return "maximum not certified";
  if (options.objective != Objective::pairs && !result.stats.optimality_certified)
    return "optimality not certified";
  if (std::string problem = testing::check_quad_result(mesh, result, options); !problem.empty())
    return problem;
  if (std::string problem = testing::check_attributes_kept(mesh, result); !problem.empty())
    return problem;
  if (!options.all_quad) return {};
  const auto minimum = testing::fewest_splits(mesh, result, options.keep_polygons, lrs);
  using Status = testing::SplitMinimum::Status;
  if (minimum.status == Status::infeasible) return "an all-quad output of a pairing with no splits";
  if (minimum.status == Status::found) {
    RC_TAG("minimum judged");
    const QuadStats& s = result.stats;
    if (s.split_edges < minimum.splits) return "fewer splits than the brute force's minimum";
    if (s.all_quad_certified && s.added_vertices_minimum != minimum.splits) {
      return "added_vertices_minimum " + std::to_string(s.added_vertices_minimum) +
             ", brute force " + std::to_string(minimum.splits) + " (" +
             std::to_string(minimum.splits_without_non_manifold) +
             " without splitting an edge of three or more faces)";
    }
  }
  return {};
}

void check_class(MeshClass c) {
  const PolygonMesh mesh = *testing::meshes_of_class(c, kMostFaces);
  const auto kept = some_edges(mesh);
  for (const auto& [name, options] : option_sets(kept)) {
    const std::string problem = run_and_check(mesh, options);
    if (!problem.empty()) RC_FAIL(name + ": " + problem);
  }
  const QuadOptions combined = random_options(kept);
  const std::string problem = run_and_check(mesh, combined);
  if (!problem.empty()) RC_FAIL("a random combination: " + problem);
}

RC_GTEST_PROP(Composition, Closed, ()) {
  check_class(MeshClass::closed);
}
RC_GTEST_PROP(Composition, OpenWithHoles, ()) {
  check_class(MeshClass::open_with_holes);
}
RC_GTEST_PROP(Composition, QuadDominant, ()) {
  check_class(MeshClass::quad_dominant);
}
RC_GTEST_PROP(Composition, NonManifold, ()) {
  check_class(MeshClass::non_manifold);
}
RC_GTEST_PROP(Composition, NonOrientable, ()) {
  check_class(MeshClass::non_orientable);
}
RC_GTEST_PROP(Composition, SeveralComponents, ()) {
  check_class(MeshClass::components);
}
RC_GTEST_PROP(Composition, FlatShadedTextured, ()) {
  check_class(MeshClass::textured);
}

// Faces repeating a vertex.
std::uint64_t repeating_faces(const PolygonMesh& mesh) {
  std::uint64_t count = 0;
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    const auto c = mesh.face(f);
    count += std::set<VertexId>(c.begin(), c.end()).size() != c.size();
  }
  return count;
}

// A mesh as files with degenerate faces hold it (a game asset's index buffer): a few faces of a
// mesh of another class collapsed in place, a corner replaced by the one before it ({a, b, c}
// becomes {a, a, c}), and with `slivers` a few degenerate triangles {a, b, a} added along sides
// of the mesh. No attributes: the added faces would have none.
PolygonMesh with_degenerate_faces(MeshClass base, std::uint64_t seed, bool slivers) {
  PolygonMesh mesh = testing::mesh_of_class(base, seed, kMostFaces);
  mesh.attributes = {};
  SeededRandom rng(seed + 1);
  const auto faces = static_cast<FaceId>(mesh.face_count());
  for (std::uint32_t k = 1 + rng.below(3); k > 0; --k) {
    const FaceId f = static_cast<FaceId>(rng.below(faces));
    const std::size_t first = mesh.face(f).data() - mesh.corners.data(), n = mesh.arity(f);
    const std::size_t corner = rng.below(n);
    mesh.corners[first + corner] = mesh.corners[first + (corner + n - 1) % n];
  }
  for (std::uint32_t k = slivers ? rng.below(3) : 0; k > 0; --k) {
    const auto c = mesh.face(static_cast<FaceId>(rng.below(faces)));
    const std::array<VertexId, 3> sliver{c[0], c[1], c[0]};
    mesh.add_face(sliver);
  }
  return mesh;
}

// The degenerate-face class through the whole matrix: a refusal must be a true one (run_and_check).
RC_GTEST_PROP(Composition, DegenerateFaces, ()) {
  const MeshClass base =
      *rc::gen::element(MeshClass::closed, MeshClass::open_with_holes, MeshClass::quad_dominant,
                        MeshClass::non_manifold, MeshClass::non_orientable);
  const PolygonMesh mesh = with_degenerate_faces(base, *rc::gen::arbitrary<std::uint64_t>(), true);
  RC_TAG(repeating_faces(mesh) > 0 ? "degenerate" : "collapsed back to itself");
  const auto kept = some_edges(mesh);
  for (const auto& [name, options] : option_sets(kept)) {
    const std::string problem = run_and_check(mesh, options);
    if (!problem.empty()) RC_FAIL(name + ": " + problem);
  }
}

// The modes files are converted in, on closed triangle meshes with degenerate faces: every one
// converts (a collapsed face leaves its neighbours a boundary, so parity never refuses), every
// other face a quad, the checks pass and every degenerate face is counted.
TEST(Composition, DegenerateFacesConvertInEveryMode) {
  std::vector<std::pair<std::string, QuadOptions>> modes;
  modes.push_back({"pairs", {}});
  modes.push_back({"all-quad", {.all_quad = true}});
  modes.push_back({"quality", {.objective = Objective::quality}});
  modes.push_back({"quality all-quad", {.objective = Objective::quality, .all_quad = true}});
  modes.push_back({"max-corner-deviation 40 all-quad", {.all_quad = true}});
  modes.back().second.max_corner_deviation = 40.0;
  modes.push_back({"sharp-angle 30 all-quad", {.all_quad = true}});
  modes.back().second.cuts.sharp_angle_degrees = 30.0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    // Only collapsed faces: an added sliver walls in its side, which may leave a part odd.
    const PolygonMesh mesh = with_degenerate_faces(MeshClass::closed, seed, false);
    const std::uint64_t degenerate = repeating_faces(mesh);
    ASSERT_GT(degenerate, 0u);
    for (const auto& [name, options] : modes) {
      SCOPED_TRACE("seed " + std::to_string(seed) + ", " + name);
      const QuadResult result = quadrangulate(mesh, options);
      EXPECT_EQ(testing::check_quad_result(mesh, result, options), "");
      if (!options.all_quad) continue;
      EXPECT_EQ(result.stats.degenerate_faces, degenerate);
      std::uint64_t not_quads = 0;
      for (FaceId f = 0; f < result.mesh.face_count(); ++f) not_quads += result.mesh.arity(f) != 4;
      EXPECT_EQ(not_quads, degenerate);
    }
  }
}

// A result that is a pairing only: one output face per source (its first face's corners: the
// brute force reads the sources) and the sources.
QuadResult pairing(const PolygonMesh& mesh, std::vector<std::array<FaceId, 2>> sources) {
  QuadResult result;
  result.mesh.positions = mesh.positions;
  for (const auto& [f, g] : sources) result.mesh.add_face(mesh.face(f));
  result.sources.assign(sources.begin(), sources.end());
  return result;
}

// The brute force itself on pairings whose minimum is known by hand.
TEST(SplitMinimum, KnownMinima) {
  using Status = testing::SplitMinimum::Status;
  // Two triangles left apart: one split of their shared edge gives both a fourth side.
  PolygonMesh two;
  two.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  two.add_face(std::array<VertexId, 3>{0, 1, 2});
  two.add_face(std::array<VertexId, 3>{1, 3, 2});
  const QuadResult apart = pairing(two, {{0, kNoFace}, {1, kNoFace}});
  auto minimum = testing::fewest_splits(two, apart, false, false);
  ASSERT_EQ(minimum.status, Status::found);
  EXPECT_EQ(minimum.splits, 1u);
  // Paired, nothing is odd.
  PolygonMesh quad;
  quad.positions = two.positions;
  quad.add_face(std::array<VertexId, 4>{1, 3, 2, 0});
  const QuadResult paired = pairing(quad, {{0, 1}});
  minimum = testing::fewest_splits(two, paired, false, false);
  ASSERT_EQ(minimum.status, Status::found);
  EXPECT_EQ(minimum.splits, 0u);
  // A triangle walled in by three quads: a split of its side makes that quad odd, which then
  // splits a boundary edge: 2. With the quads kept, no side of the triangle may be split.
  PolygonMesh walled;
  walled.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0},  {-1, -1, 0}, {3, -1, 0},
                      {3, 1, 0}, {1, 3, 0}, {-1, 3, 0}, {-1, 1, 0}};
  walled.add_face(std::array<VertexId, 3>{0, 1, 2});
  walled.add_face(std::array<VertexId, 4>{1, 0, 3, 4});
  walled.add_face(std::array<VertexId, 4>{2, 1, 5, 6});
  walled.add_face(std::array<VertexId, 4>{0, 2, 7, 8});
  const QuadResult alone =
      pairing(walled, {{0, kNoFace}, {1, kNoFace}, {2, kNoFace}, {3, kNoFace}});
  minimum = testing::fewest_splits(walled, alone, false, false);
  ASSERT_EQ(minimum.status, Status::found);
  EXPECT_EQ(minimum.splits, 2u);
  EXPECT_EQ(testing::fewest_splits(walled, alone, true, false).status, Status::infeasible);
  // A fin: three triangles on one edge, one split of it fixes all three; with a fourth face
  // (a pair's quad elsewhere) nothing changes.
  PolygonMesh fin;
  fin.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  fin.add_face(std::array<VertexId, 3>{0, 1, 2});
  fin.add_face(std::array<VertexId, 3>{1, 0, 3});
  fin.add_face(std::array<VertexId, 3>{0, 1, 4});
  const QuadResult three = pairing(fin, {{0, kNoFace}, {1, kNoFace}, {2, kNoFace}});
  minimum = testing::fewest_splits(fin, three, false, false);
  ASSERT_EQ(minimum.status, Status::found);
  EXPECT_EQ(minimum.splits, 1u);
  // A 2 x 2 grid with a fin on edge 1-5 (to vertex 7), paired into three quads: the triangles
  // 1-2-5, 4-8-7 and the fin are odd. Their boundary edges take 3 splits; splitting the fin's
  // edge fixes two triangles at once and makes the quad 1-5-8-4 odd, which edge 4-8 fixes with
  // the third triangle: 2.
  PolygonMesh grid = open_grid(2, 2);
  grid.add_face(std::array<VertexId, 3>{1, 5, 7});
  const QuadResult finned =
      pairing(grid, {{0, 1}, {2, kNoFace}, {3, 6}, {4, 5}, {7, kNoFace}, {8, kNoFace}});
  minimum = testing::fewest_splits(grid, finned, false, false);
  ASSERT_EQ(minimum.status, Status::found);
  EXPECT_EQ(minimum.splits, 2u);
  EXPECT_EQ(minimum.splits_without_non_manifold, 3u);
}

}  // namespace
}  // namespace petersen
