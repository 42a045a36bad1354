#pragma once
// Which triangles of a polygon mesh may be paired into a quad: the pairable graph, and the cuts
// no pair may cross, with their causes.

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "petersen/graph/cubic_graph.hpp"
#include "petersen/mesh/mesh.hpp"

namespace petersen {

/// Why an edge of the mesh is a cut: a pair of triangles never crosses it.
enum class CutCause : std::uint8_t {
  boundary,       ///< the edge belongs to one face
  non_manifold,   ///< three or more faces
  polygon,        ///< a face beside it is not a triangle (polygons are kept as they are)
  degenerate,     ///< a face beside it repeats a vertex, or runs along the edge twice
  duplicate,      ///< its two triangles have the same three vertices (their union is no quad)
  user,           ///< named by the caller (CutOptions::user_edges)
  sharp,          ///< its triangles fold by more than CutOptions::sharp_angle_degrees
  uv_seam,        ///< its two triangles give its ends different texture coordinates
  normal_seam,    ///< ... different corner normals
  material,       ///< its two faces have different materials
  group,          ///< ... different groups
  object,         ///< ... different objects
  smoothing,      ///< ... different smoothing groups
  face_property,  ///< ... different values of another per-face property
  /// The quad of its two triangles deviates from right angles by more than the caller allows
  /// (QuadOptions::max_corner_deviation; cut by quadrangulate, not build_pairable_graph).
  shape,
};
inline constexpr int kCutCauses = 15;
/// Whether a cause is one of the mesh's attributes (uv_seam to face_property): the cuts
/// QuadOptions::cross may let pairs cross. The structure's, the caller's and shape never are.
constexpr bool is_attribute_cause(CutCause cause) {
  return cause >= CutCause::uv_seam && cause <= CutCause::face_property;
}
/// Every attribute cause, in the order of CutCause: what `cross` takes to cross them all.
inline std::vector<CutCause> attribute_causes() {
  std::vector<CutCause> causes;
  for (int c = 0; c < kCutCauses; ++c)
    if (is_attribute_cause(CutCause(c))) causes.push_back(CutCause(c));
  return causes;
}
/// Whether a cause is the mesh's structure (boundary to duplicate): where the surface itself is
/// not a closed two-manifold of triangles, rather than a pair being refused.
constexpr bool is_structural_cause(CutCause cause) {
  return cause <= CutCause::duplicate;
}
std::string_view to_string(CutCause cause);
/// The cause named as to_string names it ("uv_seam", "material", ...), or nothing.
std::optional<CutCause> parse_cut_cause(std::string_view name);

/// Mesh edges that are cuts, by cause (index: CutCause).
struct CutCounts {
  std::array<std::uint64_t, kCutCauses> by_cause{};
  std::uint64_t total() const {
    std::uint64_t sum = 0;
    for (std::uint64_t n : by_cause) sum += n;
    return sum;
  }
  std::uint64_t structural() const {
    std::uint64_t sum = 0;
    for (int c = 0; c < kCutCauses; ++c) sum += is_structural_cause(CutCause(c)) ? by_cause[c] : 0;
    return sum;
  }
};

/// Cuts beyond the mesh's own structure; each is off while its span is empty (or the angle unset).
/// Corner ids are per entry of PolygonMesh::corners, face ids per face: an edge is cut when its
/// two faces disagree (different ids at one of its ends, or different face ids).
/// How close to CutOptions::sharp_angle_degrees a fold counts as that angle: rounding in the
/// normals moves an exact fold by about 1e-14 degrees.
inline constexpr double kFoldToleranceDegrees = 1e-9;

struct CutOptions {
  /// Cut where the normals differ by more than this many degrees; a fold within
  /// kFoldToleranceDegrees of it counts as equal (not cut), so that an exact fold (a regular
  /// 12-gon's 30°) does not fall either way by rounding.
  std::optional<double> sharp_angle_degrees = {};
  std::span<const std::array<VertexId, 2>> user_edges = {};  ///< vertex pairs, either order
  std::span<const std::uint32_t> corner_uv = {}, corner_normal = {};
  std::span<const std::uint32_t> face_material = {}, face_group = {}, face_object = {},
                                 face_smoothing = {}, face_property = {};
  /// Per face, 1 when its corner normals are only flat shading: an edge between two such faces is
  /// no normal seam whatever their normal ids; every other edge is judged by the ids alone.
  std::span<const std::uint8_t> face_flat = {};
};

/// The pairable graph: one node per triangle of the mesh (nodes in face order), one edge per
/// mesh edge that belongs to exactly two faces, both triangles, whose union has four distinct
/// vertices. Every other edge is a cut. Orientation does not matter: two triangles that run along
/// their shared edge the same way are still pairable (counted in inconsistent_edges).
struct PairableGraph {
  std::uint32_t node_count = 0;
  /// The face of each node; empty when every face is a triangle (node t is face t).
  std::pmr::vector<FaceId> node_face;
  /// node_edges[3v + k]: the pairable edge across side k of node v's triangle (its corners k and
  /// k+1), or kNoEdge when that side is a cut.
  std::pmr::vector<EdgeId> node_edges;
  /// Edge e joins nodes edge_ends[2e] and edge_ends[2e + 1]; edges are numbered by their mesh
  /// edge {a, b} in order of (min, max).
  std::pmr::vector<NodeId> edge_ends;
  std::uint64_t mesh_edges = 0;  ///< distinct undirected edges of the mesh
  CutCounts cuts = {};
  std::uint64_t inconsistent_edges = 0;  ///< pairable edges whose triangles run the same way
  bool cubic = false;                    ///< every side of every triangle is pairable
  /// The two nodes of each chosen cut: one made by the caller or the data (user, sharp, the
  /// attribute causes, shape), not by the structure. With the edges, the surface's own
  /// adjacency, so its components and genus are known under cuts.
  std::pmr::vector<NodeId> chosen_cut_ends;
  std::uint64_t inconsistent_chosen_cuts = 0;  ///< of them, those whose triangles run the same way

  std::uint32_t edge_count() const { return static_cast<std::uint32_t>(edge_ends.size() / 2); }
  FaceId face_of(NodeId v) const { return node_face.empty() ? v : node_face[v]; }
};

/// Builds the pairable graph of any polygon mesh, with the extra cuts of `cuts`. Throws MeshError
/// naming the face when a corner is out of range or a face has fewer than three corners, when a
/// span of `cuts` has the wrong size, and for meshes past 32-bit ids. O(C log d) for C corners and
/// maximum vertex degree d, plus O(u log u) for u user edges; no hashing. The vertices are
/// grouped and the edges classified in slices, on up to `threads` threads (0: every core); the
/// graph is the same for any number. The graph's arrays are allocated from `memory` (its scratch
/// from the default resource).
PairableGraph build_pairable_graph(
    const PolygonMesh& mesh, const CutOptions& cuts = {}, std::uint32_t threads = 1,
    std::pmr::memory_resource* memory = std::pmr::get_default_resource());

}  // namespace petersen
