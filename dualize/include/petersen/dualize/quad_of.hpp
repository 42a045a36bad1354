#pragma once
// The quad two edge-adjacent triangles make once their shared edge is removed: the one place
// that decides its corners and their order, for the pairing, LRS, the costs and the checks.

#include <array>
#include <span>
#include <stdexcept>

#include "petersen/mesh/mesh.hpp"

namespace petersen {

/// The quad of triangle t1 and the triangle across t1's side k (from corner k to corner k + 1),
/// whose corner off that side is d: with a, b, c = t1[k], t1[k + 1], t1[k + 2] it is (a, d, b, c),
/// in t1's orientation whichever way the other triangle runs. O(1).
inline std::array<VertexId, 4> quad_across(std::span<const VertexId> t1, int k, VertexId d) {
  return {t1[k], d, t1[(k + 1) % 3], t1[(k + 2) % 3]};
}

/// The quad of triangles t1 and t2, which share an edge: quad_across at t1's first side whose two
/// ends t2 holds. Throws std::logic_error when they share no edge. O(1).
inline std::array<VertexId, 4> quad_of(std::span<const VertexId> t1, std::span<const VertexId> t2) {
  auto in_t2 = [&](VertexId v) { return v == t2[0] || v == t2[1] || v == t2[2]; };
  for (int k = 0; k < 3; ++k) {
    const VertexId a = t1[k], b = t1[(k + 1) % 3];
    if (!in_t2(a) || !in_t2(b)) continue;
    const VertexId d = t2[0] != a && t2[0] != b ? t2[0] : t2[1] != a && t2[1] != b ? t2[1] : t2[2];
    return quad_across(t1, k, d);
  }
  throw std::logic_error("internal error: paired triangles share no edge");
}

}  // namespace petersen
