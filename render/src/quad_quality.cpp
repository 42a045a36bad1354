#include "petersen/render/quad_quality.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace petersen {

namespace {

using Vec = std::array<double, 3>;

Vec sub(const Vec& a, const Vec& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
double dot(const Vec& a, const Vec& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec scaled(const Vec& a, double s) {
  return {a[0] * s, a[1] * s, a[2] * s};
}

}  // namespace

double quad_corner_deviation(const Vec& a, const Vec& b, const Vec& c, const Vec& d) {
  const Vec corners[4] = {a, b, c, d};
  for (const Vec& p : corners) {
    for (double x : p) {
      if (!std::isfinite(x)) return kDegenerateQuadCost;
    }
  }
  Vec n = cross(sub(c, a), sub(d, b));
  const double length = std::sqrt(dot(n, n));
  if (!(length > 0) || !std::isfinite(length)) return kDegenerateQuadCost;
  n = scaled(n, 1 / length);
  double worst = 0;
  for (int i = 0; i < 4; ++i) {
    const Vec& p = corners[i];
    // The two edges at corner i, projected onto the plane orthogonal to n.
    Vec to_next = sub(corners[(i + 1) % 4], p);
    Vec to_prev = sub(corners[(i + 3) % 4], p);
    to_next = sub(to_next, scaled(n, dot(to_next, n)));
    to_prev = sub(to_prev, scaled(n, dot(to_prev, n)));
    if (!(dot(to_next, to_next) > 0) || !(dot(to_prev, to_prev) > 0)) return kDegenerateQuadCost;
    // Counter-clockwise about n from to_next to to_prev, in [0, 360).
    double theta =
        std::atan2(dot(cross(to_next, to_prev), n), dot(to_next, to_prev)) * 180 / std::numbers::pi;
    if (theta < 0) theta += 360;
    worst = std::max(worst, std::abs(90 - theta));
  }
  return worst;
}

std::vector<double> quad_costs(const PolygonMesh& mesh) {
  std::vector<double> costs;
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    if (mesh.arity(f) != 4) continue;
    const auto q = mesh.face(f);
    costs.push_back(quad_corner_deviation(mesh.positions[q[0]], mesh.positions[q[1]],
                                          mesh.positions[q[2]], mesh.positions[q[3]]));
  }
  return costs;
}

QuadQualityFigures quality_figures(std::vector<double> costs) {
  QuadQualityFigures figures;
  figures.quads = costs.size();
  if (costs.empty()) return figures;
  std::sort(costs.begin(), costs.end());
  auto rank = [&](double p) {  // nearest rank: the smallest cost with at least p of them at most
    const auto k = static_cast<std::size_t>(std::ceil(p * double(costs.size())));
    return costs[std::max<std::size_t>(k, 1) - 1];
  };
  figures.median = rank(0.5);
  figures.p95 = rank(0.95);
  figures.nonconvex = std::count_if(costs.begin(), costs.end(), [](double c) { return c > 90; });
  return figures;
}

std::string describe(const QuadQualityFigures& f) {
  char line[160];
  std::snprintf(line, sizeof line,
                "%llu quads, worst corner median %.1f\xc2\xb0, p95 %.1f\xc2\xb0, %llu non-convex",
                static_cast<unsigned long long>(f.quads), f.median, f.p95,
                static_cast<unsigned long long>(f.nonconvex));
  return line;
}

}  // namespace petersen
