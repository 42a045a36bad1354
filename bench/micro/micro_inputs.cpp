#include "micro_inputs.hpp"

#include <map>
#include <memory>

#include "memory_pool.hpp"
#include "petersen/generators/surface_generators.hpp"

namespace petersen::micro {

// benchmark_main owns main(): the pool (memory_pool.hpp) is installed before it runs, as the
// other benchmarks install it first thing.
[[maybe_unused]] const bool kPoolOn = (bench::install_memory_pool(), true);

const MicroInput& plate_input(std::uint64_t triangles) {
  static std::map<std::uint64_t, std::unique_ptr<MicroInput>> cache;
  auto& slot = cache[triangles];
  if (!slot) {
    // Subdivision s multiplies the triangles of the unsubdivided plate by s².
    PlateSpec spec{8, 8, 1, true};
    const std::uint64_t unit = voxel_plate(spec).face_count();
    while (unit * (spec.subdivision + 1) * (spec.subdivision + 1) <= triangles) ++spec.subdivision;
    slot = std::make_unique<MicroInput>();
    slot->mesh = voxel_plate(spec);
    slot->dual = build_dual(slot->mesh);
  }
  return *slot;
}

}  // namespace petersen::micro
