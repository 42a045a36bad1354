#include "petersen/render/quad_quality.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace petersen {

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
