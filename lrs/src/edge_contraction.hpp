#pragma once
// Edge contraction, its exact inverse (vertex split) and the contractibility test (paper §3.3).

#include <cstdint>

#include "triangulation.hpp"

namespace petersen::lrs {

/// What contract() recorded so that split() can undo it: the contracted halfedge h (from the
/// surviving vertex u to the removed vertex v), the halfedge y→v of the other face, and v's degree
/// just before the contraction (its degree in the paper's T_ij).
struct ContractionRecord {
  Halfedge h = kNoHalfedge;
  Halfedge t2 = kNoHalfedge;
  std::uint32_t removed_degree = 0;
};

/// Link condition: h's edge [u, v] is contractible when the common neighbours of u and v are
/// exactly the two apexes of its faces (no non-facial 3-cycle through it) and the triangulation is
/// not the tetrahedron. O(deg u + deg v).
bool is_contractible(const Triangulation& tri, Halfedge h, VertexMarks& marks);

/// Contracts h's edge [u, v] into u = origin(h), which keeps its id; v, the faces [u, v, x] and
/// [v, u, y], and the edges [u, v], [v, x], [v, y] die, and [u, x], [u, y] are the split edges of
/// the record. Precondition: is_contractible. O(deg v).
ContractionRecord contract(Triangulation& tri, Halfedge h);

/// Vertex split, the inverse of contract(record): revives v, its two faces and three edges, and
/// hands v the edges of u from [u, y] to [u, x] on v's side. Applied to the triangulation contract
/// left, it restores the exact arrays (up to out()); it also works after flips of edges not
/// incident on u (the expansion step's K), provided the split edges [u, x] and [u, y] are edges of
/// the triangulation, and gives v whatever edges then lie on its side. O(degree of v after split).
void split(Triangulation& tri, const ContractionRecord& record);

}  // namespace petersen::lrs
