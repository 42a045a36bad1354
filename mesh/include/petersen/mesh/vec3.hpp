#pragma once
// Arithmetic on mesh positions as 3-vectors: one copy for the quad measure, the renderer and
// whatever else measures geometry.

#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>

namespace petersen::vec3 {

using Vec3 = std::array<double, 3>;

inline Vec3 sub(const Vec3& p, const Vec3& q) {
  return {p[0] - q[0], p[1] - q[1], p[2] - q[2]};
}
inline double dot(const Vec3& p, const Vec3& q) {
  return p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
}
inline Vec3 cross(const Vec3& p, const Vec3& q) {
  return {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
}
/// p scaled to length 1; the caller makes sure p is not zero.
inline Vec3 unit(const Vec3& p) {
  const double length = std::sqrt(dot(p, p));
  return {p[0] / length, p[1] / length, p[2] / length};
}

/// A polygon's normal by Newell's method, of length twice its area (zero for no area): the
/// polygon's corners are `positions[corners[k]]`, in order. Exact for planar polygons and robust
/// for non-planar ones, which a cross product of two sides is not. O(k).
template <class Positions, class Corners>
Vec3 newell_normal(const Positions& positions, const Corners& corners) {
  Vec3 n{0, 0, 0};
  const std::size_t count = std::size(corners);
  for (std::size_t k = 0; k < count; ++k) {
    const Vec3& p = positions[corners[k]];
    const Vec3& q = positions[corners[(k + 1) % count]];
    n[0] += (p[1] - q[1]) * (p[2] + q[2]);
    n[1] += (p[2] - q[2]) * (p[0] + q[0]);
    n[2] += (p[0] - q[0]) * (p[1] + q[1]);
  }
  return n;
}

}  // namespace petersen::vec3
