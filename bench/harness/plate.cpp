#include "plate.hpp"

#include <algorithm>
#include <cmath>

namespace petersen::bench {

PlateShape fit_plate(std::uint32_t holes_x, std::uint32_t holes_y, bool dents, std::uint64_t target,
                     double tolerance, std::uint32_t max_units) {
  // The isotropic width nearest the target bounds the in-plane widths searched (±2 around it).
  std::uint32_t s = 1;
  while (s < max_units && uniform_plate(holes_x, holes_y, dents, s + 1).triangle_count() <= target)
    ++s;
  const std::uint32_t lo = s > 2 ? s - 2 : 1, hi = std::min(s + 2, max_units);
  const std::uint32_t depth_hi = std::min(max_units, std::max<std::uint32_t>(10, 2 * hi));

  PlateShape best = uniform_plate(holes_x, holes_y, dents, s);
  auto error = [&](const PlateShape& p) {
    return std::abs(double(p.triangle_count()) - double(target)) / double(target);
  };
  auto spread = [](const PlateShape& p) {
    const auto [mn, mx] = std::minmax({p.wall_x, p.hole_x, p.wall_y, p.hole_y});
    return mx - mn;
  };
  // Within tolerance: fewer distinct widths first, then nearer; outside it: nearer.
  auto better = [&](const PlateShape& p, const PlateShape& q) {
    const bool p_in = error(p) <= tolerance, q_in = error(q) <= tolerance;
    if (p_in != q_in) return p_in;
    if (p_in && spread(p) != spread(q)) return spread(p) < spread(q);
    return error(p) < error(q);
  };
  PlateShape p{holes_x, holes_y, 0, 0, 0, 0, 0, 0, dents};
  for (p.wall_x = lo; p.wall_x <= hi; ++p.wall_x)
    for (p.hole_x = lo; p.hole_x <= hi; ++p.hole_x)
      for (p.wall_y = lo; p.wall_y <= hi; ++p.wall_y)
        for (p.hole_y = lo; p.hole_y <= hi; ++p.hole_y) {
          const auto [mn, mx] = std::minmax({p.wall_x, p.hole_x, p.wall_y, p.hole_y});
          if (mx > 2 * mn) continue;
          for (p.thickness = 1; p.thickness <= depth_hi; ++p.thickness)
            for (p.dent_depth = dents ? 1 : 0; p.dent_depth <= (dents ? depth_hi : 0);
                 ++p.dent_depth)
              if (better(p, best)) best = p;
        }
  return best;
}

}  // namespace petersen::bench
