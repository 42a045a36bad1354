#include "quad_mesh_check.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <span>
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

namespace {

using EdgeKey = std::pair<VertexId, VertexId>;

EdgeKey key_of(VertexId a, VertexId b) {
  return {std::min(a, b), std::max(a, b)};
}

// Per undirected edge: the faces on it, +1 for each running low to high, and the count.
struct EdgeUse {
  int faces = 0, forward = 0;
};

std::map<EdgeKey, EdgeUse> edge_uses(const PolygonMesh& mesh) {
  std::map<EdgeKey, EdgeUse> uses;
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    const auto c = mesh.face(f);
    for (std::size_t k = 0; k < c.size(); ++k) {
      const VertexId a = c[k], b = c[(k + 1) % c.size()];
      if (a == b) continue;
      EdgeUse& use = uses[key_of(a, b)];
      ++use.faces;
      use.forward += a < b;
    }
  }
  return uses;
}

bool repeats(std::span<const VertexId> c) {
  for (std::size_t i = 0; i < c.size(); ++i)
    for (std::size_t j = i + 1; j < c.size(); ++j)
      if (c[i] == c[j]) return true;
  return false;
}

bool near(double a, double b) {
  return std::abs(a - b) <= 1e-6 * std::max({1.0, std::abs(a), std::abs(b)});
}

std::int64_t euler(const PolygonMesh& mesh, std::size_t edges) {
  std::vector<std::uint8_t> used(mesh.positions.size(), 0);
  for (VertexId v : mesh.corners) used[v] = 1;
  return std::int64_t(std::count(used.begin(), used.end(), 1)) - std::int64_t(edges) +
         std::int64_t(mesh.face_count());
}

}  // namespace

std::string all_quad_file_problem(const PolygonMesh& source, const PolygonMesh& output,
                                  AllQuadFileCounts& counts) {
  const std::size_t v0 = source.positions.size(), vn = output.positions.size();
  if (vn < v0 ||
      !std::equal(source.positions.begin(), source.positions.end(), output.positions.begin())) {
    return "the output does not start with the source's positions";
  }
  for (FaceId f = 0; f < output.face_count(); ++f) {
    const auto c = output.face(f);
    for (VertexId v : c)
      if (v >= vn) return "output face " + std::to_string(f) + " names a vertex out of range";
    if (c.size() == 3 && repeats(c)) {
      ++counts.kept_triangles;
      continue;
    }
    if (c.size() != 4) return "output face " + std::to_string(f) + " is not a quad";
    if (repeats(c)) return "output face " + std::to_string(f) + " repeats a vertex";
    ++counts.quads;
  }
  const auto in = edge_uses(source);
  const auto out = edge_uses(output);
  bool source_oriented = true;
  for (const auto& [e, use] : in) source_oriented &= use.faces != 2 || use.forward == 1;
  std::vector<std::vector<VertexId>> neighbours(vn - v0);
  std::vector<std::uint8_t> inner(vn - v0, 1);
  for (const auto& [e, use] : out) {
    if (use.faces > 2)
      return "output edge " + std::to_string(e.first) + "-" + std::to_string(e.second) +
             " is in more than two faces";
    if (source_oriented && use.faces == 2 && use.forward != 1) {
      return "output edge " + std::to_string(e.first) + "-" + std::to_string(e.second) +
             " is run along in one direction by both of its faces";
    }
    for (const VertexId v : {e.first, e.second}) {
      if (v < v0) continue;
      neighbours[v - v0].push_back(v == e.first ? e.second : e.first);
      if (use.faces != 2) inner[v - v0] = 0;
    }
  }
  // Each added vertex: a midpoint of a source edge, or a centre.
  std::map<EdgeKey, VertexId> midpoint_of;
  for (std::size_t i = 0; i < vn - v0; ++i) {
    const auto& p = output.positions[v0 + i];
    bool found = false;
    for (VertexId a : neighbours[i]) {
      for (VertexId b : neighbours[i]) {
        if (a >= b || a >= v0 || b >= v0 || in.count(key_of(a, b)) == 0) continue;
        const auto& pa = output.positions[a];
        const auto& pb = output.positions[b];
        bool average = true;
        for (int d = 0; d < 3; ++d) average &= near(p[d], (pa[d] + pb[d]) / 2);
        if (!average || midpoint_of.count(key_of(a, b)) != 0) continue;
        midpoint_of[key_of(a, b)] = VertexId(v0 + i);
        found = true;
        break;
      }
      if (found) break;
    }
    if (found) {
      ++counts.midpoints;
    } else if (inner[i] && neighbours[i].size() >= 3) {
      ++counts.centres;
    } else {
      return "added vertex " + std::to_string(v0 + i) +
             " is neither the midpoint of a source edge nor a centre";
    }
  }
  // Each source edge: kept, split in its two halves, or removed where it had two faces.
  std::size_t boundary_in = 0, boundary_expected = 0;
  for (const auto& [e, use] : in) {
    const bool kept = out.count(e) != 0;
    const auto m = midpoint_of.find(e);
    const bool split = m != midpoint_of.end();
    if (kept && split) {
      return "source edge " + std::to_string(e.first) + "-" + std::to_string(e.second) +
             " is both kept and split";
    }
    if (split && (out.count(key_of(e.first, m->second)) == 0 ||
                  out.count(key_of(m->second, e.second)) == 0)) {
      return "split source edge " + std::to_string(e.first) + "-" + std::to_string(e.second) +
             " lacks a half";
    }
    if (!kept && !split && use.faces != 2) {
      return "source edge " + std::to_string(e.first) + "-" + std::to_string(e.second) + " of " +
             std::to_string(use.faces) + " faces is gone";
    }
    if (use.faces == 1) {
      ++boundary_in;
      boundary_expected += split ? 2 : 1;
      const int faces = kept ? out.at(e).faces
                             : std::max(out.at(key_of(e.first, m->second)).faces,
                                        out.at(key_of(m->second, e.second)).faces);
      if (faces != 1) {
        return "boundary edge " + std::to_string(e.first) + "-" + std::to_string(e.second) +
               " is not on the output's boundary";
      }
    }
  }
  std::size_t boundary_out = 0;
  for (const auto& [e, use] : out) boundary_out += use.faces == 1;
  if (boundary_out != boundary_expected) {
    return "the output has " + std::to_string(boundary_out) + " boundary edges, " +
           std::to_string(boundary_expected) + " expected from the source's " +
           std::to_string(boundary_in);
  }
  if (euler(source, in.size()) != euler(output, out.size())) {
    return "the Euler characteristic changed from " + std::to_string(euler(source, in.size())) +
           " to " + std::to_string(euler(output, out.size()));
  }
  return "";
}

}  // namespace petersen::testing
