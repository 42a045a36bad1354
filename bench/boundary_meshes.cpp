// Meshes with boundary, polygons and non-manifold edges through the front door: pairs,
// triangles left by the certified maximum against a plain greedy pass over the same pairable
// graph, and what --all-quad adds. Usage: petersen_boundary_bench [mesh files...]; without files,
// the shared invalid/ meshes (when ../shared/meshes is present) and generated ones.

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "memory_pool.hpp"
#include "petersen/dualize/pairable_graph.hpp"
#include "petersen/generators/polygon_generators.hpp"
#include "petersen/io/read_mesh.hpp"
#include "petersen/quadrangulate/quadrangulate.hpp"

namespace {

using namespace petersen;

// What one greedy pass in edge order leaves: the pairing a user gets without augmenting paths.
std::uint64_t greedy_left(const PolygonMesh& mesh) {
  const PairableGraph graph = build_pairable_graph(mesh);
  std::vector<std::uint8_t> matched(graph.node_count, 0);
  std::uint64_t pairs = 0;
  for (EdgeId e = 0; e < graph.edge_count(); ++e) {
    const NodeId a = graph.edge_ends[2 * e], b = graph.edge_ends[2 * e + 1];
    if (matched[a] || matched[b]) continue;
    matched[a] = matched[b] = 1;
    ++pairs;
  }
  return graph.node_count - 2 * pairs;
}

void run(const std::string& name, const PolygonMesh& mesh) {
  const QuadResult best =
      quadrangulate(mesh, {.objective = Objective::pairs, .algorithm = Algorithm::automatic});
  const QuadStats& s = best.stats;
  std::string all_quad = "refused";
  double all_quad_seconds = 0;
  std::uint64_t added = 0;
  try {
    const QuadResult result = quadrangulate(
        mesh, {.objective = Objective::pairs, .algorithm = Algorithm::automatic, .all_quad = true});
    added = result.stats.added_vertices;
    all_quad_seconds = result.stats.total_seconds;
    all_quad = std::to_string(added);
  } catch (const MeshError& e) {
    std::fprintf(stderr, "%s: %s\n", name.c_str(), e.what());
  }
  std::printf("| %s | %llu | %llu | %llu | %llu | %llu | %llu | %s | %s | %.3f | %.3f |\n",
              name.c_str(), (unsigned long long)s.triangles, (unsigned long long)s.polygons_kept,
              (unsigned long long)s.cuts.total(), (unsigned long long)greedy_left(mesh),
              (unsigned long long)s.pairs, (unsigned long long)s.triangles_left,
              s.maximum_certified ? "yes" : "no", all_quad.c_str(), s.total_seconds,
              all_quad_seconds);
}

}  // namespace

int main(int argc, char** argv) {
  petersen::bench::install_memory_pool();
  std::printf(
      "| mesh | triangles | polygons | cut edges | greedy left | pairs | left (maximum) | "
      "certified | all-quad added vertices | time s | all-quad time s |\n"
      "|---|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|\n");
  if (argc > 1) {
    for (int i = 1; i < argc; ++i) run(argv[i], read_mesh(argv[i]));
    return 0;
  }
  const std::string dir = std::string(PETERSEN_SHARED_MESHES) + "/invalid/";
  for (const char* file :
       {"beetle.obj.gz", "cow.obj.gz", "stanford-bunny.obj.gz", "teapot.obj.gz"}) {
    if (std::filesystem::exists(dir + file)) run(file, read_mesh(dir + file));
  }
  run("open grid 1000x1000, 200 holes", punch_holes(open_grid(1000, 1000), 200, 1));
  run("open grid 1000x1000, 200 holes, 20000 polygons",
      merge_into_polygons(punch_holes(open_grid(1000, 1000), 200, 1), 20000, 2));
  run("Klein bottle 500x500", klein_bottle(500, 500));
  run("projective plane, 6 subdivisions", projective_plane(6));
  run("mixed mesh, seed 1, size 200000", random_mixed_mesh(1, 200000));
  return 0;
}
