#pragma once
// A mesh with its faces in a random order, for the tests whose generators list neighbouring faces
// next to each other: a greedy start in face order would pair them back by position alone, and
// the ordered sweep takes a local order where the tests want the general case.

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

#include "petersen/mesh/mesh.hpp"

namespace petersen::testing {

inline PolygonMesh shuffled_faces(const PolygonMesh& mesh, std::uint64_t seed) {
  std::vector<FaceId> order(mesh.face_count());
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937_64(seed));
  PolygonMesh shuffled;
  shuffled.positions = mesh.positions;
  for (FaceId f : order) shuffled.add_face(mesh.face(f));
  return shuffled;
}

}  // namespace petersen::testing
