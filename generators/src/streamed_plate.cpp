#include "petersen/generators/streamed_plate.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace petersen {

StreamedPlate streamed_plate_of_size(std::uint64_t triangles) {
  if (triangles > 0xFFFFFFFEull) {
    throw std::invalid_argument(std::to_string(triangles) +
                                " triangles: face ids are 32-bit, at most 4294967294");
  }
  triangles = std::max<std::uint64_t>(triangles, 12);
  // triangles = 2 · around · (rows + 1) with rows ≈ 16 · around.
  StreamedPlate plate;
  plate.around =
      std::max<std::uint32_t>(3, static_cast<std::uint32_t>(std::sqrt(triangles / 32.0)));
  plate.rows = static_cast<std::uint32_t>(
      std::max<std::uint64_t>(1, triangles / (2 * std::uint64_t{plate.around})) - 1);
  plate.rows = std::max<std::uint32_t>(plate.rows, 1);
  return plate;
}

}  // namespace petersen
