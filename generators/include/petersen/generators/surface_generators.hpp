#pragma once
// Closed, oriented triangulations for tests, benchmarks and the bundled example; all seeded. Each
// is an all-triangle PolygonMesh: face t is corners[3t..3t + 2], face_start empty.

#include "petersen/mesh/mesh.hpp"

namespace petersen {

/// A box-shaped plate on an integer lattice whose unit squares are cut into two triangles each:
/// the paper's synthetic families (Table 4.2). Along x the plate alternates walls of wall_x units
/// and holes of hole_x units, starting and ending with a wall (holes_x holes); likewise along y.
/// Without dents it is `thickness` units thick and every hole goes through (genus
/// holes_x·holes_y, family B); with dents it is thickness + dent_depth units thick and every hole
/// is a cavity dent_depth deep dug into the top (genus 0, family A). A regular triangulation.
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
PolygonMesh plate_mesh(const PlateShape& shape);

/// The plate with every width and depth equal to `units` (a regular, isotropic refinement).
PlateShape uniform_plate(std::uint32_t holes_x, std::uint32_t holes_y, bool dents,
                         std::uint32_t units);

/// The uniform plate in short: plate_mesh(uniform_plate(holes_x, holes_y, dents, subdivision)).
/// holes_x = holes_y = 0 gives a cube's surface.
struct PlateSpec {
  std::uint32_t holes_x = 1;
  std::uint32_t holes_y = 1;
  std::uint32_t subdivision = 1;
  bool dents = false;
};
PolygonMesh voxel_plate(const PlateSpec& spec);

/// Makes a closed triangulation irregular: `splits` random 1-to-3 triangle splits (new vertex at
/// the centroid), then about `flips` random edge flips that keep it simplicial (a flip is skipped
/// when the new edge exists already or an end would drop to degree 2). Genus is unchanged.
/// Throws MeshError unless every face is a triangle (face_start empty) and every edge has two.
PolygonMesh randomize_triangulation(PolygonMesh mesh, std::uint32_t splits, std::uint32_t flips,
                                    std::uint64_t seed);

/// The mesh renumbered the way scanners and subdivisions store theirs: triangles in Morton
/// (Z-order) of their centroids, vertices in order of first use, orientation kept. Neighbours then
/// sit near each other in memory, where random splits and flips leave them scattered over the
/// arrays. Throws MeshError unless every face is a triangle (face_start empty). O(F log F).
PolygonMesh spatially_ordered(const PolygonMesh& mesh);

/// An irregular closed triangulation of genus `genus`: a thin plate with `genus` holes (a cube for
/// genus 0), then `splits` random 1-to-3 triangle splits, then about `flips` random edge flips
/// that keep it a simplicial triangulation. Positions of new vertices are triangle centroids.
PolygonMesh random_closed_surface(std::uint32_t genus, std::uint32_t splits, std::uint32_t flips,
                                  std::uint64_t seed);

}  // namespace petersen
