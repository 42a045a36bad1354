#include "petersen/dualize/quad_quality.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace petersen {

namespace {

using Vec = std::array<double, 3>;

Vec sub(const Vec& p, const Vec& q) {
  return {p[0] - q[0], p[1] - q[1], p[2] - q[2]};
}
double dot(const Vec& p, const Vec& q) {
  return p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
}
Vec cross(const Vec& p, const Vec& q) {
  return {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
}
// p without its component along the unit vector n.
Vec project(const Vec& p, const Vec& n) {
  const double along = dot(p, n);
  return {p[0] - along * n[0], p[1] - along * n[1], p[2] - along * n[2]};
}

}  // namespace

double quad_corner_deviation(const Vec& a, const Vec& b, const Vec& c, const Vec& d) {
  const Vec corners[4] = {a, b, c, d};
  for (const Vec& p : corners)
    for (double x : p)
      if (!std::isfinite(x)) return kDegenerateQuadCost;
  Vec n = cross(sub(c, a), sub(d, b));
  const double length = std::sqrt(dot(n, n));
  // Also catches an overflowing cross product (length infinite).
  if (!(length > 0) || !std::isfinite(length)) return kDegenerateQuadCost;
  for (double& x : n) x /= length;
  double worst = 0;
  for (int k = 0; k < 4; ++k) {
    const Vec& p = corners[k];
    const Vec to_next = project(sub(corners[(k + 1) % 4], p), n);
    const Vec to_prev = project(sub(corners[(k + 3) % 4], p), n);
    if (dot(to_next, to_next) == 0 || dot(to_prev, to_prev) == 0) return kDegenerateQuadCost;
    // Counter-clockwise about n from to_next to to_prev: the interior angle of a quad whose
    // corners run counter-clockwise about n, as (c − a) × (d − b) makes them.
    double theta = std::atan2(dot(n, cross(to_next, to_prev)), dot(to_next, to_prev)) * 180.0 /
                   std::numbers::pi;
    if (theta < 0) theta += 360.0;
    if (theta >= 360.0) theta = 0;
    worst = std::max(worst, std::abs(90.0 - theta));
  }
  return worst;
}

HugeVector<double> dual_edge_quality(const TriangleMesh& mesh, const Dual& dual) {
  const CubicGraph& graph = dual.graph;
  HugeVector<double> cost(graph.edge_count());
  for (EdgeId e = 0; e < graph.edge_count(); ++e) {
    // Halfedge 3t + k runs from corner k to corner k + 1 of triangle t; its twin runs back.
    const HalfedgeId h1 = dual.side(e, 0), h2 = dual.side(e, 1);
    const auto& t1 = mesh.triangles[h1 / 3];
    const auto& t2 = mesh.triangles[h2 / 3];
    const int k = static_cast<int>(h1 % 3), j = static_cast<int>(h2 % 3);
    // The quad of quads_from_matching: (a[k], b[j + 2], a[k + 1], a[k + 2]).
    const auto& p = mesh.positions;
    cost[e] =
        quad_corner_deviation(p[t1[k]], p[t2[(j + 2) % 3]], p[t1[(k + 1) % 3]], p[t1[(k + 2) % 3]]);
  }
  return cost;
}

}  // namespace petersen
