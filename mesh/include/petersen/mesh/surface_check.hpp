#pragma once
// The mesh inspection on a TriangleMesh, for lrs/ (with its tests), which takes TriangleMesh:
// inspect_mesh and require_closed_surface on the mesh as a PolygonMesh.

#include "petersen/mesh/mesh_report.hpp"

namespace petersen {

using SurfaceReport = MeshReport;

/// inspect_mesh(to_polygon_mesh(mesh)). O(F log d).
MeshReport inspect_surface(const TriangleMesh& mesh);

/// require_closed_surface(to_polygon_mesh(mesh), requirements). O(F log d).
void require_closed_surface(const TriangleMesh& mesh, const SurfaceRequirements& requirements = {});

}  // namespace petersen
