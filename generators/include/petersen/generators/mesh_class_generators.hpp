#pragma once
// Seeded meshes of the classes the other generators do not make: an open non-orientable strip,
// quad-dominant meshes with odd faces among the quads, and flat shading with texture charts and
// materials on any mesh. With polygon_generators.hpp every class a user has is covered: closed,
// open with holes, quad-dominant, non-manifold, non-orientable, several components, textured.
//
// Deterministic for their arguments on any standard library (petersen's SeededRandom only).

#include <cstdint>

#include "petersen/mesh/mesh.hpp"

namespace petersen {

/// A triangulated Möbius band: u columns around the core circle and v rows across the strip,
/// vertex (i, j) at j·u + i, column u glued to column 0 with row j renamed v - j. Each cell is
/// cut along one diagonal. Open, connected, non-orientable, one boundary loop of 2u edges (the
/// two edges of the strip become one), V = u(v + 1), F = 2uv, χ = 0. Throws
/// std::invalid_argument when u < 3 or v < 1 (smaller strips repeat edges). O(uv).
PolygonMesh mobius_band(std::uint32_t u, std::uint32_t v);

/// A quad-dominant mesh: jittered_grid's lattice of nx × ny squares (open, or closed on a torus),
/// most squares one quad, about `triangle_squares` in 16 of them left as the grid's two triangles,
/// then up to `hexagons` pairs of side-by-side quads merged into a hexagon and up to `pentagons`
/// quads merged with the triangle across their right side into a pentagon. Every face keeps the
/// lattice's counter-clockwise orientation; χ, the boundary and the torus's genus are the grid's.
/// Faces in square order (a merged face where its left square was). Throws std::invalid_argument
/// as jittered_grid does. O(nx·ny).
struct QuadDominantGrid {
  std::uint32_t nx = 8, ny = 8;
  double jitter = 0.1;
  bool torus = false;
  std::uint32_t triangle_squares = 3;  ///< of 16
  std::uint32_t pentagons = 2, hexagons = 1;
  std::uint64_t seed = 1;
};
PolygonMesh quad_dominant_grid(const QuadDominantGrid& spec);

/// The mesh flat shaded and textured, as a modelling tool exports it: every corner's normal is
/// its face's unit normal (one entry per face; a degenerate face's is +z), texture coordinates
/// are a box projection (each face projected along the axis its normal is closest to, scaled by
/// `uv_scale`; an edge between faces of different axes is a UV seam, its ends given different
/// coordinates on each side), and `materials` materials (at least one) are laid in slabs along x,
/// one random slab boundary per material after the first. Replaces any attributes the mesh had.
/// O(V + corners).
struct FlatShading {
  double uv_scale = 0.25;
  std::uint32_t materials = 2;
  std::uint64_t seed = 1;
};
PolygonMesh flat_shaded(PolygonMesh mesh, const FlatShading& spec = {});

/// A hard-surface model: the cube [-1, 1]^3 with every edge chamfered, the 24 points with one
/// coordinate ±1 and the others ±0.6: 6 squares, 12 bevel rectangles and 8 corner triangles,
/// each counter-clockwise seen from outside. Closed, V = 24, F = 26, χ = 2. A model's own
/// triangles among quads: pairing one breaks a bevel. O(1).
PolygonMesh chamfered_cube();

/// The mesh as an exporter triangulates it: each quad cut along one diagonal, from its first
/// corner (`first_diagonal`) or from its second; every other face kept. Attributes are dropped.
/// O(corners).
PolygonMesh split_quads(const PolygonMesh& mesh, bool first_diagonal);

}  // namespace petersen
