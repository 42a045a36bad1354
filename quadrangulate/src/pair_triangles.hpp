#pragma once
// The maximum pairing of a mesh's triangles, certified: closed components by the chosen
// algorithm, the others by augmenting paths with a Tutte–Berge witness (quadrangulate.hpp).

#include <array>
#include <span>
#include <vector>

#include "petersen/dualize/pairable_graph.hpp"
#include "petersen/lrs/lrs.hpp"
#include "petersen/quadrangulate/quadrangulate.hpp"

namespace petersen::quad_detail {

/// A quad lrs made, with the input triangles behind it (kNoFace where its flips made a new one).
using LrsQuad = petersen::LrsQuad;

struct TrianglePairing {
  /// Per node: its partner node, kNoNode when unpaired, kLrsNode when lrs paired it (lrs_quads).
  HugeVector<NodeId> partner;
  HugeVector<LrsQuad> lrs_quads;     ///< on huge pages: they reuse what the pairing freed
  std::vector<NodeId> tutte_set;     ///< nodes; see QuadResult::tutte_set
  std::int64_t objective_units = 0;  ///< Objective::quality: the certified total, scaled costs
};
inline constexpr NodeId kLrsNode = kNoNode - 1;

/// Pairs the nodes of `graph` (the pairable graph of `mesh`; its edge arrays may be taken over, its
/// node_face stays) and checks the answer; Objective::quality needs `degrees`, the cost of each
/// edge (pairable_edge_quality). `releasable_corners`, when not null, is mesh.corners, which
/// lrs on a whole closed mesh frees without options.sources (pair_component_by_lrs); the mesh
/// then has no corners when this returns.
/// throws std::logic_error if a matching fails the verifier or its witness. Fills the matching,
/// lrs, component and time fields of `stats`, and maximum_certified.
TrianglePairing pair_triangles(PairableGraph& graph, const PolygonMesh& mesh,
                               HugeVector<VertexId>* releasable_corners,
                               std::span<const double> degrees, const QuadOptions& options,
                               QuadStats& stats);

}  // namespace petersen::quad_detail
