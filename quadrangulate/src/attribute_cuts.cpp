#include "attribute_cuts.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "petersen/mesh/vec3.hpp"

namespace petersen::quad_detail {

namespace {

// A double as a key that is equal exactly when the values are (+0 and -0 alike).
std::uint64_t key_of(double x) {
  return std::bit_cast<std::uint64_t>(x == 0 ? 0.0 : x);
}

// For values indexed 0..n-1: the id of each, the smallest index holding an equal value. Empty
// when no two values are equal, so that the indices serve as ids as they are.
template <class Less, class Equal>
std::vector<std::uint32_t> first_of_equal(std::size_t n, Less less, Equal equal) {
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), less);
  std::vector<std::uint32_t> id;
  for (std::size_t i = 1; i < n; ++i) {
    if (!equal(order[i - 1], order[i])) continue;
    if (id.empty()) {
      id.resize(n);
      std::iota(id.begin(), id.end(), 0u);
    }
    id[order[i]] = id[order[i - 1]];  // stable: the run's first is its smallest index
  }
  return id;
}

std::vector<std::uint32_t> ids_of_points(const std::pmr::vector<std::array<double, 3>>& points) {
  auto key = [&](std::uint32_t i) {
    const auto& p = points[i];
    return std::array<std::uint64_t, 3>{key_of(p[0]), key_of(p[1]), key_of(p[2])};
  };
  return first_of_equal(
      points.size(), [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); },
      [&](std::uint32_t a, std::uint32_t b) { return key(a) == key(b); });
}

std::vector<std::uint32_t> ids_of_names(const std::vector<std::string>& names) {
  return first_of_equal(
      names.size(), [&](std::uint32_t a, std::uint32_t b) { return names[a] < names[b]; },
      [&](std::uint32_t a, std::uint32_t b) { return names[a] == names[b]; });
}

// `indices` (into a table whose equal entries have the ids `id_of`) as ids: the indices
// themselves when the table has no repeated value, else a renumbered copy in `storage`.
std::span<const std::uint32_t> by_value(const std::pmr::vector<std::uint32_t>& indices,
                                        const std::vector<std::uint32_t>& id_of,
                                        std::pmr::vector<std::uint32_t>& storage) {
  if (id_of.empty()) return indices;
  storage.resize(indices.size());
  for (std::size_t i = 0; i < indices.size(); ++i) {
    storage[i] = indices[i] == kNoAttribute ? kNoAttribute : id_of[indices[i]];
  }
  return storage;
}

// One id per face for its row of property values: faces with equal rows share the id.
std::pmr::vector<std::uint32_t> face_property_ids(const std::vector<PropertyColumn>& columns,
                                                  std::size_t faces) {
  auto less = [&](std::uint32_t a, std::uint32_t b) {
    for (const PropertyColumn& c : columns) {
      const std::uint64_t x = key_of(c.values[a]), y = key_of(c.values[b]);
      if (x != y) return x < y;
    }
    return false;
  };
  auto equal = [&](std::uint32_t a, std::uint32_t b) { return !less(a, b) && !less(b, a); };
  const std::vector<std::uint32_t> id = first_of_equal(faces, less, equal);
  std::pmr::vector<std::uint32_t> ids(faces);
  for (std::uint32_t f = 0; f < faces; ++f) ids[f] = id.empty() ? f : id[f];
  return ids;
}

// Whether every corner of triangle f (corners first..first+2) has a normal along the triangle's own
// geometric normal: the triangle is flat shaded, so a seam of normals around it is shading, not a
// feature of the surface. Exported normals are rounded (six decimals at most, often four), hence
// the tolerance, an angle of about 0.8°. A degenerate triangle has no normal of its own: not flat.
bool flat_shaded(const PolygonMesh& mesh, std::size_t first) {
  const MeshAttributes& a = mesh.attributes;
  const auto& p0 = mesh.positions[mesh.corners[first]];
  const auto& p1 = mesh.positions[mesh.corners[first + 1]];
  const auto& p2 = mesh.positions[mesh.corners[first + 2]];
  const vec3::Vec3 face_normal = vec3::cross(vec3::sub(p1, p0), vec3::sub(p2, p0));
  const double face_length = std::sqrt(vec3::dot(face_normal, face_normal));
  if (!(face_length > 0) || !std::isfinite(face_length)) return false;
  for (std::size_t c = first; c < first + 3; ++c) {
    if (a.corner_normal[c] == kNoAttribute) return false;
    const vec3::Vec3& n = a.normals[a.corner_normal[c]];
    const double length = std::sqrt(vec3::dot(n, n));
    if (!(vec3::dot(n, face_normal) >= kFlatShadingCosine * length * face_length)) return false;
  }
  return true;
}

// Per face: a flat-shaded triangle, whose normal seams with another such are shading only. Empty
// when there is none. O(C).
std::vector<std::uint8_t> flat_faces(const PolygonMesh& mesh) {
  std::vector<std::uint8_t> flat;
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    if (mesh.arity(f) != 3) continue;
    const std::size_t first = mesh.all_triangles() ? 3 * std::size_t{f} : mesh.face_start[f];
    if (!flat_shaded(mesh, first)) continue;
    if (flat.empty()) flat.assign(mesh.face_count(), 0);
    flat[f] = 1;
  }
  return flat;
}

}  // namespace

CutOptions attribute_cuts(const PolygonMesh& mesh, const QuadOptions& options,
                          AttributeCutIds& ids) {
  bool crossed[kCutCauses] = {};
  for (CutCause cause : options.cross) {
    if (!is_attribute_cause(cause)) {
      throw std::invalid_argument(
          "cross: " + std::string(to_string(cause)) +
          " cannot be crossed; the mesh's attributes make the cuts that can: uv_seam, "
          "normal_seam, material, group, object, smoothing, face_property");
    }
    crossed[static_cast<int>(cause)] = true;
  }
  CutOptions cuts = options.cuts;
  const MeshAttributes& a = mesh.attributes;
  if (a.empty()) return cuts;
  check_attributes(mesh);  // here once for all that reads the attributes, the carrying too
  auto wanted = [&](std::span<const std::uint32_t> given, std::size_t have, CutCause cause) {
    return given.empty() && have > 0 && !crossed[static_cast<int>(cause)];
  };
  if (wanted(cuts.corner_uv, a.corner_texcoord.size(), CutCause::uv_seam)) {
    cuts.corner_uv = by_value(a.corner_texcoord, ids_of_points(a.texcoords), ids.corner_uv);
  }
  if (wanted(cuts.corner_normal, a.corner_normal.size(), CutCause::normal_seam)) {
    cuts.corner_normal = by_value(a.corner_normal, ids_of_points(a.normals), ids.corner_normal);
    ids.face_flat = flat_faces(mesh);
    cuts.face_flat = ids.face_flat;
  }
  if (wanted(cuts.face_material, a.face_material.size(), CutCause::material)) {
    cuts.face_material =
        by_value(a.face_material, ids_of_names(a.material_names), ids.face_material);
  }
  if (wanted(cuts.face_group, a.face_group.size(), CutCause::group)) {
    cuts.face_group = by_value(a.face_group, ids_of_names(a.group_names), ids.face_group);
  }
  if (wanted(cuts.face_object, a.face_object.size(), CutCause::object)) {
    cuts.face_object = by_value(a.face_object, ids_of_names(a.object_names), ids.face_object);
  }
  if (wanted(cuts.face_smoothing, a.face_smoothing.size(), CutCause::smoothing)) {
    cuts.face_smoothing = a.face_smoothing;
  }
  if (wanted(cuts.face_property, a.face_properties.size(), CutCause::face_property)) {
    ids.face_property = face_property_ids(a.face_properties, mesh.face_count());
    cuts.face_property = ids.face_property;
  }
  return cuts;
}

}  // namespace petersen::quad_detail
