#pragma once
// Arithmetic on mesh positions as 3-vectors: one copy for the quad measure, the renderer and
// whatever else measures geometry.

#include <array>
#include <cmath>

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

}  // namespace petersen::vec3
