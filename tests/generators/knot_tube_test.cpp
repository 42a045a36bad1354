// The trefoil tube's topology by plain counting (mesh_census.hpp), its orientation by its signed
// volume, and its quads' shapes by the measure the pairing minimises.

#include "petersen/generators/knot_tube.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "petersen/dualize/quad_quality.hpp"
#include "petersen/mesh/mesh_report.hpp"
#include "petersen/testing/mesh_census.hpp"

namespace petersen {
namespace {

using petersen::testing::census;

TEST(TrefoilTube, IsAClosedOrientedSurfaceOfGenus1) {
  for (const KnotTube spec : {KnotTube{}, KnotTube{.segments = 40, .sides = 5}}) {
    const PolygonMesh mesh = trefoil_tube(spec);
    // Simplicial too (no repeated or degenerate triangle, no pinched vertex): the library's own
    // surface check, beside the independent counts.
    EXPECT_NO_THROW(require_closed_surface(mesh, {}));
    const auto c = census(mesh);
    EXPECT_EQ(c.vertices, std::uint64_t{spec.segments} * spec.sides);
    EXPECT_EQ(c.faces, 2 * std::uint64_t{spec.segments} * spec.sides);
    EXPECT_EQ(c.euler(), 0);
    EXPECT_EQ(c.boundary_edges, 0u);
    EXPECT_EQ(c.non_manifold_edges, 0u);
    EXPECT_EQ(c.inconsistent_edges, 0u);
    EXPECT_EQ(c.components, 1u);
    EXPECT_TRUE(c.orientable);
    // Facing outwards: the enclosed volume (a sum of signed tetrahedra) is positive, and close to
    // the tube's: its 16-gon's area (8 r² sin(π/8)) times the knot's length (31.9).
    double volume = 0;
    for (FaceId f = 0; f < mesh.face_count(); ++f) {
      const auto t = mesh.face(f);
      const auto &p = mesh.positions[t[0]], &q = mesh.positions[t[1]], &r = mesh.positions[t[2]];
      volume += (p[0] * (q[1] * r[2] - q[2] * r[1]) - p[1] * (q[0] * r[2] - q[2] * r[0]) +
                 p[2] * (q[0] * r[1] - q[1] * r[0])) /
                6;
    }
    if (spec.sides == 16) {
      EXPECT_NEAR(volume, 8 * 0.36 * std::sin(2 * std::numbers::pi / 16) * 31.9, 0.3);
    }
    EXPECT_GT(volume, 0);
  }
}

TEST(TrefoilTube, FacesTwoByTwoAreNearSquareQuads) {
  const PolygonMesh mesh = trefoil_tube({});
  double worst = 0, shortest = INFINITY, longest = 0;
  for (FaceId q = 0; 2 * q < mesh.face_count(); ++q) {
    const auto a = mesh.face(2 * q), b = mesh.face(2 * q + 1);
    ASSERT_EQ(a[0], b[0]);  // {q0, q1, q2} and {q0, q2, q3}: cut along q0-q2
    ASSERT_EQ(a[2], b[1]);
    const auto& p = mesh.positions;
    worst = std::max(worst, quad_corner_deviation(p[a[0]], p[a[1]], p[a[2]], p[b[2]]));
    for (int k = 0; k < 3; ++k) {
      const auto& u = p[a[k]];
      const auto& v = p[k < 2 ? a[k + 1] : b[2]];
      const double length = std::hypot(u[0] - v[0], u[1] - v[1], u[2] - v[2]);
      if (k != 1) shortest = std::min(shortest, length), longest = std::max(longest, length);
    }
  }
  EXPECT_LT(worst, 8.0);  // trapezoids where the knot bends; no shear from the frame
  EXPECT_GT(shortest / longest, 0.4);
}

TEST(TrefoilTube, RefusesTooFewSegmentsOrSides) {
  EXPECT_THROW(trefoil_tube({.segments = 2, .sides = 16}), std::invalid_argument);
  EXPECT_THROW(trefoil_tube({.segments = 20, .sides = 2}), std::invalid_argument);
  EXPECT_THROW(trefoil_tube({.segments = 100000, .sides = 100000}), std::invalid_argument);
}

}  // namespace
}  // namespace petersen
