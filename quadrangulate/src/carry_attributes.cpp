#include "carry_attributes.hpp"

#include <bit>
#include <cmath>
#include <map>
#include <stdexcept>
#include <vector>

#include "petersen/quadrangulate/quadrangulate.hpp"
#include "petersen/quadrangulate/stages.hpp"

namespace petersen::quad_detail {

namespace {

int blend_size(const Blend& blend) {
  int n = 0;
  while (n < 4 && blend[n] != kNoAttribute) ++n;
  return n;
}

// Corner values of one kind (texture coordinates or normals): the blended corners' indices,
// kept when they all agree, else their average appended to `values` (shared with an equal one
// appended before).
class CornerValues {
 public:
  CornerValues(const std::pmr::vector<std::uint32_t>& index,
               std::pmr::vector<std::array<double, 3>>& values, bool unit)
      : index_(index), values_(values), unit_(unit) {}

  std::uint32_t blended(const Blend& blend) {
    const int n = blend_size(blend);
    const std::uint32_t first = index_[blend[0]];
    bool same = true;
    for (int k = 0; k < n; ++k) {
      if (index_[blend[k]] == kNoAttribute) return kNoAttribute;
      same &= index_[blend[k]] == first;
    }
    if (same) return first;
    std::array<double, 3> sum{0, 0, 0};
    for (int k = 0; k < n; ++k)
      for (int d = 0; d < 3; ++d) sum[d] += values_[index_[blend[k]]][d];
    for (double& x : sum) x /= n;
    if (unit_) {
      const double length = std::sqrt(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]);
      if (length > 0)
        for (double& x : sum) x /= length;
    }
    const std::array<std::uint64_t, 3> key{std::bit_cast<std::uint64_t>(sum[0]),
                                           std::bit_cast<std::uint64_t>(sum[1]),
                                           std::bit_cast<std::uint64_t>(sum[2])};
    const auto [at, added] = appended_.try_emplace(key, std::uint32_t(values_.size()));
    if (added) values_.push_back(sum);
    return at->second;
  }

 private:
  const std::pmr::vector<std::uint32_t>& index_;
  std::pmr::vector<std::array<double, 3>>& values_;
  bool unit_;
  std::map<std::array<std::uint64_t, 3>, std::uint32_t> appended_;
};

}  // namespace

double held_as(ScalarType type, double value) {
  switch (type) {
    case ScalarType::float64:
      return value;
    case ScalarType::float32:
      return static_cast<float>(value);
    default:
      return std::round(value);
  }
}

namespace {

// A derived mesh's attributes before any per-element value: the tables its indices point into,
// those of the mesh before (blends append to the value tables).
MeshAttributes shared_tables(const MeshAttributes& before, std::pmr::memory_resource* memory) {
  MeshAttributes after(memory);
  after.texcoords = before.texcoords;
  after.texcoord_components = before.texcoord_components;
  after.normals = before.normals;
  after.material_names = before.material_names;
  after.group_names = before.group_names;
  after.object_names = before.object_names;
  after.material_libraries = before.material_libraries;
  return after;
}

// Texture coordinates, then normals (renormalised): corner c blended by corner_from[c].
void blend_corners(const MeshAttributes& before, std::span<const Blend> corner_from,
                   MeshAttributes& after) {
  auto corners = [&](const std::pmr::vector<std::uint32_t>& index,
                     std::pmr::vector<std::uint32_t>& out,
                     std::pmr::vector<std::array<double, 3>>& values, bool unit) {
    if (index.empty()) return;
    CornerValues blend(index, values, unit);
    out.resize(corner_from.size());
    for (std::size_t c = 0; c < corner_from.size(); ++c) out[c] = blend.blended(corner_from[c]);
  };
  corners(before.corner_texcoord, after.corner_texcoord, after.texcoords, false);
  corners(before.corner_normal, after.corner_normal, after.normals, true);
}

// Face f takes every face value of before's face face_of[f].
void copy_face_values(const MeshAttributes& before, std::span<const FaceId> face_of,
                      MeshAttributes& after) {
  auto per_face = [&](const std::pmr::vector<std::uint32_t>& in,
                      std::pmr::vector<std::uint32_t>& out) {
    if (in.empty()) return;
    out.resize(face_of.size());
    for (std::size_t f = 0; f < face_of.size(); ++f) out[f] = in[face_of[f]];
  };
  per_face(before.face_material, after.face_material);
  per_face(before.face_group, after.face_group);
  per_face(before.face_object, after.face_object);
  per_face(before.face_smoothing, after.face_smoothing);
  for (const PropertyColumn& column : before.face_properties) {
    PropertyColumn& out = after.face_properties.emplace_back();
    out.name = column.name;
    out.type = column.type;
    out.values.resize(face_of.size());
    for (std::size_t f = 0; f < face_of.size(); ++f) out.values[f] = column.values[face_of[f]];
  }
}

// The vertices before keep their properties; new vertex i takes the average of those its blend
// names, held as the column's type.
void blend_vertex_properties(const MeshAttributes& before, std::size_t vertices_before,
                             std::span<const Blend> new_vertices, MeshAttributes& after) {
  for (const PropertyColumn& column : before.vertex_properties) {
    PropertyColumn& out = after.vertex_properties.emplace_back(column);
    out.values.resize(vertices_before + new_vertices.size());
    for (std::size_t i = 0; i < new_vertices.size(); ++i) {
      const int n = blend_size(new_vertices[i]);
      double sum = 0;
      for (int k = 0; k < n; ++k) sum += column.values[new_vertices[i][k]];
      out.values[vertices_before + i] = held_as(column.type, sum / n);
    }
  }
}

}  // namespace

MeshAttributes derived_attributes(const MeshAttributes& before, std::size_t vertices_before,
                                  std::span<const FaceId> face_of,
                                  std::span<const Blend> corner_from,
                                  std::span<const Blend> new_vertices,
                                  std::pmr::memory_resource* memory) {
  MeshAttributes after = shared_tables(before, memory);
  blend_corners(before, corner_from, after);
  copy_face_values(before, face_of, after);
  blend_vertex_properties(before, vertices_before, new_vertices, after);
  return after;
}

}  // namespace petersen::quad_detail

namespace petersen {

MeshAttributes attributes_of_pairs(const PolygonMesh& input, const PolygonMesh& out,
                                   std::span<const std::array<FaceId, 2>> sources) {
  using quad_detail::Blend, quad_detail::derived_attributes;
  const MeshAttributes& a = input.attributes;
  std::vector<FaceId> face_of;
  std::pmr::vector<Blend> corner_from;
  if (a.has_face_attributes() || a.has_corner_attributes()) {
    face_of.resize(out.face_count());
    for (FaceId o = 0; o < out.face_count(); ++o) {
      if (sources[o][0] == kNoFace) {
        throw std::logic_error(
            "internal error: an output face without an input face carries "
            "attributes");
      }
      face_of[o] = sources[o][0];
    }
  }
  if (a.has_corner_attributes()) {
    corner_from.reserve(out.corners.size());
    auto first_corner = [&](FaceId f) {
      return input.all_triangles() ? 3 * f : input.face_start[f];
    };
    for (FaceId o = 0; o < out.face_count(); ++o) {
      const auto [f, g] = sources[o];
      const std::uint32_t first_f = first_corner(f);
      if (g == kNoFace) {  // the face as it was
        for (std::uint32_t k = 0; k < out.arity(o); ++k) {
          corner_from.push_back({first_f + k, kNoAttribute, kNoAttribute, kNoAttribute});
        }
        continue;
      }
      const std::uint32_t first_g = first_corner(g);
      for (VertexId v : out.face(o)) {
        std::uint32_t corner = kNoAttribute;
        for (std::uint32_t k = 0; k < 3 && corner == kNoAttribute; ++k) {
          if (input.corners[first_f + k] == v) corner = first_f + k;
        }
        for (std::uint32_t k = 0; k < 3 && corner == kNoAttribute; ++k) {
          if (input.corners[first_g + k] == v) corner = first_g + k;
        }
        corner_from.push_back({corner, kNoAttribute, kNoAttribute, kNoAttribute});
      }
    }
  }
  // The output's vertices are the input's so far (the input's positions may have moved there).
  return derived_attributes(a, out.positions.size(), face_of, corner_from, {}, out.memory());
}

}  // namespace petersen
