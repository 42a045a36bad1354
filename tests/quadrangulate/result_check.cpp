#include "result_check.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "peers.hpp"
#include "petersen/dualize/quad_quality.hpp"
#include "petersen/graph/csr_graph.hpp"
#include "petersen/matching/tutte_berge.hpp"

namespace petersen::testing {

namespace {

using Edge = std::pair<VertexId, VertexId>;
Edge edge(VertexId a, VertexId b) {
  return {std::min(a, b), std::max(a, b)};
}

std::map<Edge, std::vector<FaceId>> faces_by_edge(const PolygonMesh& mesh) {
  std::map<Edge, std::vector<FaceId>> faces;
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    const auto c = mesh.face(f);
    for (std::size_t k = 0; k < c.size(); ++k) {
      const VertexId a = c[k], b = c[(k + 1) % c.size()];
      if (a != b) faces[edge(a, b)].push_back(f);
    }
  }
  return faces;
}

bool is_triangle(const PolygonMesh& mesh, FaceId f) {
  const auto c = mesh.face(f);
  return c.size() == 3 && c[0] != c[1] && c[1] != c[2] && c[0] != c[2];
}

}  // namespace

std::int64_t euler_characteristic(const PolygonMesh& mesh) {
  std::set<VertexId> vertices(mesh.corners.begin(), mesh.corners.end());
  return std::int64_t(vertices.size()) - std::int64_t(faces_by_edge(mesh).size()) +
         std::int64_t(mesh.face_count());
}

// Whether an extra cut forbids pairing triangles f and g across their edge (a, b).
bool extra_cut(const PolygonMesh& mesh, const CutOptions& cuts, FaceId f, FaceId g, Edge e) {
  for (const auto& [u, v] : cuts.user_edges)
    if (edge(u, v) == e) return true;
  auto corner = [&](FaceId face, VertexId v) {
    const std::size_t first = mesh.all_triangles() ? 3 * std::size_t{face} : mesh.face_start[face];
    for (std::size_t c = first; c < first + 3; ++c)
      if (mesh.corners[c] == v) return c;
    return first;
  };
  for (auto ids : {cuts.corner_uv, cuts.corner_normal}) {
    if (ids.empty()) continue;
    for (VertexId v : {e.first, e.second})
      if (ids[corner(f, v)] != ids[corner(g, v)]) return true;
  }
  for (auto ids : {cuts.face_material, cuts.face_group, cuts.face_object, cuts.face_smoothing,
                   cuts.face_property}) {
    if (!ids.empty() && ids[f] != ids[g]) return true;
  }
  if (cuts.sharp_angle_degrees) {
    // The angle between the normals, g's taken in f's orientation (a face that runs along the
    // edge the same way as f is reversed).
    auto normal = [&](FaceId face) {
      const auto t = mesh.face(face);
      const auto &p = mesh.positions[t[0]], &q = mesh.positions[t[1]], &r = mesh.positions[t[2]];
      const double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
      const double w[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
      return std::array<double, 3>{u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                                   u[0] * w[1] - u[1] * w[0]};
    };
    auto runs_forward = [&](FaceId face) {
      const auto t = mesh.face(face);
      for (int k = 0; k < 3; ++k)
        if (t[k] == e.first && t[(k + 1) % 3] == e.second) return true;
      return false;
    };
    const auto n = normal(f);
    auto m = normal(g);
    const double sign = runs_forward(f) == runs_forward(g) ? -1.0 : 1.0;
    const double dot = sign * (n[0] * m[0] + n[1] * m[1] + n[2] * m[2]);
    const double lengths = std::hypot(n[0], n[1], n[2]) * std::hypot(m[0], m[1], m[2]);
    if (!(lengths > 0)) return true;
    const double degrees = std::acos(std::clamp(dot / lengths, -1.0, 1.0)) * 180.0 / M_PI;
    if (degrees > *cuts.sharp_angle_degrees) return true;
  }
  return false;
}

// The cost of the quad triangles f < g make, in f's orientation: f = (a, b, c) sharing a-b with g,
// whose third vertex is d, gives (a, d, b, c).
double pair_cost(const PolygonMesh& mesh, FaceId f, FaceId g) {
  const auto t = mesh.face(f), u = mesh.face(g);
  auto in_u = [&](VertexId v) { return std::find(u.begin(), u.end(), v) != u.end(); };
  for (int k = 0; k < 3; ++k) {
    const VertexId a = t[k], b = t[(k + 1) % 3], c = t[(k + 2) % 3];
    if (!in_u(a) || !in_u(b)) continue;
    const VertexId d =
        *std::find_if(u.begin(), u.end(), [&](VertexId v) { return v != a && v != b; });
    const auto& p = mesh.positions;
    return quad_corner_deviation(p[a], p[d], p[b], p[c]);
  }
  return kDegenerateQuadCost;
}

std::string check_quad_result(const PolygonMesh& input, const QuadResult& result, bool all_quad,
                              bool flips_allowed, const CutOptions& cuts,
                              std::optional<double> max_corner_deviation) {
  const std::uint32_t faces = static_cast<std::uint32_t>(input.face_count());
  // The pairable graph, by definition: an edge in exactly two faces, both triangles without a
  // repeated vertex, whose union has four vertices.
  std::vector<NodeId> node_of(faces, kNoNode);
  std::uint32_t nodes = 0;
  for (FaceId f = 0; f < faces; ++f)
    if (input.arity(f) == 3) node_of[f] = nodes++;
  std::set<std::pair<FaceId, FaceId>> pairable;
  std::vector<std::array<NodeId, 2>> edges;
  for (const auto& [e, fs] : faces_by_edge(input)) {
    if (fs.size() != 2 || fs[0] == fs[1] || !is_triangle(input, fs[0]) ||
        !is_triangle(input, fs[1])) {
      continue;
    }
    std::set<VertexId> four;
    for (FaceId f : fs)
      for (VertexId v : input.face(f)) four.insert(v);
    if (four.size() != 4 || extra_cut(input, cuts, fs[0], fs[1], e)) continue;
    if (max_corner_deviation &&
        pair_cost(input, std::min(fs[0], fs[1]), std::max(fs[0], fs[1])) > *max_corner_deviation) {
      continue;
    }
    pairable.insert({std::min(fs[0], fs[1]), std::max(fs[0], fs[1])});
    edges.push_back({node_of[fs[0]], node_of[fs[1]]});
  }
  // Boost's Edmonds is far slower than LEMON's (over 300 s at 1.4M nodes): a second opinion on
  // the small graphs only.
  const std::uint32_t maximum = lemon_matching_size(nodes, edges);
  if (nodes <= 20000 && maximum != boost_matching_size(nodes, edges)) {
    return "LEMON and Boost disagree";
  }

  // Every input face used exactly once; the matching the quads make, on the test's own graph.
  std::vector<int> uses(faces, 0);
  std::vector<FaceId> partner(faces, kNoFace);
  std::uint64_t pairs = 0, left = 0;
  std::set<std::pair<FaceId, FaceId>> seen_pairs;
  for (FaceId o = 0; o < result.mesh.face_count(); ++o) {
    const auto [f, g] = result.sources[o];
    const auto out = result.mesh.face(o);
    if ((f != kNoFace && f >= faces) || (g != kNoFace && g >= faces)) {
      return "output face " + std::to_string(o) + " names a face out of range";
    }
    if (f == kNoFace || (g == kNoFace && out.size() == 4 && input.arity(f) == 3 && !all_quad)) {
      // lrs: a quad with a triangle its flips made (no input face).
      if (!flips_allowed) return "output face " + std::to_string(o) + " lacks an input face";
      for (FaceId t : {f, g})
        if (t != kNoFace && seen_pairs.insert({t, kNoFace}).second) ++uses[t];
      continue;
    }
    if (g == kNoFace) {
      // Kept or left: exactly the input face, unless all_quad split a left triangle.
      const bool split = all_quad && out.size() != input.arity(f);
      if (!split &&
          !std::equal(out.begin(), out.end(), input.face(f).begin(), input.face(f).end())) {
        return "output face " + std::to_string(o) + " differs from its input face " +
               std::to_string(f);
      }
      if (seen_pairs.insert({f, kNoFace}).second) {
        ++uses[f];
        left += input.arity(f) == 3;
      }
      continue;
    }
    if (!seen_pairs.insert({std::min(f, g), std::max(f, g)}).second) continue;  // a split piece
    ++uses[f];
    ++uses[g];
    ++pairs;
    if (!pairable.count({std::min(f, g), std::max(f, g)})) {
      return "faces " + std::to_string(f) + " and " + std::to_string(g) +
             " are paired across a cut";
    }
    partner[f] = g;
    partner[g] = f;
    if (!all_quad) {
      // The quad is the union of the two triangles, in f's orientation.
      std::set<VertexId> quad(out.begin(), out.end()), both;
      for (FaceId t : {f, g})
        for (VertexId v : input.face(t)) both.insert(v);
      if (out.size() != 4 || quad != both) return "quad " + std::to_string(o) + " is not its pair";
      const auto& p = result.mesh.positions;
      if (max_corner_deviation && quad_corner_deviation(p[out[0]], p[out[1]], p[out[2]],
                                                        p[out[3]]) > *max_corner_deviation) {
        return "quad " + std::to_string(o) + " is over the threshold";
      }
      const auto t = input.face(f);
      auto at = [&](VertexId v) { return std::find(out.begin(), out.end(), v) - out.begin(); };
      for (int k = 0; k < 3; ++k) {
        const auto i = at(t[k]), j = at(t[(k + 1) % 3]), l = at(t[(k + 2) % 3]);
        // t's corners appear in the same cyclic order in the quad.
        if (!((i < j && j < l) || (j < l && l < i) || (l < i && i < j))) {
          return "quad " + std::to_string(o) + " does not follow triangle " + std::to_string(f);
        }
      }
    }
  }
  for (FaceId f = 0; f < faces; ++f) {
    if (uses[f] != 1 && !(flips_allowed && uses[f] == 0 && input.arity(f) == 3)) {
      return "input face " + std::to_string(f) + " used " + std::to_string(uses[f]) + " times";
    }
  }
  if (left != result.stats.triangles_left && !flips_allowed) {
    return "triangles_left " + std::to_string(result.stats.triangles_left) + ", counted " +
           std::to_string(left);
  }
  if (result.stats.triangles_left != nodes - 2 * maximum) {
    return "triangles_left " + std::to_string(result.stats.triangles_left) +
           " but the maximum leaves " + std::to_string(nodes - 2 * maximum);
  }
  if (!flips_allowed) {
    if (pairs != result.stats.pairs) return "pair count differs";
    // The witness proves the pairing maximum on the test's graph.
    CsrGraph graph = CsrGraph::from_edges(nodes, edges);
    Matching matching(nodes);
    std::vector<FaceId> face_of_node(nodes);
    for (FaceId f = 0; f < faces; ++f)
      if (node_of[f] != kNoNode) face_of_node[node_of[f]] = f;
    for (EdgeId e = 0; e < edges.size(); ++e) {
      const auto [a, b] = edges[e];
      if (partner[face_of_node[a]] == face_of_node[b])
        matching.mate_edge[a] = matching.mate_edge[b] = e;
    }
    std::vector<NodeId> tutte;
    for (FaceId f : result.tutte_set) tutte.push_back(node_of[f]);
    if (MatchingCheck check = verify_maximum_matching(graph, matching, tutte); !check.ok()) {
      return "witness: " + check.message;
    }
  }
  if (all_quad) {
    for (FaceId o = 0; o < result.mesh.face_count(); ++o) {
      const FaceId f = result.sources[o][0];
      const bool kept_polygon =
          result.sources[o][1] == kNoFace && f != kNoFace && input.arity(f) != 3;
      if (!kept_polygon && result.mesh.arity(o) != 4) {
        return "all-quad output face " + std::to_string(o) + " has " +
               std::to_string(result.mesh.arity(o)) + " corners";
      }
    }
    // An edge in more than two faces must be an input edge that was, or half of one (a split of a
    // non-manifold edge at its midpoint, which all of its faces share).
    const auto in_edges = faces_by_edge(input);
    std::map<std::array<double, 3>, std::pair<Edge, std::size_t>> split_midpoints;
    for (const auto& [e, fs] : in_edges) {
      if (fs.size() < 3) continue;
      const auto& p = input.positions[e.first];
      const auto& q = input.positions[e.second];
      split_midpoints[{(p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2}] = {e, fs.size()};
    }
    for (const auto& [e, fs] : faces_by_edge(result.mesh)) {
      std::size_t allowed = 2;
      if (const auto it = in_edges.find(e); it != in_edges.end()) {
        allowed = std::max(allowed, it->second.size());
      } else {
        for (auto [added, kept] : {e, Edge{e.second, e.first}}) {
          if (added < input.positions.size()) continue;
          const auto it = split_midpoints.find(result.mesh.positions[added]);
          if (it != split_midpoints.end() &&
              (it->second.first.first == kept || it->second.first.second == kept)) {
            allowed = std::max(allowed, it->second.second);
          }
        }
      }
      if (fs.size() > allowed) {
        return "edge (" + std::to_string(e.first) + ", " + std::to_string(e.second) + ") in " +
               std::to_string(fs.size()) + " faces";
      }
    }
    if (euler_characteristic(result.mesh) != euler_characteristic(input)) {
      return "Euler characteristic changed";
    }
    for (std::size_t v = 0; v < input.positions.size(); ++v) {
      if (result.mesh.positions[v] != input.positions[v]) return "an input vertex moved";
    }
  }
  return {};
}

}  // namespace petersen::testing
