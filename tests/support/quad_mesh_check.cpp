#include "quad_mesh_check.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "petersen/dualize/quad_of.hpp"
#include "petersen/mesh/mesh_report.hpp"

namespace petersen::testing {

PolygonMesh quads_of_matching(const PolygonMesh& mesh, const CubicGraph& dual,
                              const Matching& matching) {
  if (dual.node_count() != mesh.face_count()) {
    throw MeshError("the dual graph has " + std::to_string(dual.node_count()) +
                    " nodes but the mesh has " + std::to_string(mesh.face_count()) + " faces");
  }
  if (const MatchingCheck check = verify_perfect_matching(dual, matching); !check.ok()) {
    throw MeshError("cannot make quads: " + check.message);
  }
  PolygonMesh quads;
  quads.positions = mesh.positions;
  for (FaceId t = 0; t < mesh.face_count(); ++t) {
    const auto [t1, t2] = dual.endpoints(matching.mate_edge[t]);
    if (t != std::min(t1, t2)) continue;  // each quad once, from its lower triangle
    const std::array<VertexId, 4> quad = quad_of(mesh.face(t), mesh.face(t == t1 ? t2 : t1));
    quads.add_face(quad);
  }
  return quads;
}

namespace {

// Each undirected edge with the direction the quad runs along it, and the quad.
struct Side {
  std::uint64_t edge;
  bool forward;
  FaceId quad;
  bool operator<(const Side& o) const { return edge < o.edge || (edge == o.edge && quad < o.quad); }
};

// The quads' sides, or the first quad that is not four distinct in-range corners; marks the
// vertices the quads use with bit 2 of `used`.
std::string collect_sides(const PolygonMesh& quads, std::vector<std::uint8_t>& used,
                          std::vector<Side>& sides) {
  for (FaceId q = 0; q < quads.face_count(); ++q) {
    const auto c = quads.face(q);
    if (c.size() != 4) {
      return "face " + std::to_string(q) + " has " + std::to_string(c.size()) + " corners, not 4";
    }
    for (int k = 0; k < 4; ++k) {
      if (c[k] >= used.size()) {
        return "quad " + std::to_string(q) + " has corner " + std::to_string(c[k]) +
               " out of range";
      }
      for (int j = 0; j < k; ++j) {
        if (c[j] == c[k])
          return "quad " + std::to_string(q) + " repeats vertex " + std::to_string(c[k]);
      }
      used[c[k]] |= 2;
      const VertexId u = c[k], v = c[(k + 1) % 4];
      sides.push_back({std::uint64_t{std::min(u, v)} << 32 | std::max(u, v), u < v, q});
    }
  }
  return "";
}

// The number of edges, or the first edge not in exactly two quads running opposite ways.
std::string count_edges(std::vector<Side>& sides, std::uint64_t& edges) {
  std::sort(sides.begin(), sides.end());
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t end = i + 1;
    while (end < sides.size() && sides[end].edge == sides[i].edge) ++end;
    const std::string name = "edge (" + std::to_string(sides[i].edge >> 32) + ", " +
                             std::to_string(sides[i].edge & 0xFFFFFFFFu) + ")";
    if (end - i != 2) {
      return name + " is in " + std::to_string(end - i) + " quads (first " +
             std::to_string(sides[i].quad) + "), not 2";
    }
    if (sides[i].forward == sides[i + 1].forward) {
      return name + ": quads " + std::to_string(sides[i].quad) + " and " +
             std::to_string(sides[i + 1].quad) + " run along it in the same direction";
    }
    ++edges;
    i = end;
  }
  return "";
}

}  // namespace

std::string pairing_problem(const PolygonMesh& source, const PolygonMesh& output,
                            std::uint64_t& quads) {
  using Triple = std::array<VertexId, 3>;
  auto sorted = [](VertexId a, VertexId b, VertexId c) {
    Triple t{a, b, c};
    std::sort(t.begin(), t.end());
    return t;
  };
  if (!source.all_triangles()) return "the source has faces that are not triangles";
  std::pmr::vector<Triple> in, out;
  in.reserve(source.face_count());
  for (FaceId f = 0; f < source.face_count(); ++f) {
    const std::span<const VertexId> t = source.face(f);
    in.push_back(sorted(t[0], t[1], t[2]));
  }
  quads = 0;
  out.reserve(source.face_count());
  for (FaceId f = 0; f < output.face_count(); ++f) {
    const std::span<const VertexId> q = output.face(f);
    if (q.size() == 3) {
      out.push_back(sorted(q[0], q[1], q[2]));
      continue;
    }
    if (q.size() != 4)
      return "face " + std::to_string(f) + " has " + std::to_string(q.size()) + " corners";
    std::array<VertexId, 4> corners{q[0], q[1], q[2], q[3]};
    std::sort(corners.begin(), corners.end());
    if (std::adjacent_find(corners.begin(), corners.end()) != corners.end())
      return "quad " + std::to_string(f) + " repeats a corner";
    out.push_back(sorted(q[0], q[2], q[3]));
    out.push_back(sorted(q[0], q[1], q[2]));
    ++quads;
  }
  std::sort(in.begin(), in.end());
  std::sort(out.begin(), out.end());
  if (in.size() != out.size()) {
    return "the output holds " + std::to_string(out.size()) + " triangles, the source " +
           std::to_string(in.size());
  }
  const auto [a, b] = std::mismatch(in.begin(), in.end(), out.begin());
  if (a != in.end()) {
    const Triple& t = *a < *b ? *a : *b;
    return "triangle (" + std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " +
           std::to_string(t[2]) + ") is " + (*a < *b ? "missing from" : "extra in") + " the output";
  }
  return "";
}

std::string quad_mesh_problem(const PolygonMesh& source, const PolygonMesh& quads) {
  if (quads.positions != source.positions) return "positions differ from the source's";
  const std::size_t vertex_count = source.positions.size();
  std::vector<std::uint8_t> used(vertex_count, 0);
  for (VertexId v : source.corners)
    if (v < vertex_count) used[v] |= 1;
  std::vector<Side> sides;
  if (std::string problem = collect_sides(quads, used, sides); !problem.empty()) return problem;
  for (VertexId v = 0; v < vertex_count; ++v) {
    if (used[v] == 1) return "source vertex " + std::to_string(v) + " is in no quad";
    if (used[v] == 2)
      return "vertex " + std::to_string(v) + " is in a quad but in no source triangle";
  }
  std::uint64_t edges = 0;
  if (std::string problem = count_edges(sides, edges); !problem.empty()) return problem;
  const std::int64_t vertices = std::count(used.begin(), used.end(), 3);
  const std::int64_t chi = vertices - std::int64_t(edges) + std::int64_t(quads.face_count());
  const std::int64_t source_chi = inspect_mesh(source).euler_characteristic;
  if (chi != source_chi) {
    return "Euler characteristic " + std::to_string(chi) + " differs from the source's " +
           std::to_string(source_chi);
  }
  return "";
}

}  // namespace petersen::testing
