#pragma once
// A brute force of all_quad's minimum, for small meshes, sharing no code with quadrangulate: the
// fewest edges whose midpoints give every face of the pairing an even number of sides.
//
// The faces of the pairing are rebuilt from a result's sources (pair quads = distinct {t1, t2},
// left triangles, input polygons), so a plain run's result serves as well as an all-quad one's.
// Splitting an edge adds one side to each face on it (a face twice on it gains two: no change);
// an edge of one face (boundary) changes that face alone; an edge of three or more faces changes
// all of them at once. With keep_polygons, input polygons that are not triangles are neither
// counted nor split (their edges are not available); neither are faces that repeat a vertex.
//
// The search: every subset of the edges of three or more faces (those are few), then, over the
// graph of the remaining edges (faces as nodes, one sink node for all boundary edges), the
// fewest edges that fix the odd faces: a set of edges changing the parity of exactly the odd
// faces splits into paths joining them in pairs (or to the sink), so its least size is the least
// total of breadth-first distances over all ways to pair the odd faces of each component (a
// dynamic program over subsets). Exponential in the odd faces of a component and in the
// non-manifold edges: meant for meshes of tens of faces.

#include <cstdint>

#include "petersen/quadrangulate/quadrangulate.hpp"

namespace petersen::testing {

struct SplitMinimum {
  enum class Status {
    found,       ///< `splits` is the minimum
    infeasible,  ///< no set of splits makes every side count even
    too_large,   ///< past the limits: not searched
  };
  Status status = Status::too_large;
  std::uint64_t splits = 0;
  /// With `found`: the fewest splits that split no edge of three or more faces (a large value
  /// when none do).
  std::uint64_t splits_without_non_manifold = 0;
};

/// The fewest splits for the pairing `result` made of `input` (see the top of this file), when a
/// component has at most `most_odd_faces` odd faces and there are at most `most_hyperedges`
/// edges of three or more faces; whether any exists is decided within the second limit alone.
/// `flips_allowed`: lrs's quads with a flipped triangle (closed components, all quads) are left
/// out. O(2^h · Σ 2^t t + F log F) for h such edges and t odd faces per component.
SplitMinimum fewest_splits(const PolygonMesh& input, const QuadResult& result, bool keep_polygons,
                           bool flips_allowed, std::uint32_t most_odd_faces = 14,
                           std::uint32_t most_hyperedges = 6);

}  // namespace petersen::testing
