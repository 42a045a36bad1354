#include "petersen/dualize/quads.hpp"

#include <algorithm>

#include "petersen/graph/huge_pages.hpp"
#include "petersen/mesh/mesh_report.hpp"

namespace petersen {

QuadMesh quads_from_matching(const TriangleMesh& mesh, const CubicGraph& dual,
                             const Matching& matching) {
  if (dual.node_count() != mesh.triangles.size()) {
    throw MeshError("the dual graph has " + std::to_string(dual.node_count()) +
                    " nodes but the mesh has " + std::to_string(mesh.triangles.size()) +
                    " triangles");
  }
  if (const MatchingCheck check = verify_perfect_matching(dual, matching); !check.ok()) {
    throw MeshError("cannot make quads: " + check.message);
  }
  QuadMesh quads;
  quads.positions = mesh.positions;
  quads.quads.reserve(mesh.triangles.size() / 2);
  for (FaceId t = 0; t < mesh.triangles.size(); ++t) {
    const EdgeId e = matching.mate_edge[t];
    const auto [t1, t2] = dual.endpoints(e);
    if (t != t1) continue;  // each quad once, from its first triangle
    const auto& a = mesh.triangles[t1];
    const auto& b = mesh.triangles[t2];
    bool found = false;
    // Edge k of t1 runs a[k] -> a[k+1]; its twin in t2 runs b[j] -> b[j+1] the other way.
    for (int k = 0; k < 3 && !found; ++k) {
      for (int j = 0; j < 3 && !found; ++j) {
        if (a[k] == b[(j + 1) % 3] && a[(k + 1) % 3] == b[j]) {
          quads.quads.push_back({a[k], b[(j + 2) % 3], a[(k + 1) % 3], a[(k + 2) % 3]});
          found = true;
        }
      }
    }
    if (!found) {
      throw MeshError("dual edge " + std::to_string(e) + " joins triangles " + std::to_string(t1) +
                      " and " + std::to_string(t2) + ", which share no edge");
    }
  }
  return quads;
}

QuadCheck check_quad_mesh(const TriangleMesh& source, const QuadMesh& quads) {
  auto fail = [](std::string problem) { return QuadCheck{std::move(problem)}; };
  if (quads.positions != source.positions) return fail("positions differ from the source's");
  const std::size_t vertex_count = source.positions.size();
  std::vector<std::uint8_t> used(vertex_count, 0);
  for (const auto& tri : source.triangles)
    for (VertexId v : tri)
      if (v < vertex_count) used[v] |= 1;
  // Each undirected edge with the direction the quad runs along it, and the quad.
  struct Side {
    std::uint64_t edge;
    bool forward;
    FaceId quad;
    bool operator<(const Side& o) const {
      return edge < o.edge || (edge == o.edge && quad < o.quad);
    }
  };
  HugeVector<Side> sides;
  sides.reserve(4 * quads.quads.size());
  for (FaceId q = 0; q < quads.quads.size(); ++q) {
    const auto& c = quads.quads[q];
    for (int k = 0; k < 4; ++k) {
      if (c[k] >= vertex_count) {
        return fail("quad " + std::to_string(q) + " has corner " + std::to_string(c[k]) +
                    " out of range");
      }
      for (int j = 0; j < k; ++j) {
        if (c[j] == c[k]) {
          return fail("quad " + std::to_string(q) + " repeats vertex " + std::to_string(c[k]));
        }
      }
      used[c[k]] |= 2;
      const VertexId u = c[k], v = c[(k + 1) % 4];
      sides.push_back({std::uint64_t{std::min(u, v)} << 32 | std::max(u, v), u < v, q});
    }
  }
  for (VertexId v = 0; v < vertex_count; ++v) {
    if (used[v] == 1) return fail("source vertex " + std::to_string(v) + " is in no quad");
    if (used[v] == 2) {
      return fail("vertex " + std::to_string(v) + " is in a quad but in no source triangle");
    }
  }
  std::sort(sides.begin(), sides.end());
  std::uint64_t edges = 0;
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t end = i + 1;
    while (end < sides.size() && sides[end].edge == sides[i].edge) ++end;
    const std::string name = "edge (" + std::to_string(sides[i].edge >> 32) + ", " +
                             std::to_string(sides[i].edge & 0xFFFFFFFFu) + ")";
    if (end - i != 2) {
      return fail(name + " is in " + std::to_string(end - i) + " quads (first " +
                  std::to_string(sides[i].quad) + "), not 2");
    }
    if (sides[i].forward == sides[i + 1].forward) {
      return fail(name + ": quads " + std::to_string(sides[i].quad) + " and " +
                  std::to_string(sides[i + 1].quad) + " run along it in the same direction");
    }
    ++edges;
    i = end;
  }
  const std::int64_t vertices = std::count(used.begin(), used.end(), 3);
  const std::int64_t chi = vertices - std::int64_t(edges) + std::int64_t(quads.quads.size());
  const std::int64_t source_chi = inspect_mesh(to_polygon_mesh(source)).euler_characteristic;
  if (chi != source_chi) {
    return fail("Euler characteristic " + std::to_string(chi) + " differs from the source's " +
                std::to_string(source_chi));
  }
  return {};
}

}  // namespace petersen
