#pragma once
// Closed, oriented triangulations for tests, benchmarks and the bundled example; all seeded.

#include "petersen/dualize/mesh.hpp"

namespace petersen {

/// A box-shaped plate made of unit voxels whose boundary is triangulated: (2·holes_x+1) by
/// (2·holes_y+1) cells, one cell thick, with a square through-hole at every (odd, odd) cell
/// (genus holes_x·holes_y, the paper's family B) — or, with `dents`, two cells thick with a
/// cavity dug into the top layer there instead (genus 0, the paper's family A). Every voxel face
/// is cut into subdivision² squares, two triangles each: a regular triangulation.
struct PlateSpec {
  std::uint32_t holes_x = 1;
  std::uint32_t holes_y = 1;
  std::uint32_t subdivision = 1;
  bool dents = false;
};
TriangleMesh voxel_plate(const PlateSpec& spec);

/// Makes a closed triangulation irregular: `splits` random 1-to-3 triangle splits (new vertex at
/// the centroid), then about `flips` random edge flips that keep it simplicial (a flip is skipped
/// when the new edge exists already or an end would drop to degree 2). Genus is unchanged.
TriangleMesh randomize_triangulation(TriangleMesh mesh, std::uint32_t splits, std::uint32_t flips,
                                     std::uint64_t seed);

/// An irregular closed triangulation of genus `genus`: a thin plate with `genus` holes (a cube for
/// genus 0), then `splits` random 1-to-3 triangle splits, then about `flips` random edge flips
/// that keep it a simplicial triangulation. Positions of new vertices are triangle centroids.
TriangleMesh random_closed_surface(std::uint32_t genus, std::uint32_t splits, std::uint32_t flips,
                                   std::uint64_t seed);

}  // namespace petersen
