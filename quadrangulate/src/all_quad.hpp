#pragma once
// --all-quad: the faces a pairing leaves that are not quads, made quads by the fewest midpoints.

#include <cstdint>
#include <vector>

#include "petersen/quadrangulate/quadrangulate.hpp"

namespace petersen::quad_detail {

/// What each output face of a QuadResult is, for the splits.
enum class FaceKind : std::uint8_t { kept, left, pair };

/// Makes every face of `result` a quad (but those QuadOptions::keep_polygons keeps): the fewest
/// edges get a midpoint so that every face has an even side count (plan_splits: a minimum
/// T-join, certified, after the non-manifold edges parity forces), then every face is cut into
/// quads (cut_into_quads). Updates the mesh, the sources, the attributes and the stats
/// (added_vertices, split_edges, centre_vertices, added_vertices_minimum, all_quad_certified,
/// split_quads, split_quality_*; triangles_left stays the pairing's). Throws MeshError naming an
/// input face when a face that must change repeats a vertex, or when parity proves that no
/// all-quad mesh exists. O(H) plus the T-join's matching.
void split_leftovers(QuadResult& result, const std::vector<FaceKind>& kinds,
                     const QuadOptions& options);

}  // namespace petersen::quad_detail
