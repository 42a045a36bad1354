#pragma once
// Fitting the plates of the paper's Table 4.2 (petersen::PlateShape) to its triangle counts, by
// tuning every dimension, so each member is within a fraction of a percent of the paper's.

#include <cstdint>

#include "petersen/generators/surface_generators.hpp"

namespace petersen::bench {

/// The plate with the given holes (or dents) whose triangle count is nearest `target`: among the
/// shapes within `tolerance` (relative) of it, the one whose in-plane widths are most alike, then
/// the nearest; widths and depths range over 1..`max_units`, each at most twice another.
/// O(max_units^6) formula evaluations.
PlateShape fit_plate(std::uint32_t holes_x, std::uint32_t holes_y, bool dents, std::uint64_t target,
                     double tolerance, std::uint32_t max_units);

}  // namespace petersen::bench
