#include "petersen/dualize/mesh.hpp"

#include <string>

namespace petersen {

void PolygonMesh::add_face(std::span<const VertexId> face_corners) {
  if (corners.size() + face_corners.size() > 0xFFFFFFFFu) {
    throw MeshError("more than 2^32 - 1 face corners");
  }
  if (all_triangles() && face_corners.size() != 3) {
    // The first face that is not a triangle: the implicit starts 0, 3, 6, ... become explicit.
    const std::size_t faces = corners.size() / 3;
    face_start.resize(faces + 1);
    for (std::size_t f = 0; f <= faces; ++f) face_start[f] = static_cast<std::uint32_t>(3 * f);
  }
  corners.insert(corners.end(), face_corners.begin(), face_corners.end());
  if (!all_triangles()) face_start.push_back(static_cast<std::uint32_t>(corners.size()));
}

PolygonMesh to_polygon_mesh(const TriangleMesh& mesh) {
  PolygonMesh polygons;
  polygons.positions = mesh.positions;
  polygons.corners.resize(3 * mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) polygons.corners[3 * t + k] = mesh.triangles[t][k];
  }
  return polygons;
}

TriangleMesh to_triangle_mesh(const PolygonMesh& mesh) {
  TriangleMesh triangles;
  const std::size_t faces = mesh.face_count();
  for (std::size_t f = 0; f < faces; ++f) {
    if (mesh.arity(static_cast<FaceId>(f)) != 3) {
      throw MeshError("face " + std::to_string(f) + " has " +
                      std::to_string(mesh.arity(static_cast<FaceId>(f))) +
                      " corners; only triangles are supported here");
    }
  }
  triangles.positions = mesh.positions;
  triangles.triangles.resize(faces);
  for (std::size_t f = 0; f < faces; ++f) {
    const auto corners = mesh.face(static_cast<FaceId>(f));
    triangles.triangles[f] = {corners[0], corners[1], corners[2]};
  }
  return triangles;
}

}  // namespace petersen
