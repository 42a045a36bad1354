#pragma once
// The worst-corner figures of the quads an out-of-core run writes, which are too many to hold
// (half the triangles of a mesh that does not fit): counts of the costs rounded down to
// 1/kBinsPerDegree of a degree, so the median and 95th percentile are those of the rounded costs
// (within 0.001° below the in-memory figures of the same quads); the count, the total and the
// non-convex quads are exact. 2.2 MB whatever the mesh; add is O(1), figures O(bins).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "petersen/dualize/quad_quality.hpp"

namespace petersen::partition_detail {

class QualityHistogram {
 public:
  static constexpr double kBinsPerDegree = 1024;
  static constexpr double kMostDegrees = 270;  // a corner of 360° deviates 270° from 90°

  void add(double cost) {
    ++figures_.quads;
    figures_.total += cost;
    figures_.nonconvex += cost > 90;
    // A cost that is not a number counts as the worst (the comparison is false for NaN).
    const double clamped = cost < kMostDegrees ? std::max(cost, 0.0) : kMostDegrees;
    const double bin = std::floor(clamped * kBinsPerDegree);
    ++counts_[static_cast<std::size_t>(bin)];
  }

  /// As quality_figures (nearest rank), over the rounded costs.
  QualityFigures figures() const {
    QualityFigures figures = figures_;
    if (figures.quads == 0) return figures;
    auto rank = [&](double p) {
      const auto k = static_cast<std::uint64_t>(std::ceil(p * double(figures.quads)));
      return std::max<std::uint64_t>(k, 1);
    };
    const std::uint64_t median = rank(0.5), p95 = rank(0.95);
    std::uint64_t seen = 0;
    bool median_found = false;
    for (std::size_t bin = 0; bin < counts_.size(); ++bin) {
      seen += counts_[bin];
      if (!median_found && seen >= median) {
        figures.median = double(bin) / kBinsPerDegree;
        median_found = true;
      }
      if (seen >= p95) {
        figures.p95 = double(bin) / kBinsPerDegree;
        break;
      }
    }
    return figures;
  }

 private:
  std::vector<std::uint64_t> counts_ =
      std::vector<std::uint64_t>(static_cast<std::size_t>(kMostDegrees * kBinsPerDegree) + 1);
  QualityFigures figures_;
};

}  // namespace petersen::partition_detail
