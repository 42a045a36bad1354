#pragma once
// Topology-preserving simplification, as the paper made A2–A5 and B2–B5 from A1 and B1 (§4): edge
// contractions that pass the link condition, shortest edge first, on petersen::lrs's mutable
// triangulation.

#include <cstdint>

#include "petersen/mesh/mesh.hpp"

namespace petersen::bench {

/// Contracts the shortest contractible edge (the survivor moves to the edge's midpoint) until at
/// most `target_triangles` remain; genus and connectivity are kept, because every contraction
/// passes the link condition. Unreferenced vertices are dropped. Throws std::runtime_error if no
/// contractible edge is left first. O(F log F).
PolygonMesh simplify(const PolygonMesh& mesh, std::uint64_t target_triangles);

}  // namespace petersen::bench
