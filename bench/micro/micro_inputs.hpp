#pragma once
// The meshes the micro-benchmarks run on: regular plates of about 2^k triangles, built once.

#include <cstdint>

#include "petersen/dualize/dual.hpp"

namespace petersen::micro {

/// A genus-0 plate with 8×8 dents (petersen's voxel_plate), the finest with at most `triangles`
/// triangles (at least a quarter of that), and its dual; built on first use and kept.
struct MicroInput {
  PolygonMesh mesh;
  Dual dual;
};
const MicroInput& plate_input(std::uint64_t triangles);

}  // namespace petersen::micro
