#pragma once
// K after the expansion step (paper §3.3.1) in the lean form a caller that only pairs its faces
// needs: its dual as neighbour rows, M as partner faces and its triangles, the triangulation freed
// on the way (at most 64 bytes per triangle at lrs's peak).

#include <array>

#include "expansion_step.hpp"

namespace petersen::lrs {

struct DualRows {
  /// K's dual as neighbour rows (perfect_partners' form): rows[3f + k] is the face across edge k
  /// of triangles[f].
  std::pmr::vector<NodeId> rows;
  /// M: partner[f] is the face paired with f across an edge of M, kNoNode for the ℓ faces left.
  std::pmr::vector<NodeId> partner;
  /// K's face f with the input's vertex ids, counter-clockwise from its smallest halfedge: edge k
  /// joins corners k and (k + 1) % 3. Faces are numbered in order of their smallest halfedge, as
  /// to_mesh numbers them.
  std::pmr::vector<std::array<VertexId, 3>> triangles;
  std::uint32_t unpaired = 0;  ///< ℓ: faces with no partner
};

/// Takes K (the triangulation expand_and_match left, every face alive) and the expansion's edge
/// states over and gives DualRows, freeing each array once the next is made: beside K's links
/// (24 bytes per face), at most the triangles (12) and M's side (1), then the rows (12) beside half
/// the links, the triangles and M's side (the edge states, 1.5, are freed before them), where a
/// CubicGraph of K's dual and a Matching on it would add 28 and an augmentation on them 28 more.
/// The triangulation is left empty. Throws std::logic_error if a face is dead or two edges of M
/// share a face. O(F).
DualRows into_dual_rows(Triangulation&& tri, ExpansionResult&& expansion);

}  // namespace petersen::lrs
