// all_quad on real meshes: every shared mesh (the invalid ones too) with its attributes, plus
// generated quad-dominant and flat-shaded textured ones, with all_quad alone and combined with
// Objective::quality, max_corner_deviation 30, sharp_angle 30, kept edges and the attribute cuts
// (none crossed, all crossed); every output checked by check_quad_result with the run's options
// and by check_attributes_kept.

#include <gtest/gtest.h>

#include <cctype>
#include <string>
#include <vector>

#include "petersen/generators/mesh_class_generators.hpp"
#include "petersen/generators/polygon_generators.hpp"
#include "petersen/generators/surface_generators.hpp"
#include "petersen/io/read_mesh.hpp"
#include "petersen/quadrangulate/quadrangulate.hpp"
#include "result_check.hpp"
#include "shared_meshes.hpp"

namespace petersen {
namespace {

// The independent checks sort every edge and run LEMON (and Boost below 20k triangles) once per
// option set: the meshes up to this size run, seven option sets each.
#ifdef PETERSEN_SANITIZE
constexpr std::uint32_t kMaxTriangles = 8000;
#else
constexpr std::uint32_t kMaxTriangles = 50000;
#endif

// A generated mesh by name, or nothing.
std::optional<PolygonMesh> generated(const std::string& name) {
  if (name == "generated/quad-dominant") {
    return quad_dominant_grid(
        {.nx = 60, .ny = 60, .triangle_squares = 3, .pentagons = 40, .hexagons = 20, .seed = 3});
  }
  if (name == "generated/quad-dominant-torus") {
    return quad_dominant_grid({.nx = 60,
                               .ny = 20,
                               .torus = true,
                               .triangle_squares = 4,
                               .pentagons = 25,
                               .hexagons = 10,
                               .seed = 4});
  }
  if (name == "generated/flat-shaded-holed") {
    return flat_shaded(punch_holes(random_closed_surface(2, 2000, 2000, 5), 6, 6),
                       {.materials = 3, .seed = 7});
  }
  if (name == "generated/flat-shaded-quad-dominant") {
    return flat_shaded(
        quad_dominant_grid({.nx = 40, .ny = 40, .pentagons = 20, .hexagons = 10, .seed = 8}),
        {.materials = 2, .seed = 9});
  }
  return std::nullopt;
}

// The meshes of ../shared (skipped without it), apart from the generated ones, so that their tests
// are named SharedMeshes/... and ctest reports them apart (tests/CMakeLists.txt).
std::vector<std::string> shared_meshes() {
  std::vector<std::string> names;
  for (const auto& mesh : testing::shared_meshes_up_to(kMaxTriangles)) names.push_back(mesh.file);
  for (const char* invalid : {"invalid/beetle.obj.gz", "invalid/cow.obj.gz",
                              "invalid/stanford-bunny.obj.gz", "invalid/teapot.obj.gz"}) {
    names.push_back(invalid);
  }
  return names;
}

std::vector<std::string> generated_meshes() {
  return {"generated/quad-dominant", "generated/quad-dominant-torus", "generated/flat-shaded-holed",
          "generated/flat-shaded-quad-dominant"};
}

// Every 97th side of the faces: kept edges spread over the mesh.
std::vector<std::array<VertexId, 2>> spread_edges(const PolygonMesh& mesh) {
  std::vector<std::array<VertexId, 2>> edges;
  for (FaceId f = 0; f < mesh.face_count(); f += 97) {
    const auto c = mesh.face(f);
    edges.push_back({c[0], c[1]});
  }
  return edges;
}

class AllQuadOnEveryMesh : public ::testing::TestWithParam<std::string> {};

TEST_P(AllQuadOnEveryMesh, EveryOptionSetChecked) {
  const std::string& name = GetParam();
  std::optional<PolygonMesh> mesh = generated(name);
  if (!mesh) {
    const auto dir = testing::shared_mesh_dir();
    if (!dir) GTEST_SKIP() << "no ../shared/meshes (set PETERSEN_SHARED_MESHES)";
    mesh = read_mesh(*dir + "/" + name);
  }
  const auto kept = spread_edges(*mesh);
  std::vector<std::pair<std::string, QuadOptions>> sets;
  const QuadOptions all_quad{.all_quad = true};
  sets.push_back({"all-quad", all_quad});
  QuadOptions o = all_quad;
  o.objective = Objective::quality;
  sets.push_back({"quality", o});
  o.objective = Objective::pairs;
  sets.push_back({"pairs", o});
  o = all_quad;
  o.max_corner_deviation = 30.0;
  sets.push_back({"max_corner_deviation 30", o});
  o = all_quad;
  o.cuts.sharp_angle_degrees = 30.0;
  sets.push_back({"sharp_angle 30", o});
  o = all_quad;
  o.cuts.user_edges = kept;
  sets.push_back({"kept edges", o});
  if (!mesh->attributes.empty()) {
    o = all_quad;
    o.cross = attribute_causes();
    sets.push_back({"cross all", o});
  }
  if (!mesh->all_triangles()) {
    o = all_quad;
    o.keep_polygons = true;
    sets.push_back({"keep_polygons", o});
  }
  for (const auto& [set, options] : sets) {
    SCOPED_TRACE(set);
    QuadResult result;
    try {
      result = quadrangulate(*mesh, options);
    } catch (const MeshError& e) {
      // Only keep_polygons may leave no all-quad mesh (a component's parity).
      EXPECT_TRUE(options.keep_polygons) << e.what();
      continue;
    }
    EXPECT_TRUE(result.stats.maximum_certified || options.objective == Objective::quads);
    EXPECT_EQ(testing::check_quad_result(*mesh, result, options), "");
    EXPECT_EQ(testing::check_attributes_kept(*mesh, result), "");
  }
}

std::string param_name(const ::testing::TestParamInfo<std::string>& info) {
  return testing::test_name_of_file(info.param);
}
INSTANTIATE_TEST_SUITE_P(SharedMeshes, AllQuadOnEveryMesh, ::testing::ValuesIn(shared_meshes()),
                         param_name);
INSTANTIATE_TEST_SUITE_P(Generated, AllQuadOnEveryMesh, ::testing::ValuesIn(generated_meshes()),
                         param_name);

}  // namespace
}  // namespace petersen
