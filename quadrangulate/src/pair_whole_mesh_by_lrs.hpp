#pragma once
// lrs in the common case, a whole mesh that is one closed, connected, consistently oriented
// triangle surface: its pairable graph is its dual, so lrs's triangulation is built from the
// graph's arrays instead of from copies of the mesh (issue 15: at most 64 bytes per triangle).

#include "lap_clock.hpp"
#include "pair_triangles.hpp"

namespace petersen::quad_detail {

/// Pairs every triangle of `mesh` by lrs (paper §3.3: contraction to an irreducible
/// triangulation, expansion with flips, augmenting paths), the matching of K's dual verified.
/// Preconditions: mesh.all_triangles(), graph.cubic with no inconsistent edge and one component,
/// and no corner or face attributes (a flipped triangle has none). Takes graph.node_edges and
/// graph.edge_ends over; appends one LrsQuad per pair of K's triangles to pairing.lrs_quads, each
/// with the input triangles behind it (kNoFace for both without options.sources), and sets every
/// partner to kLrsNode. Without options.sources, `releasable_corners` (the consuming front door's
/// mesh.corners, or null) is freed once lrs's triangulation is built: `mesh` has no corners from
/// then on. Fills the matching and lrs fields of `stats` and its dual, initial, augment and verify
/// times. Throws MeshError when lrs cannot take the surface (a pinched vertex): the graph's two
/// arrays are gone then, the mesh's corners kept.
void pair_whole_mesh_by_lrs(PairableGraph& graph, const PolygonMesh& mesh,
                            HugeVector<VertexId>* releasable_corners, const QuadOptions& options,
                            TrianglePairing& pairing, QuadStats& stats, LapClock& clock);

}  // namespace petersen::quad_detail
