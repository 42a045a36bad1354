#pragma once
// What kind of surface a polygon mesh is: the figures `petersen info` prints.

#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "petersen/mesh/mesh.hpp"

namespace petersen {

struct MeshReport {
  std::uint64_t vertices = 0;             ///< all vertices
  std::uint64_t referenced_vertices = 0;  ///< vertices some face uses
  std::uint64_t edges = 0;                ///< distinct undirected edges
  std::uint64_t faces = 0;
  std::map<std::uint32_t, std::uint64_t> faces_by_arity;
  std::uint64_t boundary_edges = 0;       ///< in one face
  std::uint64_t boundary_loops = 0;       ///< connected curves of boundary edges
  std::uint64_t non_manifold_edges = 0;   ///< in three or more faces
  std::uint64_t degenerate_faces = 0;     ///< faces repeating a vertex
  std::uint64_t inconsistent_edges = 0;   ///< two faces run along it the same way
  std::uint64_t components = 0;           ///< faces sharing an edge are connected
  std::int64_t euler_characteristic = 0;  ///< referenced vertices - edges + faces
  /// Every component can be oriented so that the two faces of each edge of two faces run along it
  /// in opposite directions.
  bool orientable = true;
  /// Set for a closed (no boundary, edge-manifold), orientable mesh: the sum of the components'
  /// genera from the Euler characteristic (a pinched vertex counts as if it were split).
  std::optional<std::int64_t> genus;
};

/// Inspects any polygon mesh (corners must be in range). O(C log d) for C corners.
MeshReport inspect_mesh(const PolygonMesh& mesh);

/// A multi-line summary for people.
std::string describe(const MeshReport& report);

}  // namespace petersen
