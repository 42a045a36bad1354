#pragma once
// The figures of one quadrangulate run as an ordered list of named values: the keys of
// `petersen quad --stats-json` and of the Python module's `stats` dict, from one place.

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "petersen/quadrangulate/quadrangulate.hpp"

namespace petersen {

/// What the caller measured around quadrangulate: the files and their times. A field left empty
/// (no input or output path, no load or write time) is left out of the list.
struct RunFigures {
  std::string input, output;
  std::optional<double> load_seconds, write_seconds;
  /// The whole run; when absent, QuadStats::total_seconds.
  std::optional<double> total_seconds;
};

/// One named figure; counts by cause are a list of (cause, count).
using StatValue = std::variant<bool, std::int64_t, std::uint64_t, double, std::string,
                               std::vector<std::pair<std::string, std::uint64_t>>>;
struct StatField {
  std::string key;
  StatValue value;
};

/// The share of the triangles left unpaired above which the figures say which cuts of the mesh's
/// attributes may be why (crossable_cuts_behind_left).
inline constexpr double kLeftShareToExplain = 0.02;

/// When more than kLeftShareToExplain of the triangles are left, the causes that QuadOptions::cross
/// could name (CutCause::uv_seam to face_property) and that cut some edge of this run, each with
/// its count of cut edges, in the order of CutCause; empty otherwise (few left, or no such cut).
/// Crossing them lets pairs cross those edges, which pairs the triangles left beside them unless
/// the structure (boundaries, polygons) leaves them odd anyway. O(1).
std::vector<std::pair<CutCause, std::uint64_t>> crossable_cuts_behind_left(const QuadStats& stats);

/// The figures in the order --stats-json writes them: input, output, objective, algorithm
/// ("min-cost" for Objective::quality), augment (for the
/// algorithms that augment: sg, ps, lrs), counts, cuts by cause, every phase's time, the paper's
/// columns, lrs's figures (lrs only), maximum_certified, pairs, triangles_left, then
/// cross_to_pair (crossable_cuts_behind_left by name, only when it is not empty), added_vertices,
/// total_seconds last. genus only when the stats have it. O(1).
std::vector<StatField> stats_fields(const QuadStats& stats, const QuadOptions& options,
                                    const RunFigures& run = {});

}  // namespace petersen
