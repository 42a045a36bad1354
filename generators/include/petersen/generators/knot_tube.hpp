#pragma once
// A recognisable closed model made the way modellers make one: a quad mesh (a tube around a
// trefoil knot), exported as triangles by cutting every quad along the same diagonal.

#include <cstdint>

#include "petersen/mesh/mesh.hpp"

namespace petersen {

/// The tube of radius 0.6 around the trefoil knot, the (2, 3) torus knot on the torus of major
/// radius 2 and minor radius 1 (its strands stay 1.66 apart and bend no tighter than radius
/// 1.43, so the tube never meets itself). Cross-section rings at `segments` points of equal arc
/// length, each of `sides` vertices, oriented by a rotation-minimising frame whose closing twist
/// is spread evenly along the knot: the quads between rings are near-planar trapezoids, near
/// square for segments ≈ 8.5·sides (the defaults 136 × 16 give 2176 quads, 4352 triangles).
/// Closed, orientable, genus 1, simplicial. Ring i's vertex j is i·sides + j (the last ring
/// joins the first some whole sides round, whichever shears the quads least); quad (i, j) is
/// faces 2q and 2q + 1 for q = i·sides + j, cut along its diagonal from (i, j) to (i + 1, j + 1)
/// and counter-clockwise seen from outside. Throws std::invalid_argument when segments < 3 or
/// sides < 3, or the mesh would pass 2^32 - 1 corners. O(segments·sides).
struct KnotTube {
  std::uint32_t segments = 136, sides = 16;
};
PolygonMesh trefoil_tube(const KnotTube& spec);

}  // namespace petersen
