#pragma once
// What kind of surface a polygon mesh is: the figures `petersen info` prints, and the judgement
// whether it is a closed surface the dual and the closed-surface algorithms can work on.
//
// Decisions, for the whole library:
// - Pinched (non-manifold) vertices, whose faces form several fans, are ACCEPTED by the dual
//   builder and the matching algorithms: every edge still has two triangles, so the dual is cubic
//   and bridgeless and the quads are valid. They are reported, and require_closed_surface refuses
//   them only when asked (an algorithm that needs vertex links that are single cycles, such as
//   LRS, asks).
// - Several connected components are ACCEPTED: the dual graph is then disconnected and
//   perfect_matching matches each component on its own. Refused only when asked.
// - Unreferenced vertices are ACCEPTED (reported): they are not part of the surface.
// - Duplicate faces (the same vertices as an earlier face, either orientation) are REFUSED: even
//   when two triangles close up as a two-triangle sphere, the quad of the pair would repeat a
//   corner. drop_duplicate_faces (duplicate_faces.hpp) removes them.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "petersen/mesh/mesh.hpp"

namespace petersen {

/// An undirected edge named by its two vertices, as one face runs along it.
struct EdgeRef {
  VertexId a = 0, b = 0;
  friend bool operator==(const EdgeRef&, const EdgeRef&) = default;
};

/// How many elements have one property, and the first few of them (at most kFirstFew), for
/// messages that name an example.
template <typename T>
struct Findings {
  static constexpr std::size_t kFirstFew = 5;
  std::uint64_t count = 0;
  std::vector<T> first;
  void add(const T& element) {
    if (count++ < kFirstFew) first.push_back(element);
  }
  bool empty() const { return count == 0; }
};

/// Faces with a corner out of range are reported and left out of everything else; every other
/// face, degenerate ones included, counts in the edges, components and Euler characteristic.
struct MeshReport {
  std::uint64_t vertices = 0;             ///< all vertices
  std::uint64_t referenced_vertices = 0;  ///< vertices some face uses
  std::uint64_t edges = 0;                ///< distinct undirected edges
  std::uint64_t faces = 0;
  std::map<std::uint32_t, std::uint64_t> faces_by_arity;
  Findings<FaceId> out_of_range_faces;   ///< a corner names no vertex
  Findings<FaceId> degenerate_faces;     ///< faces repeating a vertex
  Findings<FaceId> duplicate_faces;      ///< same vertices as an earlier face (duplicate_faces)
  Findings<EdgeRef> boundary_edges;      ///< in one face
  std::uint64_t boundary_loops = 0;      ///< connected curves of boundary edges
  Findings<EdgeRef> non_manifold_edges;  ///< in three or more faces
  Findings<EdgeRef> inconsistent_edges;  ///< two faces run along it the same way
  Findings<VertexId> pinched_vertices;   ///< its faces form more than one fan
  Findings<VertexId> unreferenced_vertices;
  std::uint64_t components = 0;  ///< faces sharing an edge are connected
  /// Faces sharing a vertex are connected: fewer than `components` where parts touch only at
  /// pinched vertices.
  std::uint64_t vertex_components = 0;
  std::int64_t euler_characteristic = 0;  ///< referenced vertices - edges + faces
  /// Every component can be oriented so that the two faces of each edge of two faces run along it
  /// in opposite directions.
  bool orientable = true;
  /// Set for a closed (no boundary, edge-manifold), orientable mesh: the sum of the components'
  /// genera from the Euler characteristic, each pinched vertex counted as split into its fans.
  std::optional<std::int64_t> genus;

  /// Every edge in exactly two faces running along it in opposite directions, no face out of
  /// range, degenerate or duplicate, at least one face. Pinched vertices allowed.
  bool closed() const;
};

/// Inspects any polygon mesh without assuming anything of it. O(C log d) for C corners and
/// maximum vertex degree d.
MeshReport inspect_mesh(const PolygonMesh& mesh);

/// A multi-line summary for people.
std::string describe(const MeshReport& report);

struct SurfaceRequirements {
  bool allow_pinched_vertices = true;
  bool allow_several_components = true;
};

/// Throws MeshError naming the first offending element (triangle t, edge (a, b), vertex v) if
/// the mesh is not closed(), or has pinched vertices or several components (a disconnected dual)
/// when those are not allowed. The checks run in the order of MeshReport's findings. O(C log d).
void require_closed_surface(const PolygonMesh& mesh, const SurfaceRequirements& requirements = {});
/// The same judgement on a report already made (no second pass over the mesh). O(1).
void require_closed_surface(const MeshReport& report, const SurfaceRequirements& requirements = {});

}  // namespace petersen
