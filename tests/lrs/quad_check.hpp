#pragma once
// The checks on lrs's quads against the surface they came from, on a polygon mesh of the quads.

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <string>
#include <utility>

#include "petersen/dualize/quad_of.hpp"
#include "petersen/lrs/lrs.hpp"
#include "petersen/mesh/mesh.hpp"

namespace petersen::lrs::testing {

/// The quads as a polygon mesh over the input's positions.
inline PolygonMesh quad_mesh_of(const PolygonMesh& input, const LrsPairing& pairing) {
  PolygonMesh quads;
  quads.positions = input.positions;
  for (const LrsQuad& quad : pairing.quads) quads.add_face(quad.corners);
  return quads;
}

/// The first problem with lrs's quads of `input` (a closed triangle surface), or "": F/2 quads of
/// four distinct in-range corners; every edge in exactly two quads that run along it in opposite
/// directions (a closed, oriented quad surface); the input's vertices and Euler characteristic
/// V − E + F; each input triangle the source of one quad at most, the quad holding its corners,
/// and a quad of two sources exactly their quad_of.
inline std::string quad_problem(const PolygonMesh& input, const LrsPairing& pairing) {
  const PolygonMesh quads = quad_mesh_of(input, pairing);
  if (2 * quads.face_count() != input.face_count()) return "not one quad per two triangles";
  std::map<std::pair<VertexId, VertexId>, int> directed;
  std::set<VertexId> quad_vertices, input_vertices(input.corners.begin(), input.corners.end());
  for (FaceId q = 0; q < quads.face_count(); ++q) {
    const auto c = quads.face(q);
    for (int k = 0; k < 4; ++k) {
      if (c[k] >= input.positions.size()) return "corner out of range in quad " + std::to_string(q);
      for (int j = 0; j < k; ++j) {
        if (c[j] == c[k]) return "repeated corner in quad " + std::to_string(q);
      }
      ++directed[{c[k], c[(k + 1) % 4]}];
      quad_vertices.insert(c[k]);
    }
  }
  std::size_t edges = 0;
  for (const auto& [edge, count] : directed) {
    const auto twin = directed.find({edge.second, edge.first});
    if (count != 1 || twin == directed.end() || twin->second != 1) {
      return "edge " + std::to_string(edge.first) + "-" + std::to_string(edge.second) +
             " not in two opposite quads";
    }
    edges += edge.first < edge.second;
  }
  if (quad_vertices != input_vertices) return "not the input's vertices";
  const auto euler_input = static_cast<std::int64_t>(input_vertices.size()) -
                           static_cast<std::int64_t>(3 * input.face_count() / 2) +
                           static_cast<std::int64_t>(input.face_count());
  const auto euler_quads = static_cast<std::int64_t>(quad_vertices.size()) -
                           static_cast<std::int64_t>(edges) +
                           static_cast<std::int64_t>(quads.face_count());
  if (euler_input != euler_quads) return "Euler characteristic differs";
  std::set<FaceId> named;
  for (FaceId q = 0; q < pairing.quads.size(); ++q) {
    const LrsQuad& quad = pairing.quads[q];
    for (const FaceId s : quad.sources) {
      if (s == kNoFace) continue;
      if (s >= input.face_count() || !named.insert(s).second) {
        return "source " + std::to_string(s) + " named twice or out of range";
      }
      for (const VertexId v : input.face(s)) {
        if (std::find(quad.corners.begin(), quad.corners.end(), v) == quad.corners.end()) {
          return "quad " + std::to_string(q) + " misses a corner of its source";
        }
      }
    }
    if (quad.sources[0] != kNoFace && quad.sources[1] != kNoFace &&
        quad_of(input.face(quad.sources[0]), input.face(quad.sources[1])) != quad.corners) {
      return "quad " + std::to_string(q) + " is not the quad of its two sources";
    }
  }
  return {};
}

}  // namespace petersen::lrs::testing
