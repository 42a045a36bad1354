#include "validate_input.hpp"

#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>

#include "petersen/dualize/quad_quality.hpp"

namespace petersen::quad_detail {

namespace {

// "12.5", or "nan", "inf", "-inf": std::to_string would print 12.500000.
std::string number_text(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

void check_range(const char* option, std::optional<double> value, double low, double high,
                 const char* unit = "degrees") {
  if (!value) return;
  // Written so that NaN fails: every comparison with it is false.
  if (!(std::isfinite(*value) && *value >= low && *value <= high)) {
    throw std::invalid_argument(std::string(option) + " must be a finite number of " + unit +
                                " in [" + number_text(low) + ", " + number_text(high) + "], not " +
                                number_text(*value));
  }
}

}  // namespace

void validate_options(const QuadOptions& options) {
  check_range("max_corner_deviation", options.max_corner_deviation, 0, kDegenerateQuadCost);
  check_range("sharp_angle_degrees", options.cuts.sharp_angle_degrees, 0, 180);
  // Bounds far above any quad's cost (270 of shape, 180 of flow per unit weight) that keep the
  // scaled costs inside the solver's range.
  check_range("triangle_cost", options.triangle_cost, 0, kMaxTriangleCost);
  check_range("flow_weight", options.flow_weight, 0, kMaxFlowWeight, "degrees per degree");
  if (options.objective != Objective::pairs &&
      options.algorithm != PairingAlgorithm{Algorithm::automatic}) {
    throw std::invalid_argument("algorithm " + std::string(to_string(options.algorithm)) +
                                " pairs by objective pairs only; objective " +
                                std::string(to_string(options.objective)) +
                                " pairs by the minimum-cost matching");
  }
  if (options.threads > kMaxQuadThreads) {
    throw std::invalid_argument("threads must be 0 (every core) or at most " +
                                std::to_string(kMaxQuadThreads) + ", not " +
                                std::to_string(options.threads));
  }
}

void validate_positions(const PolygonMesh& mesh) {
  const Positions& positions = mesh.positions;
  const std::size_t vertex_count = positions.size();
  for (std::size_t v = 0; v < vertex_count; ++v) {
    const auto& p = positions[v];
    if (std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])) continue;
    throw MeshError("vertex " + std::to_string(v) + " has a coordinate that is not finite (" +
                    number_text(p[0]) + ", " + number_text(p[1]) + ", " + number_text(p[2]) + ")");
  }
}

}  // namespace petersen::quad_detail
