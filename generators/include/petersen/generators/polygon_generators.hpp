#pragma once
// Seeded generators of every kind of mesh a user has, for tests and benchmarks: non-orientable
// closed surfaces, open grids with holes, meshes mixing triangles and polygons, non-manifold
// edges, pinched vertices, inconsistent orientation and several components.
//
// Every function is deterministic for its arguments on any standard library: random choices use
// petersen's SeededRandom (petersen/graph/seeded_random.hpp) and its bounded draws, never the std
// distributions or std::shuffle, whose results differ between implementations. Counts below are
// of referenced vertices; V, E, F are vertices, distinct undirected edges and faces, χ = V - E + F.

#include <cstdint>
#include <span>

#include "petersen/mesh/mesh.hpp"

namespace petersen {

/// A closed, non-orientable, connected triangulated Klein bottle: the u × v grid of a torus whose
/// rows close up with a reflection (row v is row 0 with column i renamed (u - i) mod u), each cell
/// cut along one diagonal. Simplicial: no repeated triangle, every edge in exactly two triangles,
/// every vertex link one 6-cycle. V = uv, E = 3uv, F = 2uv, χ = 0, no boundary. Positions are
/// the figure-8 immersion, with its self-intersection circle pushed apart so that no two
/// vertices coincide (checked for every grid up to 120 × 120, and 1000 × 1000). Throws
/// std::invalid_argument when u < 3 or v < 3 (smaller grids repeat edges) or when the mesh would
/// pass 2^32 - 1 corners. O(uv).
PolygonMesh klein_bottle(std::uint32_t u, std::uint32_t v);

/// A closed, non-orientable, connected triangulated real projective plane: the six-vertex
/// hemi-icosahedron (the icosahedron with antipodal points identified: 6 vertices, 15 edges, 10
/// triangles), refined by `subdivision` rounds of 4-to-1 midpoint subdivision. Simplicial, every
/// edge in exactly two triangles, χ = 1, F = 10·4^subdivision (an odd count without
/// subdivision). Positions: each vertex is a point of the sphere (up to sign) mapped by Apéry's
/// even quartic parametrization of Boy's surface; finite and pairwise distinct (checked up to
/// subdivision 7). Throws std::invalid_argument when subdivision > 12. O(F).
PolygonMesh projective_plane(std::uint32_t subdivision);

/// The planar rectangle [0, nx] × [0, ny] (z = 0) triangulated on the integer lattice, every
/// unit square cut into two triangles, counter-clockwise seen from +z. Orientable, connected, one
/// boundary loop of 2(nx + ny) edges, V = (nx + 1)(ny + 1), F = 2·nx·ny, χ = 1. Throws
/// std::invalid_argument when nx or ny is 0 or the mesh would pass 2^32 - 1 corners. O(nx·ny).
PolygonMesh open_grid(std::uint32_t nx, std::uint32_t ny);

/// A lattice of near-square quads, each cut along a random one of its two diagonals: a mesh whose
/// best pairing gives back the quads it was made from. Every lattice point is moved by up to
/// `jitter` (a fraction of the spacing) along each lattice direction, uniformly at random.
/// - open (torus false): open_grid's rectangle [0, nx] × [0, ny] at z = 0, vertex (x, y) at
///   y·(nx+1) + x, one boundary loop;
/// - torus: closed, the lattice wrapped around a torus of minor radius 1 and major radius nx/ny
///   (so that the quads are near-square on average), vertex (x, y) at y·nx + x, x around the
///   major circle; needs nx ≥ 3·ny (the hole) and ny ≥ 3.
/// Square q = y·nx + x (corners (x, y), (x+1, y), (x+1, y+1), (x, y+1)) is faces 2q and 2q + 1,
/// counter-clockwise (seen from +z, or from outside the torus). Throws std::invalid_argument as
/// open_grid does, for a jitter outside [0, 0.25) (the squares could fold), or a torus too
/// small. O(nx·ny).
struct JitteredGrid {
  std::uint32_t nx = 60, ny = 60;
  double jitter = 0.1;
  bool torus = false;
  std::uint64_t seed = 1;
};
PolygonMesh jittered_grid(const JitteredGrid& spec);

/// The mesh with `holes` random patches of faces removed: each patch is a random remaining face,
/// alone or (with probability 1/2) together with every remaining face sharing a vertex with it.
/// Each patch cut into a surface's interior opens a new boundary loop; patches may overlap,
/// merge, touch the boundary or touch one another at a vertex (a pinched vertex). The vertex
/// array is kept unchanged (vertices may become unreferenced); the remaining faces keep their
/// corners and their order. At least one face is always kept: a patch that would remove every
/// remaining face is skipped. O(V + corners + holes·a·d) for maximum face arity a and vertex
/// degree d.
PolygonMesh punch_holes(const PolygonMesh& mesh, std::uint32_t holes, std::uint64_t seed);

/// Merges about `count` random groups of two or three edge-adjacent triangles into quads and
/// pentagons. A triangle joins a polygon across an edge that belongs to exactly these two faces,
/// runs in opposite directions in them (so the polygon keeps both faces' orientation) and whose
/// third corner is not a corner of the polygon yet; the polygon's corners are in order. A group
/// that finds no such neighbour stays a triangle, so fewer polygons may come out. V, E - merges,
/// F - merges: χ, the boundary, orientability and components are unchanged. Faces that are not
/// triangles are kept. The polygon takes the place of its seed triangle in the face order.
/// O(corners·log(corners) + count·log(corners)).
PolygonMesh merge_into_polygons(const PolygonMesh& mesh, std::uint32_t count, std::uint64_t seed);

/// Adds `count` fins: each a new triangle on an existing edge (a, b) of a random face, with a new
/// vertex off the edge (beside its midpoint, along the face's normal). The edge is chosen among
/// those with two or more faces where any exists, so it ends up in three or more faces (a
/// non-manifold edge); on a mesh with only boundary edges it becomes an ordinary edge of two
/// faces. V + count, F + count, E + 2·count: χ is unchanged. O(corners·log(corners) + count·a)
/// for maximum face arity a.
PolygonMesh add_fins(const PolygonMesh& mesh, std::uint32_t count, std::uint64_t seed);

/// Makes up to `count` pinched vertices: each time, two random referenced vertices u and w whose
/// closed face neighbourhoods are disjoint (no face holds both, no vertex shares a face with both)
/// and that lie in no earlier pinch's neighbourhoods are merged: w is renamed u in every face
/// (so no edge or face is repeated and none degenerates), w stays in the vertex array
/// unreferenced. u's faces then form at least two fans touching only at u (on a closed surface,
/// two cones sharing an apex). Each pinch lowers V and χ by one, leaves E and F unchanged, and
/// joins two components into one when u and w were in different ones. Gives up after
/// 16·count + 64 candidate pairs, so fewer pinches happen on small meshes.
/// O(V + corners + count·a·d) for maximum face arity a and vertex degree d.
PolygonMesh pinch_vertices(const PolygonMesh& mesh, std::uint32_t count, std::uint64_t seed);

/// Reverses the corner order of min(count, F) distinct random faces: the mesh's orientation
/// becomes inconsistent across their edges. Nothing else changes. O(F + corners).
PolygonMesh flip_faces(const PolygonMesh& mesh, std::uint32_t count, std::uint64_t seed);

/// The meshes side by side as one: positions appended in order, each mesh's corners offset by the
/// vertices before it. Components add up; so do V, E, F and χ. O(total V + total corners).
PolygonMesh concatenate(std::span<const PolygonMesh> meshes);

/// One random mesh of about `size` faces (at least the smallest base shape: a few faces to a few
/// thousand are meant), drawing every kind above: one to three components, each a closed
/// orientable surface of random genus (random_closed_surface), a Klein bottle, a projective plane
/// or an open grid; then, each with some probability, holes, polygons, fins, pinched vertices and
/// flipped faces. Always at least one face; corners in range, no face with a repeated corner, no
/// two faces on the same set of vertices. O(size) expected.
PolygonMesh random_mixed_mesh(std::uint64_t seed, std::uint32_t size);

}  // namespace petersen
