#include "petersen/generators/knot_tube.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "petersen/mesh/vec3.hpp"

namespace petersen {

namespace {

using vec3::cross, vec3::dot, vec3::sub, vec3::unit;
using Vec = vec3::Vec3;

constexpr double kPi = std::numbers::pi;
constexpr double kTubeRadius = 0.6;

// The (2, 3) torus knot at parameter t in [0, 2π).
Vec trefoil(double t) {
  const double ring = 2 + std::cos(3 * t);
  return {ring * std::cos(2 * t), ring * std::sin(2 * t), std::sin(3 * t)};
}

Vec add_scaled(const Vec& p, double s, const Vec& q) {
  return {p[0] + s * q[0], p[1] + s * q[1], p[2] + s * q[2]};
}

// `count` points of the knot at equal arc length, from a polyline of 64 samples per point
// (the speed of the parametrisation varies by a factor of 2.4 along the knot).
std::vector<Vec> equal_arc_points(std::uint32_t count) {
  const std::size_t samples = std::size_t{count} * 64;
  std::vector<Vec> dense(samples + 1);
  std::vector<double> length(samples + 1, 0);
  for (std::size_t k = 0; k <= samples; ++k) {
    dense[k] = trefoil(2 * kPi * double(k) / double(samples));
    if (k > 0) {
      const Vec d = sub(dense[k], dense[k - 1]);
      length[k] = length[k - 1] + std::sqrt(dot(d, d));
    }
  }
  std::vector<Vec> points(count);
  std::size_t k = 0;
  for (std::uint32_t i = 0; i < count; ++i) {
    const double at = length[samples] * double(i) / double(count);
    while (length[k + 1] < at) ++k;
    const double s = (at - length[k]) / (length[k + 1] - length[k]);
    points[i] = add_scaled(dense[k], s, sub(dense[k + 1], dense[k]));
  }
  return points;
}

// A unit vector orthogonal to the unit vector t.
Vec orthogonal(const Vec& t) {
  const Vec axis = std::abs(t[0]) < 0.9 ? Vec{1, 0, 0} : Vec{0, 1, 0};
  return unit(cross(t, axis));
}

}  // namespace

PolygonMesh trefoil_tube(const KnotTube& spec) {
  const std::uint32_t n = spec.segments, m = spec.sides;
  if (n < 3 || m < 3) {
    throw std::invalid_argument("trefoil: needs at least 3 segments and 3 sides, not " +
                                std::to_string(n) + " x " + std::to_string(m));
  }
  if (std::uint64_t{n} * m * 6 > 0xFFFFFFFFull) {
    throw std::invalid_argument("trefoil: " + std::to_string(n) + " x " + std::to_string(m) +
                                " passes 2^32 - 1 corners");
  }
  const std::vector<Vec> centre = equal_arc_points(n);
  std::vector<Vec> tangent(n), normal(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    tangent[i] = unit(sub(centre[(i + 1) % n], centre[(i + n - 1) % n]));
  }
  // Parallel transport of the normal by the double reflection method (Wang, Jüttler, Zheng and
  // Liu 2008): the frame turns no more about the tangent than the curve makes it.
  normal[0] = orthogonal(tangent[0]);
  auto transported = [&](std::uint32_t i, const Vec& r) {
    const std::uint32_t j = (i + 1) % n;
    const Vec v1 = sub(centre[j], centre[i]);
    const double c1 = dot(v1, v1);
    const Vec r_l = add_scaled(r, -2 * dot(v1, r) / c1, v1);
    const Vec t_l = add_scaled(tangent[i], -2 * dot(v1, tangent[i]) / c1, v1);
    const Vec v2 = sub(tangent[j], t_l);
    const double c2 = dot(v2, v2);
    return c2 > 0 ? add_scaled(r_l, -2 * dot(v2, r_l) / c2, v2) : r_l;
  };
  for (std::uint32_t i = 0; i + 1 < n; ++i) normal[i + 1] = transported(i, normal[i]);
  // The frame carried once round comes back turned by `twist` about the tangent. The last ring
  // joins the first `shift` vertices on, which takes the twist up to a multiple of a side's angle;
  // ring i is turned back by i/n of the rest (at most half a side's angle), so that the quads
  // shear as little as they can.
  const Vec back = transported(n - 1, normal[n - 1]);
  const double twist = std::atan2(dot(cross(normal[0], back), tangent[0]), dot(normal[0], back));
  const double side_angle = 2 * kPi / double(m);
  const auto shift = static_cast<std::int64_t>(std::lround(twist / side_angle));
  const double rest = twist - double(shift) * side_angle;
  PolygonMesh mesh;
  mesh.positions.resize(std::size_t{n} * m);
  for (std::uint32_t i = 0; i < n; ++i) {
    const Vec binormal = cross(tangent[i], normal[i]);
    const double turn = -rest * double(i) / double(n);
    for (std::uint32_t j = 0; j < m; ++j) {
      const double a = 2 * kPi * double(j) / double(m) + turn;
      const Vec radial =
          add_scaled(add_scaled({0, 0, 0}, std::cos(a), normal[i]), std::sin(a), binormal);
      mesh.positions[std::size_t{i} * m + j] = add_scaled(centre[i], kTubeRadius, radial);
    }
  }
  mesh.corners.reserve(std::size_t{n} * m * 6);
  for (std::uint32_t i = 0; i < n; ++i) {
    for (std::uint32_t j = 0; j < m; ++j) {
      // Ring n is ring 0, its vertex b being ring 0's b + shift.
      const auto v = [&](std::uint32_t a, std::uint32_t b) {
        const std::int64_t j = a < n ? b : std::int64_t{b} + shift;
        return static_cast<VertexId>((a % n) * m + ((j % m) + m) % m);
      };
      // Around the ring, then along the knot: counter-clockwise seen from outside.
      const VertexId q[4] = {v(i, j), v(i, j + 1), v(i + 1, j + 1), v(i + 1, j)};
      mesh.corners.insert(mesh.corners.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
    }
  }
  return mesh;
}

}  // namespace petersen
