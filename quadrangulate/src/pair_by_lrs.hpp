#pragma once
// lrs (paper §3.3–3.4) on one closed component of the pairable graph, for pair_triangles: the
// whole mesh from the graph's own arrays, or one component of several as a mesh of its own.

#include <span>
#include <vector>

#include "petersen/graph/stopwatch.hpp"
#include "petersen/quadrangulate/stages.hpp"

namespace petersen::quad_detail {

/// Pairs the triangles of one closed component by pair_closed_component_by_lrs and appends one
/// LrsQuad per pair of K's triangles to pairing.lrs_quads, with the input faces behind it (kNoFace
/// for both on the whole graph without options.sources), its nodes' partners set to kLrsNode. With
/// `nodes` empty the component is the whole graph (graph.cubic, no inconsistent edge, one
/// component, mesh of triangles): the triangulation is built from graph.node_edges and
/// graph.edge_ends, taken over, and without options.sources `releasable_corners` (the consuming
/// front door's mesh.corners, or null) is freed once it is built. Otherwise `nodes` (ascending) are
/// renumbered onto their own vertices (`local`: per input vertex, all kNoNode, left so). Returns
/// false, with the reason in stats.lrs_fallback_reason, when lrs cannot take the component: the
/// mesh has corner or face attributes (a flipped triangle has none), or the component is not an
/// orientable manifold (a pinched vertex); the whole graph's arrays are then made again. Fills the
/// matching and lrs fields of `stats` and its dual, initial, augment and verify times.
bool pair_component_by_lrs(PairableGraph& graph, const PolygonMesh& mesh,
                           std::span<const NodeId> nodes,
                           std::pmr::vector<VertexId>* releasable_corners,
                           const QuadOptions& options, std::vector<VertexId>& local,
                           TrianglePairing& pairing, QuadStats& stats, Stopwatch& clock);

}  // namespace petersen::quad_detail
