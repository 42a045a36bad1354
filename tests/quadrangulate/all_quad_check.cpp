#include "all_quad_check.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <span>
#include <tuple>
#include <utility>
#include <vector>

#include "petersen/testing/mesh_census.hpp"

namespace petersen::testing {

namespace {

constexpr VertexId kNoVertex = 0xFFFFFFFFu;

using Edge = std::pair<VertexId, VertexId>;
Edge undirected(VertexId a, VertexId b) {
  return {std::min(a, b), std::max(a, b)};
}

std::string face_name(FaceId o) {
  return "output face " + std::to_string(o);
}

// Whether output face o is a quad lrs made with a triangle its flips made: no input face, or a
// quad of four input vertices named after one input triangle alone.
bool flipped_quad(const PolygonMesh& input, const QuadResult& result, FaceId o) {
  const auto [f, g] = result.sources[o];
  if (f == kNoFace) return true;
  const auto out = result.mesh.face(o);
  return g == kNoFace && input.arity(f) == 3 && out.size() == 4 &&
         std::all_of(out.begin(), out.end(),
                     [&](VertexId v) { return v < input.positions.size(); });
}

// The pre-split face of a source: the pair's quad in t1's orientation (t1 = (a, b, c) sharing
// a-b with t2, whose third vertex is d, gives (a, d, b, c)), or the input face.
std::vector<VertexId> pre_split_face(const PolygonMesh& input, FaceId f, FaceId g) {
  const auto t = input.face(f);
  if (g == kNoFace) return {t.begin(), t.end()};
  const auto u = input.face(g);
  auto in_u = [&](VertexId v) { return std::find(u.begin(), u.end(), v) != u.end(); };
  for (int k = 0; k < 3; ++k) {
    const VertexId a = t[k], b = t[(k + 1) % 3], c = t[(k + 2) % 3];
    if (!in_u(a) || !in_u(b)) continue;
    const VertexId d =
        *std::find_if(u.begin(), u.end(), [&](VertexId v) { return v != a && v != b; });
    return {a, d, b, c};
  }
  return {};
}

// Whether `face` is `cycle` started at another corner (same direction).
bool is_rotation_of(std::span<const VertexId> face, const std::vector<VertexId>& cycle) {
  if (face.size() != cycle.size()) return false;
  const auto start = std::find(cycle.begin(), cycle.end(), face[0]);
  if (start == cycle.end()) return false;
  const std::size_t offset = start - cycle.begin();
  for (std::size_t k = 0; k < face.size(); ++k)
    if (face[k] != cycle[(offset + k) % cycle.size()]) return false;
  return true;
}

// One pre-split side and what the output made of it: its midpoint, or kNoVertex.
struct Side {
  Edge edge;
  VertexId midpoint;
  FaceId group_face;  // an output face of the group, for messages
  auto operator<=>(const Side&) const = default;
};

// The output faces of one source: checks that they tile the pre-split face `cycle` (see the top of
// all_quad_check.hpp), appending its sides to `sides` and its inner new vertices to `centres`
// and its inner edges to `inner`. Empty, or the problem.
std::string check_tiling(const PolygonMesh& out, std::size_t n, std::span<const FaceId> pieces,
                         const std::vector<VertexId>& cycle, std::vector<Side>& sides,
                         std::vector<VertexId>& centres, std::vector<Edge>& inner) {
  const std::string where =
      face_name(pieces[0]) + " (of " + std::to_string(pieces.size()) + " pieces of one source)";
  std::map<Edge, int> directed;  // (from, to) -> count
  std::set<VertexId> vertices;
  std::set<Edge> edges;
  for (FaceId o : pieces) {
    const auto c = out.face(o);
    if (c.size() != 4) return face_name(o) + " has " + std::to_string(c.size()) + " corners";
    if (std::set<VertexId>(c.begin(), c.end()).size() != 4)
      return face_name(o) + " repeats a corner";
    for (std::size_t k = 0; k < 4; ++k) {
      ++directed[{c[k], c[(k + 1) % 4]}];
      vertices.insert(c[k]);
      edges.insert(undirected(c[k], c[(k + 1) % 4]));
    }
  }
  if (std::int64_t(vertices.size()) - std::int64_t(edges.size()) + std::int64_t(pieces.size()) != 1)
    return where + ": the pieces are no disk";
  // Inner edges run both ways once; what is left is the boundary, one edge out of each vertex.
  std::map<VertexId, VertexId> next;
  for (const auto& [e, count] : directed) {
    const auto back = directed.find({e.second, e.first});
    const int reverse = back == directed.end() ? 0 : back->second;
    if (count > 1 || reverse > 1) return where + ": an edge twice in one direction";
    if (reverse == 1) {
      if (e.first < e.second) inner.push_back(undirected(e.first, e.second));
      continue;
    }
    if (!next.emplace(e.first, e.second).second) return where + ": a boundary vertex twice";
  }
  // Walk the boundary from the source's first corner: its corners in order, at most one new
  // vertex between two of them.
  VertexId at = cycle[0];
  std::set<VertexId> on_boundary{at};
  for (std::size_t k = 0; k < cycle.size(); ++k) {
    const VertexId a = cycle[k], b = cycle[(k + 1) % cycle.size()];
    auto step = [&]() -> VertexId {
      const auto it = next.find(at);
      return it == next.end() ? kNoVertex : it->second;
    };
    VertexId v = step();
    VertexId midpoint = kNoVertex;
    if (v != b && v != kNoVertex && v >= n) {
      midpoint = v;
      at = v;
      on_boundary.insert(v);
      v = step();
    }
    if (v != b) {
      return where + ": the boundary of the pieces is not the side " + std::to_string(a) + "-" +
             std::to_string(b) + " of its source (with at most one midpoint), or runs against it";
    }
    at = b;
    on_boundary.insert(b);
    sides.push_back({undirected(a, b), midpoint, pieces[0]});
  }
  if (on_boundary.size() != next.size()) return where + ": the boundary is more than one loop";
  for (VertexId v : vertices) {
    if (on_boundary.count(v)) continue;
    if (v < n) return where + ": input vertex " + std::to_string(v) + " inside the pieces";
    centres.push_back(v);
  }
  return {};
}

// Every pre-split side split in all its faces or in none, by one midpoint, and no vertex the
// midpoint of two sides or both a midpoint and a centre.
std::string check_sides(std::vector<Side>& sides, std::vector<VertexId>& centres,
                        AllQuadCheck& counted) {
  std::sort(sides.begin(), sides.end());
  std::vector<VertexId> midpoints;
  for (std::size_t i = 0, j = 0; i < sides.size(); i = j) {
    while (j < sides.size() && sides[j].edge == sides[i].edge) ++j;
    for (std::size_t k = i + 1; k < j; ++k) {
      if (sides[k].midpoint != sides[i].midpoint) {
        return "side " + std::to_string(sides[i].edge.first) + "-" +
               std::to_string(sides[i].edge.second) + " is split differently in " +
               face_name(sides[i].group_face) + " and " + face_name(sides[k].group_face);
      }
    }
    if (sides[i].midpoint != kNoVertex) midpoints.push_back(sides[i].midpoint);
  }
  std::sort(midpoints.begin(), midpoints.end());
  if (std::adjacent_find(midpoints.begin(), midpoints.end()) != midpoints.end())
    return "a new vertex is the midpoint of two sides";
  std::sort(centres.begin(), centres.end());
  if (std::adjacent_find(centres.begin(), centres.end()) != centres.end())
    return "a centre vertex is inside two faces";
  for (VertexId c : centres) {
    if (std::binary_search(midpoints.begin(), midpoints.end(), c))
      return "new vertex " + std::to_string(c) + " is both a midpoint and a centre";
  }
  counted.split_edges = midpoints.size();
  counted.centre_vertices = centres.size();
  return {};
}

// No inner edge of a face's pieces is an edge of any other output face.
std::string check_inner_edges(const PolygonMesh& out, std::vector<Edge>& inner) {
  std::vector<Edge> all;
  all.reserve(out.corners.size());
  for (FaceId o = 0; o < out.face_count(); ++o) {
    const auto c = out.face(o);
    for (std::size_t k = 0; k < c.size(); ++k)
      all.push_back(undirected(c[k], c[(k + 1) % c.size()]));
  }
  std::sort(all.begin(), all.end());
  for (const Edge& e : inner) {
    const auto [first, end] = std::equal_range(all.begin(), all.end(), e);
    if (end - first != 2) {
      return "inner edge " + std::to_string(e.first) + "-" + std::to_string(e.second) + " is in " +
             std::to_string(end - first) + " faces";
    }
  }
  return {};
}

std::string check_topology(const PolygonMesh& input, const PolygonMesh& out) {
  for (std::size_t v = 0; v < input.positions.size(); ++v) {
    if (out.positions[v] != input.positions[v])
      return "input vertex " + std::to_string(v) + " moved";
  }
  const auto before = component_census(input), after = component_census(out);
  if (before.size() != after.size()) {
    return std::to_string(before.size()) + " components became " + std::to_string(after.size());
  }
  for (std::size_t k = 0; k < before.size(); ++k) {
    if (before[k] != after[k]) {
      return "a component's census changed: Euler characteristic " +
             std::to_string(before[k].euler) + ", boundary loops " +
             std::to_string(before[k].boundary_loops) + ", orientable " +
             std::to_string(before[k].orientable) + " became " + std::to_string(after[k].euler) +
             ", " + std::to_string(after[k].boundary_loops) + ", " +
             std::to_string(after[k].orientable);
    }
  }
  return {};
}

}  // namespace

AllQuadCheck check_all_quad_mesh(const PolygonMesh& input, const QuadResult& result,
                                 KeptPolygons polygons, bool flips_allowed) {
  AllQuadCheck counted;
  const PolygonMesh& out = result.mesh;
  const std::size_t n = input.positions.size();
  if (result.sources.size() != out.face_count()) {
    counted.problem = "sources has " + std::to_string(result.sources.size()) + " entries for " +
                      std::to_string(out.face_count()) + " faces";
    return counted;
  }
  if (out.positions.size() < n) {
    counted.problem = "the output has fewer vertices than the input";
    return counted;
  }
  // The output faces by source.
  std::vector<std::tuple<FaceId, FaceId, FaceId>> by_source;
  for (FaceId o = 0; o < out.face_count(); ++o) {
    const auto [f, g] = result.sources[o];
    if ((f != kNoFace && f >= input.face_count()) || (g != kNoFace && g >= input.face_count())) {
      counted.problem = face_name(o) + " names a face out of range";
      return counted;
    }
    if (flips_allowed && flipped_quad(input, result, o)) continue;
    by_source.push_back({f, g, o});
  }
  std::sort(by_source.begin(), by_source.end());
  std::vector<Side> sides;
  std::vector<VertexId> centres;
  std::vector<Edge> inner;
  std::vector<FaceId> pieces;
  for (std::size_t i = 0, j = 0; i < by_source.size(); i = j) {
    const auto [f, g, first] = by_source[i];
    pieces.clear();
    for (; j < by_source.size() && std::get<0>(by_source[j]) == f && std::get<1>(by_source[j]) == g;
         ++j)
      pieces.push_back(std::get<2>(by_source[j]));
    const std::vector<VertexId> cycle = pre_split_face(input, f, g);
    if (cycle.empty()) {
      counted.problem = face_name(first) + ": its two source triangles share no edge";
      return counted;
    }
    const bool polygon = g == kNoFace && input.arity(f) != 3;
    const auto out_face = out.face(pieces[0]);
    const bool exactly = pieces.size() == 1 &&
                         std::equal(out_face.begin(), out_face.end(), cycle.begin(), cycle.end());
    if (polygon && polygons == KeptPolygons::kept) {
      if (!exactly) {
        counted.problem = "input polygon " + std::to_string(f) + " is not kept exactly (" +
                          face_name(pieces[0]) + ")";
        return counted;
      }
    }
    if (polygon && exactly && polygons != KeptPolygons::rebuilt) {
      for (std::size_t k = 0; k < cycle.size(); ++k)
        sides.push_back({undirected(cycle[k], cycle[(k + 1) % cycle.size()]), kNoVertex, first});
      continue;
    }
    if (pieces.size() == 1 && is_rotation_of(out_face, cycle)) {
      // The face as it was (a pair's quad, a polygon): no new vertex, nothing inside.
      for (std::size_t k = 0; k < cycle.size(); ++k)
        sides.push_back({undirected(cycle[k], cycle[(k + 1) % cycle.size()]), kNoVertex, first});
      // A face repeating a vertex is kept as it is; any other must be a quad.
      const bool repeats = std::set<VertexId>(cycle.begin(), cycle.end()).size() != cycle.size();
      if (cycle.size() != 4 && !repeats) {
        counted.problem = face_name(first) + " has " + std::to_string(cycle.size()) + " corners";
        return counted;
      }
      continue;
    }
    counted.problem = check_tiling(out, n, pieces, cycle, sides, centres, inner);
    if (!counted.problem.empty()) return counted;
  }
  counted.problem = check_sides(sides, centres, counted);
  if (counted.problem.empty() &&
      counted.split_edges + counted.centre_vertices != out.positions.size() - n) {
    counted.problem = std::to_string(out.positions.size() - n) + " vertices added, but " +
                      std::to_string(counted.split_edges) + " midpoints and " +
                      std::to_string(counted.centre_vertices) + " centres found";
  }
  if (counted.problem.empty()) counted.problem = check_inner_edges(out, inner);
  if (counted.problem.empty()) counted.problem = check_topology(input, out);
  return counted;
}

std::string check_all_quad_counts(const PolygonMesh& input, const QuadResult& result,
                                  const QuadOptions& options, const AllQuadCheck& counted) {
  const QuadStats& s = result.stats;
  const std::uint64_t added = result.mesh.positions.size() - input.positions.size();
  auto figures = [&] {
    return " (added_vertices " + std::to_string(s.added_vertices) + ", split_edges " +
           std::to_string(s.split_edges) + ", centre_vertices " +
           std::to_string(s.centre_vertices) + ", added_vertices_minimum " +
           std::to_string(s.added_vertices_minimum) + "; counted " + std::to_string(added) +
           " new vertices, " + std::to_string(counted.split_edges) + " midpoints, " +
           std::to_string(counted.centre_vertices) + " centres)";
  };
  if (s.added_vertices != added)
    return "added_vertices is not the count of new vertices" + figures();
  if (s.added_vertices != s.split_edges + s.centre_vertices)
    return "added_vertices is not split_edges + centre_vertices" + figures();
  if (s.split_edges != counted.split_edges || s.centre_vertices != counted.centre_vertices)
    return "split_edges or centre_vertices differ from the output's" + figures();
  if (s.added_vertices_minimum > s.split_edges) return "fewer splits than the minimum" + figures();
  if (options.objective == Objective::pairs &&
      (s.centre_vertices != 0 || s.split_edges != s.added_vertices_minimum)) {
    return "Objective::pairs must add exactly the minimum, no centre" + figures();
  }
  if (!(std::isfinite(s.split_quality_median) && std::isfinite(s.split_quality_p95) &&
        s.split_quality_median >= 0 && s.split_quality_median <= s.split_quality_p95)) {
    return "split quality median " + std::to_string(s.split_quality_median) + ", p95 " +
           std::to_string(s.split_quality_p95);
  }
  if (s.split_quads > result.mesh.face_count()) return "more split quads than faces";
  return {};
}

}  // namespace petersen::testing
