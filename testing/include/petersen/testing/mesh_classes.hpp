#pragma once
// One RapidCheck generator per class of mesh a user has, for tests that must hold on every class
// (target petersen::testing): closed, open with holes, quad-dominant, non-manifold,
// non-orientable, several components, flat shaded with texture seams and materials.
//
//   for (MeshClass c : kMeshClasses) {
//     const PolygonMesh mesh = *petersen::testing::meshes_of_class(c, 60);
//     ...
//   }
//
// The meshes come from petersen's seeded generators (polygon_generators.hpp,
// mesh_class_generators.hpp), so a failing case replays exactly from its seed.

#include <rapidcheck.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string_view>
#include <vector>

#include "petersen/generators/mesh_class_generators.hpp"
#include "petersen/generators/polygon_generators.hpp"
#include "petersen/generators/surface_generators.hpp"
#include "petersen/graph/seeded_random.hpp"

namespace petersen::testing {

enum class MeshClass {
  closed,           ///< closed orientable triangulations of genus 0 or 1
  open_with_holes,  ///< grids and closed surfaces with patches removed
  quad_dominant,    ///< quads with triangles, pentagons and hexagons among them
  non_manifold,     ///< edges of three or more faces, pinched vertices
  non_orientable,   ///< Möbius bands (open), Klein bottles and projective planes (closed)
  components,       ///< two or three meshes of the classes above side by side, some faces flipped
  textured,         ///< any of the above flat shaded, with UV seams and materials
};
inline constexpr std::array kMeshClasses = {MeshClass::closed,         MeshClass::open_with_holes,
                                            MeshClass::quad_dominant,  MeshClass::non_manifold,
                                            MeshClass::non_orientable, MeshClass::components,
                                            MeshClass::textured};

inline std::string_view to_string(MeshClass c) {
  constexpr std::array<std::string_view, kMeshClasses.size()> names = {
      "closed",         "open_with_holes", "quad_dominant", "non_manifold",
      "non_orientable", "components",      "textured"};
  return names[static_cast<std::size_t>(c)];
}

/// A mesh of the class of about `faces` faces (at least the class's smallest shape, a dozen
/// faces or so), every choice drawn from `seed`. O(faces).
inline PolygonMesh mesh_of_class(MeshClass c, std::uint64_t seed, std::uint32_t faces) {
  SeededRandom rng(seed);
  const std::uint32_t side =
      std::max<std::uint32_t>(1, static_cast<std::uint32_t>(std::sqrt(faces / 2.0)));
  auto grid_side = [&] { return side + rng.below(2); };
  switch (c) {
    case MeshClass::closed: {
      const std::uint32_t genus = faces >= 80 ? rng.below(2) : 0;
      const std::uint32_t splits = faces > 12 ? (faces - 12) / 2 : 0;
      return random_closed_surface(genus, splits, splits, rng.next());
    }
    case MeshClass::open_with_holes: {
      const PolygonMesh base = rng.below(2) == 0
                                   ? open_grid(grid_side(), grid_side())
                                   : random_closed_surface(0, faces / 2, faces / 2, rng.next());
      const std::uint32_t holes = 1 + rng.below(1 + faces / 30);
      return punch_holes(base, holes, rng.next());
    }
    case MeshClass::quad_dominant: {
      const std::uint32_t nx =
          std::max<std::uint32_t>(2, static_cast<std::uint32_t>(std::sqrt(double(faces))));
      const bool torus = nx >= 9 && rng.below(3) == 0;
      return quad_dominant_grid({.nx = torus ? 3 * (nx / 3) : nx,
                                 .ny = torus ? nx / 3 : nx,
                                 .jitter = 0.1,
                                 .torus = torus,
                                 .triangle_squares = 2 + rng.below(5),
                                 .pentagons = 1 + rng.below(3),
                                 .hexagons = rng.below(3),
                                 .seed = rng.next()});
    }
    case MeshClass::non_manifold: {
      PolygonMesh base = rng.below(2) == 0
                             ? random_closed_surface(0, faces / 2, faces / 2, rng.next())
                             : open_grid(grid_side(), grid_side());
      base = add_fins(base, 1 + rng.below(3), rng.next());
      if (rng.below(2) == 0) base = pinch_vertices(base, 1, rng.next());
      return base;
    }
    case MeshClass::non_orientable:
      switch (rng.below(3)) {
        case 0:
          return mobius_band(std::max<std::uint32_t>(3, 2 * side),
                             1 + rng.below(std::max(side / 2, 1u)));
        case 1:
          return klein_bottle(std::max<std::uint32_t>(3, side), std::max<std::uint32_t>(3, side));
        default:
          return projective_plane(faces >= 40 ? 1 : 0);
      }
    case MeshClass::components: {
      const std::uint32_t parts = 2 + rng.below(2);
      std::vector<PolygonMesh> meshes;
      for (std::uint32_t k = 0; k < parts; ++k) {
        const MeshClass part = kMeshClasses[rng.below(kMeshClasses.size() - 2)];
        meshes.push_back(mesh_of_class(part, rng.next(), faces / parts));
      }
      PolygonMesh all = concatenate(meshes);
      if (rng.below(2) == 0) all = flip_faces(all, 1 + rng.below(3), rng.next());
      return all;
    }
    case MeshClass::textured: {
      const MeshClass base = kMeshClasses[rng.below(kMeshClasses.size() - 1)];
      return flat_shaded(mesh_of_class(base, rng.next(), faces),
                         {.uv_scale = 0.25, .materials = 1 + rng.below(3), .seed = rng.next()});
    }
  }
  return {};
}

/// Meshes of the class, of about 12 to `most_faces` faces; shrinks towards small ones.
inline rc::Gen<PolygonMesh> meshes_of_class(MeshClass c, std::uint32_t most_faces) {
  return rc::gen::apply(
      [c](std::uint64_t seed, std::uint32_t faces) { return mesh_of_class(c, seed, faces); },
      rc::gen::arbitrary<std::uint64_t>(), rc::gen::inRange<std::uint32_t>(12, most_faces + 1));
}

}  // namespace petersen::testing
