#include "petersen/mesh/mesh.hpp"

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

namespace {

/// An attribute array is empty (the mesh has none) or has one entry per element; a property
/// column always has one per element.
void check_size(const std::string& what, std::size_t size, std::size_t expected, const char* per,
                bool may_be_empty = true) {
  if ((size != 0 || !may_be_empty) && size != expected) {
    throw MeshError("attribute " + what + " has " + std::to_string(size) +
                    " entries; the mesh has " + std::to_string(expected) + " " + per);
  }
}

void check_indices(const char* what, const std::pmr::vector<std::uint32_t>& indices,
                   std::size_t bound) {
  for (std::size_t i = 0; i < indices.size(); ++i) {
    if (indices[i] != kNoAttribute && indices[i] >= bound) {
      throw MeshError(std::string{"attribute "} + what + "[" + std::to_string(i) +
                      "] = " + std::to_string(indices[i]) + " is out of range (" +
                      std::to_string(bound) + " values)");
    }
  }
}

}  // namespace

void check_attributes(const PolygonMesh& mesh) {
  const MeshAttributes& a = mesh.attributes;
  const std::size_t corners = mesh.corners.size(), faces = mesh.face_count();
  check_size("corner_texcoord", a.corner_texcoord.size(), corners, "corners");
  check_size("corner_normal", a.corner_normal.size(), corners, "corners");
  check_size("face_material", a.face_material.size(), faces, "faces");
  check_size("face_group", a.face_group.size(), faces, "faces");
  check_size("face_object", a.face_object.size(), faces, "faces");
  check_size("face_smoothing", a.face_smoothing.size(), faces, "faces");
  for (const PropertyColumn& column : a.vertex_properties) {
    check_size("vertex property " + column.name, column.values.size(), mesh.positions.size(),
               "vertices", false);
  }
  for (const PropertyColumn& column : a.face_properties) {
    check_size("face property " + column.name, column.values.size(), faces, "faces", false);
  }
  check_indices("corner_texcoord", a.corner_texcoord, a.texcoords.size());
  check_indices("corner_normal", a.corner_normal, a.normals.size());
  check_indices("face_material", a.face_material, a.material_names.size());
  check_indices("face_group", a.face_group, a.group_names.size());
  check_indices("face_object", a.face_object, a.object_names.size());
}

}  // namespace petersen
