#pragma once
// An independent check of a QuadResult against its input, sharing no code with quadrangulate:
// its own pairable graph (a std::map over edges), LEMON's and Boost's maximum matchings for the
// size, and verify_maximum_matching for the witness.

#include <optional>
#include <span>
#include <string>

#include "petersen/quadrangulate/quadrangulate.hpp"

namespace petersen::testing {

/// Empty when `result` is a correct maximum pairing of `input` (or, with all_quad, a correct
/// all-quad mesh made from one, see all_quad_check.hpp; the input's polygons may be kept or
/// rebuilt); else the first problem found.
/// `cuts` are the extra cuts the run was given, judged here on their own terms; the cuts of the
/// input's attributes (seams, material and other borders) are judged from the values
/// themselves, except those whose span `cuts` sets and those `cross` names.
/// `max_corner_deviation` is the run's threshold: no pair's quad may cost more.
std::string check_quad_result(const PolygonMesh& input, const QuadResult& result, bool all_quad,
                              bool flips_allowed, const CutOptions& cuts = {},
                              std::span<const CutCause> cross = {},
                              std::optional<double> max_corner_deviation = {});

/// The same check for a run with these options, judged on their own terms: the objective (quads
/// need not be maximum, but must be certified optimal), the algorithm (lrs may flip), the cuts,
/// cross, the threshold, and with all_quad keep_polygons (input polygons kept
/// exactly, or rebuilt into quads) and the all-quad figures (check_all_quad_counts).
std::string check_quad_result(const PolygonMesh& input, const QuadResult& result,
                              const QuadOptions& options);

/// Empty when the output carries the input's attributes: every output corner of an input vertex
/// has the texture coordinate and normal (values) of that vertex's corner in the output face's
/// source triangles (the first one's where both have it), every new vertex (all_quad) those of
/// its face's source corners averaged over the edge or quad it splits, every face its first
/// source's material, group, object, smoothing group and face properties, and every vertex its
/// vertex properties (new ones averaged, integers rounded). Else the first problem found.
std::string check_attributes_kept(const PolygonMesh& input, const QuadResult& result);

/// V − E + F over referenced vertices and distinct edges.
std::int64_t euler_characteristic(const PolygonMesh& mesh);

}  // namespace petersen::testing
