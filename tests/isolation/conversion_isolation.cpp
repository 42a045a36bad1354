// Two conversions on two threads, each handed its own memory resource: each result lives on its
// own resource, the two results are the same, and when they are gone each resource has every byte
// back. The library keeps no memory and no state between calls; the resources the caller passes
// are all it allocates its results from. A plain main, as core_isolation.cpp.

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory_resource>
#include <optional>
#include <string>
#include <thread>

#include "counting_resource.hpp"
#include "petersen/generators/surface_generators.hpp"
#include "petersen/quadrangulate/quadrangulate.hpp"

namespace {

int failures = 0;
void expect(bool ok, const char* what) {
  std::printf("%s: %s\n", ok ? "ok" : "FAILED", what);
  failures += !ok;
}

bool same_mesh(const petersen::PolygonMesh& a, const petersen::PolygonMesh& b) {
  return std::equal(a.positions.begin(), a.positions.end(), b.positions.begin(),
                    b.positions.end()) &&
         std::equal(a.corners.begin(), a.corners.end(), b.corners.begin(), b.corners.end()) &&
         std::equal(a.face_start.begin(), a.face_start.end(), b.face_start.begin(),
                    b.face_start.end());
}

}  // namespace

int main() {
  using petersen::testing::CountingResource;
  // A closed plate with holes, by each objective.
  const petersen::PolygonMesh mesh = petersen::voxel_plate({3, 2, 6, true});
  // What the conversions allocate without being handed a resource (scratch not threaded through)
  // goes to the default resource: counted, to show it is the smaller part.
  CountingResource fallback;
  std::pmr::set_default_resource(&fallback);
  for (petersen::Objective objective :
       {petersen::Objective::quads, petersen::Objective::pairs, petersen::Objective::quality}) {
    CountingResource first, second;
    {
      std::optional<petersen::QuadResult> a, b;
      std::thread ta(
          [&] { a = petersen::quadrangulate(mesh, {.objective = objective, .memory = &first}); });
      std::thread tb(
          [&] { b = petersen::quadrangulate(mesh, {.objective = objective, .memory = &second}); });
      ta.join();
      tb.join();
      std::printf(
          "%s: %zu triangles, %llu pairs; %zu and %zu bytes allocated from the resources, %zu "
          "from the default one\n",
          std::string(petersen::to_string(objective)).c_str(), mesh.face_count(),
          (unsigned long long)a->stats.pairs, first.allocated_bytes(), second.allocated_bytes(),
          fallback.allocated_bytes());
      expect(a->mesh.memory() == &first && b->mesh.memory() == &second &&
                 a->sources.get_allocator().resource() == &first &&
                 b->sources.get_allocator().resource() == &second,
             "each result is on the resource its options named");
      expect(same_mesh(a->mesh, b->mesh) && a->sources == b->sources &&
                 a->stats.pairs == b->stats.pairs && a->stats.pairs > 0,
             "the two results are the same");
      const std::size_t result_bytes = a->mesh.corners.size() * sizeof(petersen::VertexId) +
                                       a->mesh.positions.size() * sizeof(a->mesh.positions[0]);
      expect(first.allocated_bytes() >= result_bytes && second.allocated_bytes() >= result_bytes,
             "each resource served its own conversion");
    }
    expect(first.live_bytes() == 0 && second.live_bytes() == 0,
           "with the results gone, each resource has every byte back");
    fallback.reset();
  }
  std::pmr::set_default_resource(nullptr);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
