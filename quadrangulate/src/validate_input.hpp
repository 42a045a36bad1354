#pragma once
// The front door's checks of what the caller gives: the options' values and the mesh's
// coordinates, once at the door, so that no phase after it meets a NaN or an out-of-range angle.

#include "petersen/quadrangulate/quadrangulate.hpp"

namespace petersen::quad_detail {

/// Throws std::invalid_argument naming the option and its value when max_corner_deviation is not
/// a finite number in [0, kDegenerateQuadCost] (the range of quad_corner_deviation), when
/// cuts.sharp_angle_degrees is not a finite number in [0, 180], or when threads exceeds
/// kMaxQuadThreads. O(1).
void validate_options(const QuadOptions& options);

/// Throws MeshError naming the first vertex (its index and coordinates) whose position is not
/// finite, referenced by a face or not: no measure, fold or output file has a meaning for it.
/// O(V).
void validate_positions(const PolygonMesh& mesh);

}  // namespace petersen::quad_detail
