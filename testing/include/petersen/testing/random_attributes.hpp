#pragma once
// Random attributes (texture coordinates, normals, materials, groups, properties) on random
// polygon meshes, for property tests of the readers, the writers and everything that carries
// attributes through (target petersen::testing):
//
//   RC_GTEST_PROP(Io, ObjRoundTrip, ()) {
//     const PolygonMesh mesh = *petersen::testing::meshes_with_attributes(AttributeSet::obj);
//     ...
//   }

#include <rapidcheck.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "petersen/mesh/mesh.hpp"
#include "petersen/testing/arbitrary.hpp"

namespace petersen::testing {

/// Which attributes a generated mesh carries: exactly what one format holds (so that writing it
/// in that format and reading it back loses nothing), or every kind any format holds.
enum class AttributeSet { off, obj, ply, all };

/// x rounded to the nearest float.
[[gnu::noinline]] inline double round_to_float(double x) {
  return static_cast<float>(x);
}

namespace detail {

/// The draws the generators make, from one seeded engine in a fixed order.
struct Draws {
  std::mt19937_64 random;

  bool chance(double p) { return std::uniform_real_distribution<double>(0, 1)(random) < p; }
  std::uint32_t below(std::uint32_t n) {
    return static_cast<std::uint32_t>(
        std::uniform_int_distribution<std::uint64_t>(0, n - 1)(random));
  }
  double real(double from, double to) {
    return std::uniform_real_distribution<double>(from, to)(random);
  }
};

inline std::size_t first_corner(const PolygonMesh& mesh, std::size_t f) {
  return mesh.all_triangles() ? 3 * f : std::size_t{mesh.face_start[f]};
}

/// Corner texture coordinates: OBJ shares them and leaves some corners without; PLY alone gives
/// every corner of a face one, or none. `three` allows u v w.
inline void add_corner_texcoords(PolygonMesh& mesh, bool ply_only, bool three, Draws& draw) {
  MeshAttributes& a = mesh.attributes;
  const bool floats = draw.chance(0.5);  // all float-exact: PLY writes them as float then
  a.texcoord_components = three && draw.chance(0.5) ? 3 : 2;
  const std::uint32_t count = 1 + draw.below(12);
  for (std::uint32_t t = 0; t < count; ++t) {
    std::array<double, 3> uv{draw.real(-1, 2), draw.real(-1, 2),
                             a.texcoord_components == 3 ? draw.real(0, 1) : 0};
    if (floats) {
      for (double& x : uv) x = static_cast<float>(x);
    }
    a.texcoords.push_back(uv);
  }
  a.corner_texcoord.assign(mesh.corners.size(), kNoAttribute);
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const bool face_has = draw.chance(0.8);
    const std::size_t first = first_corner(mesh, f);
    for (std::size_t k = first; k < first + mesh.arity(FaceId(f)); ++k) {
      if (ply_only) {
        if (face_has) a.corner_texcoord[k] = draw.below(count);
      } else if (draw.chance(0.9)) {
        a.corner_texcoord[k] = draw.below(count);
      }
    }
  }
}

/// OBJ's corner normals: smooth (each vertex's corners share one) or per corner, some without.
inline void add_corner_normals(PolygonMesh& mesh, Draws& draw) {
  MeshAttributes& a = mesh.attributes;
  const std::uint32_t count = 1 + draw.below(8);
  for (std::uint32_t n = 0; n < count; ++n) {
    a.normals.push_back({draw.real(-1, 1), draw.real(-1, 1), draw.real(-1, 1)});
  }
  a.corner_normal.assign(mesh.corners.size(), kNoAttribute);
  if (draw.chance(0.3)) {
    for (std::size_t k = 0; k < mesh.corners.size(); ++k) {
      a.corner_normal[k] = mesh.corners[k] % count;
    }
  } else {
    const double share = draw.chance(0.5) ? 1.0 : 0.8;  // of the corners that get a normal
    for (std::uint32_t& normal : a.corner_normal) {
      if (draw.chance(share)) normal = draw.below(count);
    }
  }
}

/// OBJ's named face attributes (usemtl, g, o), each present or not, in runs of faces as in a
/// real file; some names hold a space.
inline void add_face_names(PolygonMesh& mesh, Draws& draw) {
  MeshAttributes& a = mesh.attributes;
  const std::pair<std::vector<std::string>*, std::pmr::vector<std::uint32_t>*> named[3] = {
      {&a.material_names, &a.face_material},
      {&a.group_names, &a.face_group},
      {&a.object_names, &a.face_object}};
  for (const auto& [names, values] : named) {
    if (!draw.chance(0.5)) continue;
    const std::uint32_t count = 1 + draw.below(4);
    for (std::uint32_t n = 0; n < count; ++n) {
      names->push_back((n % 2 ? "name " : "n") + std::to_string(n));
    }
    values->assign(mesh.face_count(), kNoAttribute);
    std::uint32_t value = kNoAttribute;
    for (std::uint32_t& v : *values) {
      if (draw.chance(0.2)) value = draw.chance(0.1) ? kNoAttribute : draw.below(count);
      v = value;
    }
  }
}

/// Every OBJ attribute but texture coordinates and colours, each present or not.
inline void add_obj_attributes(PolygonMesh& mesh, Draws& draw) {
  MeshAttributes& a = mesh.attributes;
  if (draw.chance(0.5)) add_corner_normals(mesh, draw);
  add_face_names(mesh, draw);
  if (draw.chance(0.5)) {
    a.face_smoothing.assign(mesh.face_count(), 0);
    for (std::uint32_t& s : a.face_smoothing) s = draw.below(4);
  }
  if (draw.chance(0.5)) a.material_libraries = {"scene.mtl", "other lib.mtl"};
}

/// A column of `size` values of the type, each within the type's range.
inline PropertyColumn random_column(std::string name, ScalarType type, std::size_t size,
                                    Draws& draw) {
  PropertyColumn c{std::move(name), type, {}};
  for (std::size_t i = 0; i < size; ++i) {
    switch (type) {
      case ScalarType::int8:
        c.values.push_back(double(draw.below(256)) - 128);
        break;
      case ScalarType::uint8:
        c.values.push_back(draw.below(256));
        break;
      case ScalarType::int16:
        c.values.push_back(double(draw.below(65536)) - 32768);
        break;
      case ScalarType::uint16:
        c.values.push_back(draw.below(65536));
        break;
      case ScalarType::int32:
        c.values.push_back(double(draw.below(0xFFFFFFFFu)) - 2147483647.0);
        break;
      case ScalarType::uint32:
        c.values.push_back(draw.below(0xFFFFFFFFu));
        break;
      case ScalarType::float32:
        c.values.push_back(static_cast<float>(draw.real(-10, 10)));
        break;
      case ScalarType::float64:
        c.values.push_back(draw.real(-1e6, 1e6));
        break;
    }
  }
  return c;
}

/// red, green, blue and, with `alpha`, alpha columns of the type.
inline void add_colour(std::vector<PropertyColumn>& columns, std::size_t size, bool alpha,
                       ScalarType type, Draws& draw) {
  for (const char* name : {"red", "green", "blue", "alpha"}) {
    if (std::string(name) == "alpha" && !alpha) break;
    columns.push_back(random_column(name, type, size, draw));
  }
}

/// PLY: float positions (rounded to float) or not, and up to three vertex and three face
/// properties of random types.
inline void add_ply_properties(PolygonMesh& mesh, Draws& draw) {
  MeshAttributes& a = mesh.attributes;
  if (draw.chance(0.3)) {
    a.position_type = ScalarType::float32;
    // One call per coordinate: GCC 12.2 at -O3 vectorizes the plain loop over the vertices'
    // coordinates into one whose epilogue rounds only z of the last vertices.
    for (auto& p : mesh.positions) {
      for (double& x : p) x = round_to_float(x);
    }
  }
  for (auto* columns : {&a.vertex_properties, &a.face_properties}) {
    const std::size_t size =
        columns == &a.vertex_properties ? mesh.positions.size() : mesh.face_count();
    const std::uint32_t count = draw.below(4);
    for (std::uint32_t c = 0; c < count; ++c) {
      // Built by appends: GCC 12 gives a false -Wstringop-overflow on "p" + std::to_string(c).
      std::string name(1, 'p');
      name.append(std::to_string(c));
      columns->push_back(random_column(std::move(name), ScalarType(draw.below(8)), size, draw));
    }
  }
}

/// OFF: vertex normals, texture coordinates s t, vertex and face colours (uint8 or float32,
/// with or without alpha), each present or not.
inline void add_off_properties(PolygonMesh& mesh, Draws& draw) {
  MeshAttributes& a = mesh.attributes;
  const std::size_t vertices = mesh.positions.size();
  if (draw.chance(0.4)) {
    for (const char* name : {"nx", "ny", "nz"}) {
      a.vertex_properties.push_back(random_column(name, ScalarType::float32, vertices, draw));
    }
  }
  if (draw.chance(0.4)) {
    for (const char* name : {"s", "t"}) {
      a.vertex_properties.push_back(random_column(name, ScalarType::float32, vertices, draw));
    }
  }
  for (auto* columns : {&a.vertex_properties, &a.face_properties}) {
    if (!draw.chance(0.5)) continue;
    const std::size_t size = columns == &a.vertex_properties ? vertices : mesh.face_count();
    const bool alpha = draw.chance(0.5);
    add_colour(*columns, size, alpha, draw.chance(0.5) ? ScalarType::uint8 : ScalarType::float32,
               draw);
  }
}

}  // namespace detail

/// Adds random attributes of the set to the mesh, drawn from the seed; each kind is present or
/// absent at random, and values are ones the set's format writes exactly (PLY values fit their
/// type; a float PLY's positions are rounded to float). check_attributes accepts the result.
inline void add_random_attributes(PolygonMesh& mesh, AttributeSet set, std::uint64_t seed) {
  detail::Draws draw{std::mt19937_64(seed)};
  const bool off = set == AttributeSet::off || set == AttributeSet::all;
  const bool obj = set == AttributeSet::obj || set == AttributeSet::all;
  const bool ply = set == AttributeSet::ply || set == AttributeSet::all;
  if ((obj || ply) && draw.chance(0.6)) {
    detail::add_corner_texcoords(mesh, ply && !obj, obj && set != AttributeSet::all, draw);
  }
  if (obj) detail::add_obj_attributes(mesh, draw);
  if (ply) {
    detail::add_ply_properties(mesh, draw);
  } else if (off) {
    detail::add_off_properties(mesh, draw);
  } else if (obj && draw.chance(0.5)) {
    detail::add_colour(mesh.attributes.vertex_properties, mesh.positions.size(), false,
                       ScalarType::float32, draw);
  }
}

/// Random polygon meshes (mixed_meshes) with random attributes of the set.
inline rc::Gen<PolygonMesh> meshes_with_attributes(AttributeSet set) {
  return rc::gen::apply(
      [set](PolygonMesh mesh, std::uint64_t seed) {
        add_random_attributes(mesh, set, seed);
        return mesh;
      },
      mixed_meshes(), rc::gen::arbitrary<std::uint64_t>());
}

}  // namespace petersen::testing
