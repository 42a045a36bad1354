#pragma once
// An independent check of a QuadResult against its input, sharing no code with quadrangulate:
// its own pairable graph (a std::map over edges), LEMON's and Boost's maximum matchings for the
// size, and verify_maximum_matching for the witness.

#include <optional>
#include <string>

#include "petersen/quadrangulate/quadrangulate.hpp"

namespace petersen::testing {

/// Empty when `result` is a correct maximum pairing of `input` (or, with all_quad, a correct
/// all-quad mesh made from one); else the first problem found.
/// `cuts` are the extra cuts the run was given, judged here on their own terms, and
/// `max_corner_deviation` the run's threshold: no pair's quad may cost more.
std::string check_quad_result(const PolygonMesh& input, const QuadResult& result, bool all_quad,
                              bool flips_allowed, const CutOptions& cuts = {},
                              std::optional<double> max_corner_deviation = {});

/// V − E + F over referenced vertices and distinct edges.
std::int64_t euler_characteristic(const PolygonMesh& mesh);

}  // namespace petersen::testing
