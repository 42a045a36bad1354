#pragma once
// Is a triangle mesh a closed surface the graph algorithms can work on? What is its genus?
//
// Decisions, for the whole library:
// - Pinched (non-manifold) vertices, whose triangles form several fans, are ACCEPTED by the dual
//   builder and the matching algorithms: every edge still has two triangles, so the dual is cubic
//   and bridgeless and the quads are valid. They are reported, and require_closed_surface refuses
//   them only when asked (an algorithm that needs vertex links that are single cycles, such as
//   LRS, asks).
// - Several connected components are ACCEPTED: the dual graph is then disconnected and
//   perfect_matching matches each component on its own. Refused only when asked.
// - Unreferenced vertices are ACCEPTED (reported): they are not part of the surface.
// - Duplicate triangles (the same three vertices, either orientation) are REFUSED: even when they
//   close up as a two-triangle sphere, the quad of the pair would repeat a corner.

#include <optional>
#include <string>
#include <vector>

#include "petersen/mesh/mesh.hpp"

namespace petersen {

/// An undirected edge named by its two vertices, as one triangle runs along it.
struct EdgeRef {
  VertexId a = 0, b = 0;
  friend bool operator==(const EdgeRef&, const EdgeRef&) = default;
};

/// How many elements have one problem, and the first few of them (at most kFirstFew).
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

struct SurfaceReport {
  std::uint32_t vertices = 0;  ///< referenced vertices
  std::uint64_t edges = 0;     ///< distinct undirected edges of the valid triangles
  std::uint32_t faces = 0;     ///< all triangles
  /// Connected components of the surface: triangles sharing a vertex are connected.
  std::uint32_t components = 0;
  /// Components of the dual graph: triangles sharing an edge are connected. More than
  /// `components` when parts touch only at pinched vertices.
  std::uint32_t edge_components = 0;
  std::int64_t euler_characteristic = 0;  ///< vertices - edges + valid triangles

  Findings<FaceId> out_of_range_triangles;  ///< a corner names no vertex
  Findings<FaceId> degenerate_triangles;    ///< a repeated corner
  Findings<FaceId> duplicate_triangles;     ///< same vertex set as an earlier triangle
  Findings<EdgeRef> boundary_edges;         ///< in one triangle only
  Findings<EdgeRef> non_manifold_edges;     ///< in more than two triangles
  Findings<EdgeRef> inconsistent_edges;     ///< two triangles run along it the same way
  Findings<VertexId> pinched_vertices;      ///< its triangles form more than one fan
  Findings<VertexId> unreferenced_vertices;

  /// Every edge in exactly two triangles running along it in opposite directions, no invalid,
  /// degenerate or duplicate triangle, at least one triangle. Pinched vertices allowed.
  bool closed() const;
  /// Sum of the genera of the edge components, computed with each pinched vertex split into its
  /// fans (so a pinched vertex does not change it). Set when closed().
  std::optional<std::uint32_t> genus;
};

/// Inspects the mesh without assuming anything of it. O(F log d) for maximum vertex degree d.
SurfaceReport inspect_surface(const TriangleMesh& mesh);

/// A multi-line human-readable summary of the report (counts, first elements of each problem).
std::string describe(const SurfaceReport& report);

struct SurfaceRequirements {
  bool allow_pinched_vertices = true;
  bool allow_several_components = true;
};

/// Throws MeshError naming the first offending element (triangle t, edge (a, b), vertex v) if
/// the mesh is not a closed surface, or has pinched vertices or several edge components (a
/// disconnected dual) when those are not allowed. The checks run in the order of SurfaceReport's
/// findings. O(F log d).
void require_closed_surface(const TriangleMesh& mesh, const SurfaceRequirements& requirements = {});
/// The same judgement on a report already made (no second pass over the mesh). O(1).
void require_closed_surface(const SurfaceReport& report,
                            const SurfaceRequirements& requirements = {});

}  // namespace petersen
