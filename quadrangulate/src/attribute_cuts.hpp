#pragma once
// The cuts a mesh's own attributes make (QuadOptions::cross): seams of texture coordinates and
// normals, borders of materials, groups, objects, smoothing groups and face properties, as the
// per-corner and per-face ids CutOptions compares.

#include <cstdint>

#include "petersen/quadrangulate/quadrangulate.hpp"

namespace petersen::quad_detail {

/// The ids made for the cuts, owned here; the CutOptions returned points into them.
struct AttributeCutIds {
  std::pmr::vector<std::uint32_t> corner_uv, corner_normal, face_material, face_group, face_object,
      face_property;
  std::vector<std::uint8_t> face_flat;
};

/// `options.cuts` with each attribute cut of `mesh` added where the caller left its span empty
/// and did not name its cause in options.cross. Values are compared, not indices: equal texture
/// coordinates or normals, equal names and equal property rows get one id (-0 equals +0); two
/// flat-shaded triangles (kFlatShadingCosine) make no normal seam (CutOptions::face_flat), so flat
/// shading only takes seams away. Checks the attributes first (check_attributes, MeshError) and
/// options.cross (std::invalid_argument). O(C + F log F + T log T) for C corners, F faces, T
/// texture coordinates and normals; nothing when the mesh has no attributes.
CutOptions attribute_cuts(const PolygonMesh& mesh, const QuadOptions& options,
                          AttributeCutIds& ids);

}  // namespace petersen::quad_detail
