#pragma once
// The box-shaped plates of the paper's Table 4.2, with every dimension tunable so each member can
// be generated within a fraction of a percent of the paper's triangle counts.

#include <cstdint>

#include "petersen/dualize/mesh.hpp"

namespace petersen::bench {

/// A plate of holes_x by holes_y holes (or dents) on an integer lattice whose unit squares are cut
/// into two triangles each. Along x the plate alternates walls of wall_x units and holes of
/// hole_x units, starting and ending with a wall; likewise along y. Without dents it is
/// `thickness` units thick and every hole goes through (genus holes_x·holes_y, family B); with
/// dents it is thickness + dent_depth units thick and every hole is a cavity dent_depth deep dug
/// into the top (genus 0, family A).
struct PlateShape {
  std::uint32_t holes_x = 1, holes_y = 1;
  std::uint32_t wall_x = 1, hole_x = 1, wall_y = 1, hole_y = 1;
  std::uint32_t thickness = 1;
  std::uint32_t dent_depth = 0;
  bool dents = false;

  /// Triangles of the plate, from the formula (no mesh built). O(1).
  std::uint64_t triangle_count() const;
  /// Genus of the plate's surface: 0 with dents, holes_x·holes_y without.
  std::uint64_t genus() const;
};

/// The closed, consistently oriented triangulation of the plate's surface. O(triangles).
TriangleMesh plate_mesh(const PlateShape& shape);

/// The plate with the given holes (or dents) whose triangle count is nearest `target`: among the
/// shapes within `tolerance` (relative) of it, the one whose in-plane widths are most alike, then
/// the nearest; widths and depths range over 1..`max_units`, each at most twice another.
/// O(max_units^6) formula evaluations.
PlateShape fit_plate(std::uint32_t holes_x, std::uint32_t holes_y, bool dents, std::uint64_t target,
                     double tolerance, std::uint32_t max_units);

/// A plate with all widths and depths equal to `units` (a regular, isotropic refinement).
PlateShape uniform_plate(std::uint32_t holes_x, std::uint32_t holes_y, bool dents,
                         std::uint32_t units);

}  // namespace petersen::bench
