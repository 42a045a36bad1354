#include "micro_inputs.hpp"

#include <map>
#include <memory>

#include "petersen/generators/surface_generators.hpp"

namespace petersen::micro {

// benchmark_main owns main(): the pool (huge_pages.hpp) is turned on before it runs, as the CLI
// and the other benchmarks turn it on first thing.
[[maybe_unused]] const bool kPoolOn = (huge_pages::enable_pool_unless_switched_off(), true);

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
