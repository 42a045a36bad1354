#pragma once
// Which edges --all-quad gives a midpoint: the fewest that make every face's side count even.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "petersen/mesh/edge_groups.hpp"
#include "petersen/quadrangulate/stages.hpp"

namespace petersen::quad_detail {

/// Why SplitPlan::kept keeps a face: QuadOptions::keep_polygons keeps it, or it repeats a vertex.
inline constexpr std::uint8_t kKeptPolygon = 1, kKeptDegenerate = 2;

/// The edges to split, each as all of its halfedges (one on the boundary, two between two faces,
/// more on a non-manifold edge): edge i is halfedges[edge_start[i]..edge_start[i+1]).
struct SplitPlan {
  std::vector<std::uint32_t> edge_start{0};
  std::vector<std::uint32_t> halfedges;
  std::vector<std::uint8_t> kept;         ///< per face: left exactly as it is (kKept*), or 0
  std::uint64_t degenerate_faces = 0;     ///< faces kept because they repeat a vertex
  std::uint64_t non_manifold_splits = 0;  ///< of the edges, those of three or more faces
  std::uint64_t minimum = 0;              ///< non_manifold_splits + the minimum T-join's size
  bool join_certified = false;            ///< the T-join's certificate passed its check
  /// A non-manifold edge has a face in a component that holds odd faces: splitting it flips
  /// several faces at once, which the T-join does not weigh, so fewer splits may exist.
  bool non_manifold_beside_odd = false;

  std::uint32_t edge_count() const { return static_cast<std::uint32_t>(edge_start.size() - 1); }
};

/// Whether some vertex is twice among `corners`. O(n^2) up to 8 corners, O(n log n) beyond.
bool repeats_a_vertex(std::span<const VertexId> corners);

/// The parity model (docs/algorithms.md, "All quads"): a face of s sides can be cut into quads
/// iff s is even, and a midpoint adds a side to every face on its edge. T is the set of faces of
/// odd side count. A face is kept as it is (never in T, no side split) when `keep_polygons`
/// keeps it (an input polygon that is not a triangle) or when it repeats a vertex (no cut of it
/// into quads repeats none).
/// Edges of exactly two faces are the dual's edges and boundary edges join a sink; a component
/// of that dual with an odd number of T faces and no boundary needs splits of non-manifold edges
/// (each flips all its faces at once), chosen by solve_parity_system; then a minimum T-join of the
/// dual (minimum_t_join) over the components holding T faces. Edges of a kept face or twice in
/// one face are never split. Throws MeshError, naming an input face, when no choice of splits
/// makes some component even: a proof that no all-quad mesh refines those faces (their total side
/// count stays odd) while the kept faces stay as they are. O(H) plus the solvers.
SplitPlan plan_splits(const PolygonMesh& mesh, const PolygonHalfedges& half,
                      const EdgeGroups& groups, std::span<const FaceKind> kinds,
                      std::span<const std::array<FaceId, 2>> sources, bool keep_polygons,
                      std::uint32_t threads);

}  // namespace petersen::quad_detail
