#pragma once
// Edge flip (paper Definition 3.3) and its validity test.

#include "triangulation.hpp"

namespace petersen::lrs {

/// h's edge [a, b] with faces [a, b, c] and [b, a, d] is flippable when its flip [c, d] is not
/// already an edge and a and b keep degree at least 3. O(deg c).
bool is_flippable(const Triangulation& tri, Halfedge h);

/// Replaces [a, b] and its faces [a, b, c], [b, a, d] by [d, c] and the faces [c, a, d], [d, b, c];
/// every id is kept: h becomes d→c in face(h). Flipping twice gives back the same triangulation
/// with the two halfedges (and the two faces) of the edge exchanged. Precondition: is_flippable.
/// O(1).
void flip(Triangulation& tri, Halfedge h);

}  // namespace petersen::lrs
