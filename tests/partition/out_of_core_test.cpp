// The out-of-core conversion on small meshes with tiny memory limits, so that they are cut into
// many parts; the output read back by the ordinary reader and checked on its own: every face a
// quad or a left triangle, every input triangle used exactly once, each quad's two triangles
// sharing its diagonal.

#include "petersen/partition/out_of_core.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>

#include "petersen/dualize/quad_quality.hpp"
#include "petersen/generators/mesh_class_generators.hpp"
#include "petersen/generators/polygon_generators.hpp"
#include "petersen/generators/streamed_plate.hpp"
#include "petersen/io/file_error.hpp"
#include "petersen/io/ply_stream.hpp"
#include "petersen/io/read_mesh.hpp"
#include "petersen/partition/partition.hpp"
#include "petersen/quadrangulate/quadrangulate.hpp"
#include "petersen/quadrangulate/stages.hpp"
#include "petersen/quadrangulate/triangle_prices.hpp"
#include "quad_mesh_check.hpp"
#include "shared_meshes.hpp"

namespace petersen {
namespace {

namespace fs = std::filesystem;

struct TempDir {
  fs::path path;
  TempDir() {
    path = fs::temp_directory_path() /
           ("petersen-ooc-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
  std::string operator/(const std::string& name) const { return (path / name).string(); }
};

void write_triangles(const std::string& path, std::uint64_t vertices,
                     const std::vector<VertexId>& corners) {
  PlyStreamWriter out(path,
                      "element vertex " + std::to_string(vertices) +
                          "\nproperty float x\nproperty float y\nproperty float z\n",
                      corners.size() / 3);
  for (std::uint64_t v = 0; v < vertices; ++v) {
    const float xyz[3] = {float(v), float(v % 7), 0.5f};
    out.write_vertex_records({reinterpret_cast<const char*>(xyz), sizeof xyz});
  }
  for (std::size_t i = 0; i < corners.size(); i += 3) {
    out.write_triangle(corners[i], corners[i + 1], corners[i + 2]);
  }
  out.commit();
}

// Checks the output against the input on its own (pairing_problem); returns its quads.
std::uint64_t checked_quads(const std::vector<VertexId>& input, const PolygonMesh& output,
                            std::uint64_t vertices) {
  EXPECT_EQ(output.positions.size(), vertices);
  PolygonMesh source;
  source.corners.assign(input.begin(), input.end());
  std::uint64_t quads = 0;
  EXPECT_EQ(testing::pairing_problem(source, output, quads), "");
  return quads;
}

// The plate's triangles, written to `path` as binary PLY.
std::vector<VertexId> write_plate(const StreamedPlate& plate, const std::string& path) {
  std::vector<VertexId> corners;
  for_each_plate_triangle(plate, [&](VertexId a, VertexId b, VertexId c) {
    corners.insert(corners.end(), {a, b, c});
  });
  write_triangles(path, plate.vertices(), corners);
  return corners;
}

TEST(OutOfCore, ClosedPlateInManyPartsIsPerfect) {
  const TempDir dir;
  const StreamedPlate plate = streamed_plate_of_size(60000);
  const std::vector<VertexId> corners = write_plate(plate, dir / "plate.ply");
  for (std::uint64_t limit : {std::uint64_t{200} << 10, std::uint64_t{1} << 20}) {
    const OutOfCoreStats stats =
        quad_out_of_core(dir / "plate.ply", dir / "quads.ply", {.memory_limit = limit});
    EXPECT_GE(stats.parts, 10u) << "limit " << limit;
    EXPECT_TRUE(stats.closed);
    EXPECT_TRUE(stats.perfect_certified);
    EXPECT_EQ(stats.triangles_left, 0u);
    const PolygonMesh out = read_mesh(dir / "quads.ply");
    EXPECT_EQ(checked_quads(corners, out, plate.vertices()), plate.triangles() / 2);
    EXPECT_EQ(stats.pairs, plate.triangles() / 2);
  }
  // Nothing left beside the output.
  std::uint64_t files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir.path)) ++files;
  EXPECT_EQ(files, 2u);
}

// Whatever the part size, a closed mesh comes out perfect: a window with an odd number of free
// triangles leaves one, which must be moved across the part to its far border to be carried
// forward (PartPairingOptions::move_budget).
TEST(OutOfCore, ClosedPlateIsPerfectForEveryPartSize) {
  const TempDir dir;
  const StreamedPlate plate = streamed_plate_of_size(100000);
  const std::vector<VertexId> corners = write_plate(plate, dir / "plate.ply");
  for (std::uint64_t part : {997u, 2048u, 3001u, 6250u, 7919u, 12345u, 20011u, 33333u, 49999u}) {
    const OutOfCoreStats stats =
        quad_out_of_core(dir / "plate.ply", dir / "quads.ply", {.part_triangles = part});
    EXPECT_TRUE(stats.perfect_certified) << "parts of " << part;
    EXPECT_EQ(stats.triangles_left, 0u) << "parts of " << part;
  }
  const PolygonMesh out = read_mesh(dir / "quads.ply");
  EXPECT_EQ(checked_quads(corners, out, plate.vertices()), plate.triangles() / 2);
}

TEST(OutOfCore, OpenMeshMatchesTheInMemoryMaximum) {
  const TempDir dir;
  const PolygonMesh mesh = punch_holes(open_grid(60, 50), 20, 3);
  const std::vector<VertexId> corners(mesh.corners.begin(), mesh.corners.end());
  write_triangles(dir / "open.ply", mesh.positions.size(), corners);
  const OutOfCoreStats stats =
      quad_out_of_core(dir / "open.ply", dir / "quads.ply", {.part_triangles = 500});
  EXPECT_GE(stats.parts, 8u);
  EXPECT_FALSE(stats.closed);
  EXPECT_FALSE(stats.perfect_certified);
  const PolygonMesh out = read_mesh(dir / "quads.ply");
  const std::uint64_t quads = checked_quads(corners, out, mesh.positions.size());
  EXPECT_EQ(quads, stats.pairs);
  QuadOptions options;
  options.objective = Objective::pairs;  // the maximum, which the parts are compared with
  options.sources = false;
  EXPECT_EQ(stats.pairs, quadrangulate(mesh, options).stats.pairs);
}

// `mesh` (triangles) written as binary PLY with its positions as floats; returns the mesh as the
// file holds it, read back by the ordinary reader: the in-memory run it is compared with.
PolygonMesh write_mesh_ply(const PolygonMesh& mesh, const std::string& path) {
  PlyStreamWriter out(path,
                      "element vertex " + std::to_string(mesh.positions.size()) +
                          "\nproperty float x\nproperty float y\nproperty float z\n",
                      mesh.face_count());
  for (const auto& p : mesh.positions) {
    const float xyz[3] = {float(p[0]), float(p[1]), float(p[2])};
    out.write_vertex_records({reinterpret_cast<const char*>(xyz), sizeof xyz});
  }
  for (std::size_t i = 0; i < mesh.corners.size(); i += 3) {
    out.write_triangle(mesh.corners[i], mesh.corners[i + 1], mesh.corners[i + 2]);
  }
  out.commit();
  return read_mesh(path);
}

// The total of a pairing as Objective::quads counts it, from the output file and its source:
// each quad's worst corner plus the price of each triangle left, as the whole source's pairable
// graph under `options` prices it (triangle_prices).
double total_of(const PolygonMesh& output, const PolygonMesh& source, const QuadOptions& options) {
  QuadStats stats;
  const PairableMesh pairable = pairable_mesh(source, options, stats);
  const std::pmr::vector<Cost> prices = triangle_prices(
      pairable.graph.node_count, pairable.graph.edge_ends, scale_costs(pairable.costs),
      std::llround(options.triangle_cost * kDefaultCostScale));
  std::map<std::array<VertexId, 3>, double> price_of;  // by the triangle's sorted corners
  auto key = [](const PolygonMesh& mesh, FaceId f) {
    const std::span<const VertexId> face = mesh.face(f);
    std::array<VertexId, 3> c = {face[0], face[1], face[2]};
    std::sort(c.begin(), c.end());
    return c;
  };
  for (NodeId v = 0; v < pairable.graph.node_count; ++v) {
    price_of[key(source, pairable.graph.face_of(v))] = double(prices[v]) / kDefaultCostScale;
  }
  double total = 0;
  for (double cost : quad_costs(output)) total += cost;
  for (FaceId f = 0; f < output.face_count(); ++f) {
    if (output.arity(f) != 3) continue;
    const auto it = price_of.find(key(output, f));
    total += it == price_of.end() ? options.triangle_cost : it->second;
  }
  return total;
}

QuadOptions quads_at(double triangle_cost, std::optional<double> sharp_angle = {}) {
  QuadOptions options;
  options.triangle_cost = triangle_cost;
  options.cuts.sharp_angle_degrees = sharp_angle;
  return options;
}

// The meshes the cost objectives are checked on: an open jittered grid with holes and a closed
// jittered torus, as their PLY files hold them.
std::vector<std::pair<std::string, PolygonMesh>> cost_meshes(const TempDir& dir) {
  std::vector<std::pair<std::string, PolygonMesh>> meshes;
  const PolygonMesh open = punch_holes(jittered_grid({.nx = 60, .ny = 40, .jitter = 0.2}), 25, 3);
  meshes.emplace_back(dir / "open.ply", write_mesh_ply(open, dir / "open.ply"));
  const PolygonMesh torus = jittered_grid({.nx = 90, .ny = 24, .jitter = 0.2, .torus = true});
  meshes.emplace_back(dir / "torus.ply", write_mesh_ply(torus, dir / "torus.ply"));
  return meshes;
}

// The default objective out of core: a valid pairing whose total is at least the in-memory
// certified optimum, which is at least the stitched lower bound; one part gives the optimum.
TEST(OutOfCore, QuadsObjectiveIsBoundedByTheInMemoryOptimum) {
  const TempDir dir;
  for (const auto& [path, mesh] : cost_meshes(dir)) {
    QuadOptions options;
    options.sources = false;
    const QuadResult memory = quadrangulate(mesh, options);
    ASSERT_TRUE(memory.stats.optimality_certified);
    const double optimum = memory.stats.objective_total;
    const std::vector<VertexId> corners(mesh.corners.begin(), mesh.corners.end());
    for (std::uint64_t part : {1000u, 2999u, 100000u}) {
      const OutOfCoreStats stats =
          quad_out_of_core(path, dir / "quads.ply",
                           {.costs = {.objective = Objective::quads}, .part_triangles = part});
      const PolygonMesh out = read_mesh(dir / "quads.ply");
      EXPECT_EQ(checked_quads(corners, out, mesh.positions.size()), stats.pairs);
      EXPECT_TRUE(stats.costs_certified && stats.lower_bound_valid);
      EXPECT_NEAR(total_of(out, mesh, quads_at(kDefaultTriangleCost)), stats.objective_total, 1e-3);
      EXPECT_LE(stats.lower_bound, optimum + 1e-9) << path << " parts of " << part;
      EXPECT_LE(optimum, stats.objective_total + 1e-9) << path << " parts of " << part;
      if (stats.parts == 1) {
        EXPECT_TRUE(stats.optimality_certified);
        EXPECT_DOUBLE_EQ(stats.objective_total, optimum);
        EXPECT_EQ(stats.pairs, memory.stats.pairs);
      } else {
        EXPECT_GE(stats.parts, 2u);
        EXPECT_GT(stats.cut_adjacencies, 0u);
      }
    }
  }
}

// The cost objectives' output does not depend on the threads: the same bytes from one and two.
TEST(OutOfCore, CostObjectivesDoNotDependOnThreads) {
  const TempDir dir;
  const auto meshes = cost_meshes(dir);
  const std::string& path = meshes.front().first;
  for (Objective objective : {Objective::quads, Objective::quality}) {
    std::string bytes[2];
    for (std::uint32_t threads : {1u, 2u}) {
      quad_out_of_core(
          path, dir / "quads.ply",
          {.costs = {.objective = objective}, .part_triangles = 1000, .threads = threads});
      std::ifstream in(dir / "quads.ply", std::ios::binary);
      bytes[threads - 1].assign(std::istreambuf_iterator<char>(in), {});
    }
    EXPECT_FALSE(bytes[0].empty());
    EXPECT_EQ(bytes[0], bytes[1]) << to_string(objective);
  }
}

// The seam step measures its candidate edges in batches and solves its graph's components (the
// bands of the cuts between parts) in batches of whole components: an edge and a component at a
// time give the answer of all at once. Parts of 25 rows of the grid, so that the bands of two
// cuts (16 steps, about 8 rows deep) are apart.
TEST(OutOfCore, SeamBatchesGiveTheAnswerOfOneBatch) {
  const PolygonMesh mesh = jittered_grid({.nx = 60, .ny = 120, .jitter = 0.2});
  const std::vector<VertexId> corners(mesh.corners.begin(), mesh.corners.end());
  std::vector<std::array<double, 3>> positions;
  for (const VertexId c : corners) positions.push_back(mesh.positions[c]);
  for (const Objective objective : {Objective::quads, Objective::quality}) {
    const PartCosts costs{.objective = objective};
    std::vector<SeamFace> seam;
    std::vector<OpenEdge> open;
    const std::uint64_t n = corners.size() / 3, part = 3000;
    for (std::uint64_t first = 0; first < n; first += part) {
      const std::uint64_t count = std::min(part, n - first);
      const PartPairing p =
          pair_part({.first_face = static_cast<FaceId>(first),
                     .corners = std::span(corners).subspan(3 * first, 3 * count),
                     .corner_positions = std::span(positions).subspan(3 * first, 3 * count)},
                    {.costs = costs});
      seam.insert(seam.end(), p.seam.begin(), p.seam.end());
      open.insert(open.end(), p.open_edges.begin(), p.open_edges.end());
    }
    const CutPairing cut = pair_open_edges(std::move(open));
    ASSERT_GT(cut.adjacencies.size(), 0u);
    const SeamResult whole = pair_seams({seam, cut.adjacencies}, costs, 1);
    const SeamResult each =
        pair_seams({.faces = seam, .adjacencies = cut.adjacencies, .batch_faces = 0}, costs, 1);
    EXPECT_TRUE(whole.certified && each.certified);
    EXPECT_GT(whole.seam_graph_faces, 0u);
    EXPECT_EQ(whole.objective_change, each.objective_change) << to_string(objective);
    EXPECT_EQ(whole.partner, each.partner) << to_string(objective);
    EXPECT_EQ(whole.pairs_across, each.pairs_across) << to_string(objective);
  }
}

// What the seam step is handed comes from outside (a cluster's tasks, Python): a price or a dual
// that would overflow its sums is refused naming the face, and a part whose band is too thin
// for the seams to price its faces from both sides is refused before any work.
TEST(OutOfCore, SeamStepRefusesValuesItCannotSum) {
  const PolygonMesh mesh = jittered_grid({.nx = 12, .ny = 12, .jitter = 0.2});
  const std::vector<VertexId> corners(mesh.corners.begin(), mesh.corners.end());
  std::vector<std::array<double, 3>> positions;
  for (const VertexId c : corners) positions.push_back(mesh.positions[c]);
  const PartTriangles part{.corners = std::span(corners).first(150),
                           .corner_positions = std::span(positions).first(150)};
  EXPECT_THROW(pair_part(part, {.costs = {.objective = Objective::quads}, .band_radius = 2}),
               std::invalid_argument);
  const PartPairing p = pair_part(part, {.costs = {.objective = Objective::quads}});
  ASSERT_FALSE(p.seam.empty());
  const PartCosts costs{.objective = Objective::quads};
  EXPECT_NO_THROW(pair_seams({p.seam, {}}, costs));
  for (int field = 0; field < 3; ++field) {
    std::vector<SeamFace> seam = p.seam;
    if (field == 0) seam.back().price = kMaxCost + 1;
    if (field == 1) seam.back().dual[1] = std::numeric_limits<std::int64_t>::min();
    if (field == 2) seam.back().stay_dual = std::numeric_limits<std::int64_t>::max();
    try {
      pair_seams({seam, {}}, costs);
      ADD_FAILURE() << "field " << field << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("face " + std::to_string(seam.back().face)),
                std::string::npos)
          << e.what();
    }
  }
}

// --objective quality out of core: each part's cheapest maximum and the seams'; on the closed
// torus every triangle is paired, and the cost is never below the in-memory optimum.
TEST(OutOfCore, QualityObjectivePairsEachPartsMaximum) {
  const TempDir dir;
  for (const auto& [path, mesh] : cost_meshes(dir)) {
    QuadOptions options;
    options.objective = Objective::quality;
    options.sources = false;
    const QuadResult memory = quadrangulate(mesh, options);
    const OutOfCoreStats stats =
        quad_out_of_core(path, dir / "quads.ply",
                         {.costs = {.objective = Objective::quality}, .part_triangles = 1500});
    const std::vector<VertexId> corners(mesh.corners.begin(), mesh.corners.end());
    const PolygonMesh out = read_mesh(dir / "quads.ply");
    EXPECT_EQ(checked_quads(corners, out, mesh.positions.size()), stats.pairs);
    EXPECT_FALSE(stats.lower_bound_valid);
    EXPECT_FALSE(stats.optimality_certified);
    EXPECT_LE(stats.pairs, memory.stats.pairs);
    if (stats.closed) {
      EXPECT_EQ(stats.triangles_left, 0u);
      EXPECT_TRUE(stats.perfect_certified);
      EXPECT_LE(memory.stats.objective_total, stats.objective_total + 1e-9);
    }
  }
}

// The shared meshes of triangles in five parts or more: a valid pairing whose stitched lower bound
// is at most the in-memory certified optimum, which is at most its total.
TEST(OutOfCore, SharedMeshesQuadsObjectiveIsBoundedByTheInMemoryOptimum) {
  const auto shared = testing::shared_mesh_dir();
  if (!shared) GTEST_SKIP() << "no ../shared/meshes (set PETERSEN_SHARED_MESHES)";
  const TempDir dir;
  for (const char* file : {"bunny.off.gz", "3holes.off.gz", "fandisk.obj.gz", "fertility.off.gz",
                           "armadillo.obj.gz", "rocker-arm.obj.gz"}) {
    PolygonMesh source = read_mesh(*shared + "/" + file);
    if (!source.all_triangles()) continue;
    source.attributes = {};
    const PolygonMesh mesh = write_mesh_ply(source, dir / "mesh.ply");
    QuadOptions options;
    options.sources = false;
    const QuadResult memory = quadrangulate(mesh, options);
    ASSERT_TRUE(memory.stats.optimality_certified) << file;
    const OutOfCoreStats stats = quad_out_of_core(
        dir / "mesh.ply", dir / "quads.ply",
        {.costs = {.objective = Objective::quads}, .part_triangles = mesh.face_count() / 5 + 1});
    EXPECT_GE(stats.parts, 5u) << file;
    const std::vector<VertexId> corners(mesh.corners.begin(), mesh.corners.end());
    const PolygonMesh out = read_mesh(dir / "quads.ply");
    EXPECT_EQ(checked_quads(corners, out, mesh.positions.size()), stats.pairs) << file;
    // Each quad's cost is rounded to the solver's units (scale_costs): 2^-17 degrees at most.
    EXPECT_NEAR(total_of(out, mesh, quads_at(kDefaultTriangleCost)), stats.objective_total,
                1e-5 * double(stats.pairs) + 1e-6)
        << file;
    EXPECT_LE(stats.lower_bound, memory.stats.objective_total + 1e-9) << file;
    EXPECT_LE(memory.stats.objective_total, stats.objective_total + 1e-9) << file;
  }
}

// A model's own triangles beside the cuts: chamfered cubes exported triangulated (by either
// diagonal), in parts that cut through them. Their corners may stay for less than the price
// (triangle_prices), which a part beside a cut cannot see whole; the seams price them from both
// sides, so every cube comes back as in memory: its 18 quads, its 8 corners left.
TEST(OutOfCore, OwnTrianglesBesideTheCutsArePricedAsInMemory) {
  const TempDir dir;
  constexpr std::uint32_t kCubes = 40;
  std::vector<PolygonMesh> cubes;
  for (std::uint32_t i = 0; i < kCubes; ++i) {
    PolygonMesh cube = split_quads(chamfered_cube(), i % 2 == 0);
    for (auto& p : cube.positions) p[0] += 3.0 * i;
    cubes.push_back(std::move(cube));
  }
  const PolygonMesh mesh = write_mesh_ply(concatenate(cubes), dir / "cubes.ply");
  QuadOptions options;
  options.sources = false;
  const QuadResult memory = quadrangulate(mesh, options);
  ASSERT_TRUE(memory.stats.optimality_certified);
  ASSERT_EQ(memory.stats.triangles_left, 8 * kCubes);
  for (std::uint64_t part : {30u, 97u, 500u}) {
    const OutOfCoreStats stats =
        quad_out_of_core(dir / "cubes.ply", dir / "quads.ply",
                         {.costs = {.objective = Objective::quads}, .part_triangles = part});
    EXPECT_GT(stats.parts, 1u);
    const PolygonMesh out = read_mesh(dir / "quads.ply");
    EXPECT_EQ(stats.triangles_left, 8 * kCubes) << "parts of " << part;
    EXPECT_NEAR(stats.objective_total, memory.stats.objective_total, 1e-6) << "parts of " << part;
    EXPECT_NEAR(total_of(out, mesh, quads_at(kDefaultTriangleCost)), stats.objective_total, 1e-3);
    EXPECT_TRUE(stats.costs_certified && stats.lower_bound_valid);
    EXPECT_LE(stats.lower_bound, memory.stats.objective_total + 1e-9) << "parts of " << part;
  }
}

// The threshold and the sharp angle are honoured inside the parts and across the cuts: no quad
// of the output is above the threshold, and the sharp angle gives what it gives in memory.
TEST(OutOfCore, ThresholdAndSharpAngleAreHonoured) {
  const TempDir dir;
  for (const auto& [path, mesh] : cost_meshes(dir)) {
    const OutOfCoreStats stats =
        quad_out_of_core(path, dir / "quads.ply",
                         {.costs = {.objective = Objective::quads, .max_corner_deviation = 10.0},
                          .part_triangles = 1000});
    const PolygonMesh out = read_mesh(dir / "quads.ply");
    for (double cost : quad_costs(out)) EXPECT_LE(cost, 10.0 + 1e-9);
    EXPECT_GT(stats.pairs, 0u);
    QuadOptions options;
    options.sources = false;
    options.triangle_cost = 20.0;
    options.cuts.sharp_angle_degrees = 5.0;
    const QuadResult memory = quadrangulate(mesh, options);
    const OutOfCoreStats sharp = quad_out_of_core(path, dir / "quads.ply",
                                                  {.costs = {.objective = Objective::quads,
                                                             .triangle_cost = 20.0,
                                                             .sharp_angle_degrees = 5.0},
                                                   .part_triangles = 1000});
    EXPECT_LE(sharp.lower_bound, memory.stats.objective_total + 1e-9);
    EXPECT_LE(memory.stats.objective_total, sharp.objective_total + 1e-9);
    EXPECT_NEAR(total_of(read_mesh(dir / "quads.ply"), mesh, quads_at(20.0, 5.0)),
                sharp.objective_total, 1e-3);
  }
}

// --all-quad out of core (all_quad.hpp), on the open grids with holes and the closed torus in
// many parts, by every objective (and the threshold): the output passes the independent check
// of an all-quad file, and the stats count what the file holds.
TEST(OutOfCore, AllQuadInManyPartsPassesTheIndependentCheck) {
  const TempDir dir;
  auto meshes = cost_meshes(dir);
  meshes.emplace_back(dir / "lattice.ply",
                      write_mesh_ply(punch_holes(open_grid(60, 50), 20, 3), dir / "lattice.ply"));
  for (const auto& [path, mesh] : meshes) {
    for (const Objective objective : {Objective::pairs, Objective::quads, Objective::quality}) {
      for (const bool threshold : {false, true}) {
        if (threshold && objective == Objective::pairs) continue;
        PartCosts costs{.objective = objective};
        if (threshold) costs.max_corner_deviation = 30;
        const OutOfCoreStats stats = quad_out_of_core(
            path, dir / "aq.ply", {.costs = costs, .part_triangles = 700, .all_quad = true});
        const std::string what =
            path + " " + std::string(to_string(objective)) + (threshold ? " threshold 30" : "");
        EXPECT_GE(stats.all_quad_parts, 4u) << what;
        EXPECT_TRUE(stats.all_quad_parts_certified) << what;
        const PolygonMesh out = read_mesh(dir / "aq.ply");
        EXPECT_EQ(out.face_count(), stats.faces_out) << what;
        EXPECT_EQ(out.positions.size(), mesh.positions.size() + stats.added_vertices) << what;
        EXPECT_EQ(stats.added_vertices, stats.split_edges + stats.centre_vertices) << what;
        testing::AllQuadFileCounts counts;
        EXPECT_EQ(testing::all_quad_file_problem(mesh, out, counts), "") << what;
        EXPECT_EQ(counts.quads, out.face_count()) << what;
        EXPECT_EQ(counts.midpoints, stats.split_edges) << what;
        EXPECT_EQ(counts.centres, stats.centre_vertices) << what;
        if (objective == Objective::pairs) {
          EXPECT_EQ(stats.centre_vertices, 0u) << what;
        }
      }
    }
  }
}

// The midpoints part by part against the certified whole-mesh minimum for the same pairing: the
// out-of-core pairing without --all-quad (quality under a 30 degree threshold, which leaves
// triangles), read back, and the whole output's minimum T-join (plan_piece_splits on it as one
// piece, the boundary its sink). Equal in one part; never below it in many (the excess is
// printed).
TEST(OutOfCore, AllQuadMidpointsAgainstTheInMemoryMinimum) {
  const TempDir dir;
  auto meshes = cost_meshes(dir);
  meshes.emplace_back(dir / "lattice.ply",
                      write_mesh_ply(punch_holes(open_grid(60, 50), 20, 3), dir / "lattice.ply"));
  for (const auto& [path, mesh] : meshes) {
    for (std::uint64_t part : {100000u, 1500u, 600u}) {
      const OutOfCoreOptions options{
          .costs = {.objective = Objective::quality, .max_corner_deviation = 30},
          .part_triangles = part};
      quad_out_of_core(path, dir / "paired.ply", options);
      OutOfCoreOptions all_quad = options;
      all_quad.all_quad = true;
      const OutOfCoreStats stats = quad_out_of_core(path, dir / "aq.ply", all_quad);
      const PieceSplits whole = plan_piece_splits(read_mesh(dir / "paired.ply"), {});
      ASSERT_TRUE(whole.certified);
      const std::uint64_t minimum = whole.edges.size();
      std::printf(
          "%s, %llu parts, %llu triangles left: %llu midpoints part by part, whole-mesh "
          "minimum %llu\n",
          path.c_str(), (unsigned long long)stats.all_quad_parts,
          (unsigned long long)stats.triangles_left, (unsigned long long)stats.split_edges,
          (unsigned long long)minimum);
      EXPECT_GT(minimum, 0u) << path;
      EXPECT_GE(stats.split_edges, minimum) << path;
      if (stats.all_quad_parts == 1) {
        EXPECT_EQ(stats.split_edges, minimum) << path;
      }
    }
  }
}

TEST(OutOfCore, RefusesWhatItCannotStreamNamingTheFileAndFace) {
  const TempDir dir;
  {
    std::ofstream ascii(dir / "ascii.ply");
    ascii << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
             "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
             "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  }
  EXPECT_THROW(quad_out_of_core(dir / "ascii.ply", dir / "out.ply"), FileError);
  write_triangles(dir / "range.ply", 3, {0, 1, 7});
  try {
    quad_out_of_core(dir / "range.ply", dir / "out.ply");
    FAIL() << "no error";
  } catch (const FileError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("range.ply"), std::string::npos) << what;
    EXPECT_NE(what.find("face 0"), std::string::npos) << what;
  }
  EXPECT_FALSE(fs::exists(dir / "out.ply"));
}

}  // namespace
}  // namespace petersen
