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

#include <cmath>
#include <cstdint>
#include <random>
#include <string>

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

/// Adds random attributes of the set to the mesh, drawn from the seed; each kind is present or
/// absent at random, and values are ones the set's format writes exactly (PLY values fit their
/// type; a float PLY's positions are rounded to float). check_attributes accepts the result.
inline void add_random_attributes(PolygonMesh& mesh, AttributeSet set, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  auto chance = [&](double p) { return std::uniform_real_distribution<double>(0, 1)(random) < p; };
  auto below = [&](std::uint32_t n) {
    return static_cast<std::uint32_t>(
        std::uniform_int_distribution<std::uint64_t>(0, n - 1)(random));
  };
  auto real = [&](double from, double to) {
    return std::uniform_real_distribution<double>(from, to)(random);
  };
  const bool off = set == AttributeSet::off || set == AttributeSet::all;
  const bool obj = set == AttributeSet::obj || set == AttributeSet::all;
  const bool ply = set == AttributeSet::ply || set == AttributeSet::all;
  MeshAttributes& a = mesh.attributes;
  const std::size_t corners = mesh.corners.size(), faces = mesh.face_count(),
                    vertices = mesh.positions.size();
  auto first_corner = [&](std::size_t f) {
    return mesh.all_triangles() ? 3 * f : std::size_t{mesh.face_start[f]};
  };

  // Corner texture coordinates: OBJ shares them and leaves some corners without; PLY gives
  // every corner of a face one, or none.
  if ((obj || ply) && chance(0.6)) {
    const bool floats = chance(0.5);  // all float-exact: PLY writes them as float then
    a.texcoord_components = obj && set != AttributeSet::all && chance(0.5) ? 3 : 2;
    const std::uint32_t count = 1 + below(12);
    for (std::uint32_t t = 0; t < count; ++t) {
      std::array<double, 3> uv{real(-1, 2), real(-1, 2),
                               a.texcoord_components == 3 ? real(0, 1) : 0};
      if (floats) {
        for (double& x : uv) x = static_cast<float>(x);
      }
      a.texcoords.push_back(uv);
    }
    a.corner_texcoord.assign(corners, kNoAttribute);
    for (std::size_t f = 0; f < faces; ++f) {
      const bool face_has = chance(0.8);
      for (std::size_t k = first_corner(f); k < first_corner(f) + mesh.arity(FaceId(f)); ++k) {
        if (ply && !obj) {
          if (face_has) a.corner_texcoord[k] = below(count);
        } else if (chance(0.9)) {
          a.corner_texcoord[k] = below(count);
        }
      }
    }
  }
  if (obj) {
    if (chance(0.5)) {
      const std::uint32_t count = 1 + below(8);
      for (std::uint32_t n = 0; n < count; ++n) {
        a.normals.push_back({real(-1, 1), real(-1, 1), real(-1, 1)});
      }
      a.corner_normal.assign(corners, kNoAttribute);
      if (chance(0.3)) {  // smooth shading: each vertex's corners share one normal
        for (std::size_t k = 0; k < corners; ++k) a.corner_normal[k] = mesh.corners[k] % count;
      } else {
        const double share = chance(0.5) ? 1.0 : 0.8;  // of the corners that get a normal
        for (std::uint32_t& normal : a.corner_normal) {
          if (chance(share)) normal = below(count);
        }
      }
    }
    const std::pair<std::vector<std::string>*, HugeVector<std::uint32_t>*> named[3] = {
        {&a.material_names, &a.face_material},
        {&a.group_names, &a.face_group},
        {&a.object_names, &a.face_object}};
    for (const auto& [names, values] : named) {
      if (!chance(0.5)) continue;
      const std::uint32_t count = 1 + below(4);
      for (std::uint32_t n = 0; n < count; ++n) {
        names->push_back((n % 2 ? "name " : "n") + std::to_string(n));  // some with a space
      }
      values->assign(faces, kNoAttribute);
      // Runs of faces share a value, as in a real file.
      std::uint32_t value = kNoAttribute;
      for (std::uint32_t& v : *values) {
        if (chance(0.2)) value = chance(0.1) ? kNoAttribute : below(count);
        v = value;
      }
    }
    if (chance(0.5)) {
      a.face_smoothing.assign(faces, 0);
      for (std::uint32_t& s : a.face_smoothing) s = below(4);
    }
    if (chance(0.5)) a.material_libraries = {"scene.mtl", "other lib.mtl"};
  }

  auto column = [&](std::string name, ScalarType type, std::size_t size) {
    PropertyColumn c{std::move(name), type, {}};
    for (std::size_t i = 0; i < size; ++i) {
      switch (type) {
        case ScalarType::int8:
          c.values.push_back(double(below(256)) - 128);
          break;
        case ScalarType::uint8:
          c.values.push_back(below(256));
          break;
        case ScalarType::int16:
          c.values.push_back(double(below(65536)) - 32768);
          break;
        case ScalarType::uint16:
          c.values.push_back(below(65536));
          break;
        case ScalarType::int32:
          c.values.push_back(double(below(0xFFFFFFFFu)) - 2147483647.0);
          break;
        case ScalarType::uint32:
          c.values.push_back(below(0xFFFFFFFFu));
          break;
        case ScalarType::float32:
          c.values.push_back(static_cast<float>(real(-10, 10)));
          break;
        case ScalarType::float64:
          c.values.push_back(real(-1e6, 1e6));
          break;
      }
    }
    return c;
  };
  auto colour = [&](std::vector<PropertyColumn>& columns, std::size_t size, bool alpha,
                    ScalarType type) {
    for (const char* name : {"red", "green", "blue", "alpha"}) {
      if (std::string(name) == "alpha" && !alpha) break;
      columns.push_back(column(name, type, size));
    }
  };
  if (ply) {
    if (chance(0.3)) {
      a.position_type = ScalarType::float32;
      // One call per coordinate: GCC 12.2 at -O3 vectorizes the plain loop over the vertices'
      // coordinates into one whose epilogue rounds only z of the last vertices.
      for (auto& p : mesh.positions) {
        for (double& x : p) x = round_to_float(x);
      }
    }
    for (auto* columns : {&a.vertex_properties, &a.face_properties}) {
      const std::size_t size = columns == &a.vertex_properties ? vertices : faces;
      const std::uint32_t count = below(4);
      for (std::uint32_t c = 0; c < count; ++c) {
        columns->push_back(column("p" + std::to_string(c), ScalarType(below(8)), size));
      }
    }
  } else if (off) {
    if (chance(0.4)) {
      for (const char* name : {"nx", "ny", "nz"}) {
        a.vertex_properties.push_back(column(name, ScalarType::float32, vertices));
      }
    }
    if (chance(0.4)) {
      for (const char* name : {"s", "t"}) {
        a.vertex_properties.push_back(column(name, ScalarType::float32, vertices));
      }
    }
    if (chance(0.5)) {
      colour(a.vertex_properties, vertices, chance(0.5),
             chance(0.5) ? ScalarType::uint8 : ScalarType::float32);
    }
    if (chance(0.5)) {
      colour(a.face_properties, faces, chance(0.5),
             chance(0.5) ? ScalarType::uint8 : ScalarType::float32);
    }
  } else if (obj && chance(0.5)) {
    colour(a.vertex_properties, vertices, false, ScalarType::float32);
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
