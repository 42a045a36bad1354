#pragma once
// --all-quad's last step: every face, its midpoints inserted, cut into quads.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "carry_attributes.hpp"
#include "petersen/mesh/edge_groups.hpp"

namespace petersen::quad_detail {

struct CutIntoQuadsOptions {
  /// Objective::quality: a crossed quad is cut around a new centre vertex (the average of its four
  /// corners, as carry_attributes blends them) where that gives a smaller worst corner than
  /// every fan. Otherwise only fans, no new vertex.
  bool centres_where_better = false;
};

/// The faces after the cuts, in the order of the faces they come from.
struct QuadPieces {
  PolygonMesh
      mesh;  ///< faces only (on the cut mesh's resource): the positions stay in the mesh cut
  std::pmr::vector<std::array<FaceId, 2>> sources;
  std::vector<FaceId> face_of = {};  ///< with attributes: the face each output face comes from
  std::vector<Blend> corner_from =
      {};                           ///< with attributes: each corner's blend of its face's corners
  std::vector<FaceId> pieces = {};  ///< the output faces the cuts made
  std::uint64_t centres = 0;        ///< centre vertices added
};

/// Cuts every face of `mesh` with an even side count once the midpoints are in (midpoint[h]:
/// the vertex on halfedge h's edge, or kNoNode) into quads; a kept face, or a quad with no
/// midpoint, stays as it is. A triangle with one midpoint is that quad. A face of s ≥ 6 sides is
/// cut by a fan of s/2 − 1 quads from one of its corners (all s of them, or 32 spread around a
/// larger face), the one whose worst corner (quad_corner_deviation) is least among the fans whose
/// diagonals are no edge of the mesh yet;
/// a quad crossed straight through (midpoints on opposite sides) by the segment joining them.
/// A centre vertex with s/2 quads around it (spokes to every other corner) is used where
/// `options` asks and it is better, and where no fan is free; it lies at the average of the
/// face's corners (of four spread corners beyond four), each appended to mesh.positions and,
/// with `new_vertices`, its blend. O(Σ s) per candidate, at most 32 candidates per face.
QuadPieces cut_into_quads(PolygonMesh& mesh, const PolygonHalfedges& half, const EdgeGroups& groups,
                          std::span<const VertexId> midpoint, std::span<const std::uint8_t> kept,
                          std::span<const std::array<FaceId, 2>> sources,
                          std::vector<Blend>* new_vertices, const CutIntoQuadsOptions& options);

}  // namespace petersen::quad_detail
