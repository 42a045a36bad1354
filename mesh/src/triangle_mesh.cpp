#include <string>

#include "petersen/mesh/mesh.hpp"
#include "petersen/mesh/surface_check.hpp"

namespace petersen {

PolygonMesh to_polygon_mesh(const TriangleMesh& mesh) {
  PolygonMesh polygons;
  polygons.positions = mesh.positions;
  polygons.corners.resize(3 * mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) polygons.corners[3 * t + k] = mesh.triangles[t][k];
  }
  return polygons;
}

TriangleMesh::TriangleMesh(const PolygonMesh& mesh) {
  const std::size_t faces = mesh.face_count();
  for (std::size_t f = 0; f < faces; ++f) {
    if (mesh.arity(static_cast<FaceId>(f)) != 3) {
      throw MeshError("face " + std::to_string(f) + " has " +
                      std::to_string(mesh.arity(static_cast<FaceId>(f))) +
                      " corners; only triangles are supported here");
    }
  }
  positions = mesh.positions;
  triangles.resize(faces);
  for (std::size_t f = 0; f < faces; ++f) {
    const auto corners = mesh.face(static_cast<FaceId>(f));
    triangles[f] = {corners[0], corners[1], corners[2]};
  }
}

TriangleMesh to_triangle_mesh(const PolygonMesh& mesh) {
  return TriangleMesh(mesh);
}

MeshReport inspect_surface(const TriangleMesh& mesh) {
  return inspect_mesh(to_polygon_mesh(mesh));
}

void require_closed_surface(const TriangleMesh& mesh, const SurfaceRequirements& requirements) {
  require_closed_surface(to_polygon_mesh(mesh), requirements);
}

}  // namespace petersen
