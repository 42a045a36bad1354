#include "result_check.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <span>
#include <unordered_set>
#include <utility>
#include <vector>

#include "all_quad_check.hpp"
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

// Each edge with the faces around it (in increasing order, a face once per side it has there),
// edges in increasing order: one sort of (edge, face) entries. With a map of vectors instead,
// fertility-sub3's test (576k triangles) took 59 s under load; 16.6 s quiet with this.
class FacesByEdge {
 public:
  using Group = std::pair<Edge, std::span<const FaceId>>;

  explicit FacesByEdge(const PolygonMesh& mesh) {
    std::vector<std::pair<Edge, FaceId>> entries;
    entries.reserve(mesh.corners.size());
    for (FaceId f = 0; f < mesh.face_count(); ++f) {
      const auto c = mesh.face(f);
      for (std::size_t k = 0; k < c.size(); ++k) {
        const VertexId a = c[k], b = c[(k + 1) % c.size()];
        if (a != b) entries.push_back({edge(a, b), f});
      }
    }
    std::sort(entries.begin(), entries.end());
    faces_.reserve(entries.size());
    for (const auto& entry : entries) faces_.push_back(entry.second);
    for (std::size_t i = 0, j = 0; i < entries.size(); i = j) {
      while (j < entries.size() && entries[j].first == entries[i].first) ++j;
      groups_.push_back({entries[i].first, std::span(faces_).subspan(i, j - i)});
    }
  }
  FacesByEdge(const FacesByEdge&) = delete;  // the groups point into faces_
  FacesByEdge& operator=(const FacesByEdge&) = delete;

  auto begin() const { return groups_.begin(); }
  auto end() const { return groups_.end(); }
  std::size_t size() const { return groups_.size(); }
  /// The faces around edge e; empty when no face has it.
  std::span<const FaceId> find(Edge e) const {
    const auto it = std::lower_bound(groups_.begin(), groups_.end(), e,
                                     [](const Group& g, const Edge& key) { return g.first < key; });
    return it != groups_.end() && it->first == e ? it->second : std::span<const FaceId>();
  }

 private:
  std::vector<FaceId> faces_;
  std::vector<Group> groups_;
};

// A face pair as one key, the smaller face first.
std::uint64_t pair_key(FaceId f, FaceId g) {
  return std::uint64_t{std::min(f, g)} << 32 | std::max(f, g);
}

// The vertices, each once, in increasing order.
std::vector<VertexId> distinct(std::vector<VertexId> vertices) {
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  return vertices;
}

// The distinct vertices of the faces.
std::vector<VertexId> vertices_of(const PolygonMesh& mesh, std::initializer_list<FaceId> faces) {
  std::vector<VertexId> vertices;
  for (FaceId f : faces)
    for (VertexId v : mesh.face(f)) vertices.push_back(v);
  return distinct(std::move(vertices));
}

bool is_triangle(const PolygonMesh& mesh, FaceId f) {
  const auto c = mesh.face(f);
  return c.size() == 3 && c[0] != c[1] && c[1] != c[2] && c[0] != c[2];
}

std::size_t first_corner(const PolygonMesh& mesh, FaceId f) {
  return mesh.all_triangles() ? 3 * std::size_t{f} : mesh.face_start[f];
}

// The corner of face f at vertex v (its first), or none.
std::optional<std::size_t> corner_at(const PolygonMesh& mesh, FaceId f, VertexId v) {
  const std::size_t first = first_corner(mesh, f);
  for (std::size_t c = first; c < first + mesh.arity(f); ++c)
    if (mesh.corners[c] == v) return c;
  return std::nullopt;
}

using Value = std::optional<std::array<double, 3>>;

// A corner's texture coordinate (cause uv_seam) or normal (normal_seam), as a value.
Value corner_value(const MeshAttributes& a, CutCause cause, std::size_t c) {
  const bool uv = cause == CutCause::uv_seam;
  const auto& index = uv ? a.corner_texcoord : a.corner_normal;
  if (index.empty() || index[c] == kNoAttribute) return std::nullopt;
  return (uv ? a.texcoords : a.normals)[index[c]];
}

std::optional<std::string> name_of(const std::pmr::vector<std::uint32_t>& index,
                                   const std::vector<std::string>& names, FaceId f) {
  if (index.empty() || index[f] == kNoAttribute) return std::nullopt;
  return names[index[f]];
}

// Whether face f of `a` and face g of `b` differ in the face attribute of `cause` (material,
// group, object, smoothing or face_property), by value.
bool face_differs(CutCause cause, const MeshAttributes& a, FaceId f, const MeshAttributes& b,
                  FaceId g) {
  switch (cause) {
    case CutCause::material:
      return name_of(a.face_material, a.material_names, f) !=
             name_of(b.face_material, b.material_names, g);
    case CutCause::group:
      return name_of(a.face_group, a.group_names, f) != name_of(b.face_group, b.group_names, g);
    case CutCause::object:
      return name_of(a.face_object, a.object_names, f) != name_of(b.face_object, b.object_names, g);
    case CutCause::smoothing:
      return (a.face_smoothing.empty() ? 0 : a.face_smoothing[f]) !=
             (b.face_smoothing.empty() ? 0 : b.face_smoothing[g]);
    default:
      if (a.face_properties.size() != b.face_properties.size()) return true;
      for (std::size_t k = 0; k < a.face_properties.size(); ++k) {
        if (a.face_properties[k].values[f] != b.face_properties[k].values[g]) return true;
      }
      return false;
  }
}

// Whether triangle f is flat shaded: each corner normal along the triangle's own normal, the
// cosine of their angle at least kFlatShadingCosine. Two flat-shaded triangles make no normal
// seam.
bool flat_shaded(const PolygonMesh& mesh, FaceId f) {
  const MeshAttributes& a = mesh.attributes;
  if (mesh.arity(f) != 3 || a.corner_normal.empty()) return false;
  const std::size_t first = first_corner(mesh, f);
  std::array<std::array<double, 3>, 3> p;
  for (int k = 0; k < 3; ++k) p[k] = mesh.positions[mesh.corners[first + k]];
  const double u[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
  const double v[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
  const double m[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                       u[0] * v[1] - u[1] * v[0]};
  const double m_length = std::hypot(m[0], m[1], m[2]);
  if (!(m_length > 0) || !std::isfinite(m_length)) return false;
  for (std::size_t c = first; c < first + 3; ++c) {
    if (a.corner_normal[c] == kNoAttribute) return false;
    const auto& n = a.normals[a.corner_normal[c]];
    const double dot = n[0] * m[0] + n[1] * m[1] + n[2] * m[2];
    if (!(dot >= kFlatShadingCosine * std::hypot(n[0], n[1], n[2]) * m_length)) return false;
  }
  return true;
}

constexpr CutCause kCornerCauses[] = {CutCause::uv_seam, CutCause::normal_seam};
constexpr CutCause kFaceCauses[] = {CutCause::material, CutCause::group, CutCause::object,
                                    CutCause::smoothing, CutCause::face_property};

}  // namespace

std::int64_t euler_characteristic(const PolygonMesh& mesh) {
  const std::vector<VertexId> vertices = distinct({mesh.corners.begin(), mesh.corners.end()});
  return std::int64_t(vertices.size()) - std::int64_t(FacesByEdge(mesh).size()) +
         std::int64_t(mesh.face_count());
}

// Whether an extra cut forbids pairing triangles f and g across their edge (a, b).
bool extra_cut(const PolygonMesh& mesh, const CutOptions& cuts, std::span<const CutCause> cross,
               FaceId f, FaceId g, Edge e) {
  // The attribute cuts quadrangulate makes unless crossed or set by the caller, by value.
  auto given = [&](CutCause cause) {
    switch (cause) {
      case CutCause::uv_seam:
        return !cuts.corner_uv.empty();
      case CutCause::normal_seam:
        return !cuts.corner_normal.empty();
      case CutCause::material:
        return !cuts.face_material.empty();
      case CutCause::group:
        return !cuts.face_group.empty();
      case CutCause::object:
        return !cuts.face_object.empty();
      case CutCause::smoothing:
        return !cuts.face_smoothing.empty();
      default:
        return !cuts.face_property.empty();
    }
  };
  auto applies = [&](CutCause cause) {
    return !given(cause) && std::find(cross.begin(), cross.end(), cause) == cross.end();
  };
  const MeshAttributes& a = mesh.attributes;
  for (CutCause cause : kCornerCauses) {
    if (!applies(cause)) continue;
    if (cause == CutCause::normal_seam && flat_shaded(mesh, f) && flat_shaded(mesh, g)) continue;
    for (VertexId v : {e.first, e.second}) {
      if (corner_value(a, cause, *corner_at(mesh, f, v)) !=
          corner_value(a, cause, *corner_at(mesh, g, v))) {
        return true;
      }
    }
  }
  for (CutCause cause : kFaceCauses)
    if (applies(cause) && face_differs(cause, a, f, a, g)) return true;

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
    // A fold within 1e-9 degrees of the option is that angle: not more.
    if (degrees > *cuts.sharp_angle_degrees + 1e-9) return true;
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

namespace {

// The size of a maximum matching of the graph, by LEMON and, on graphs of at most 20,000 nodes, by
// Boost too (its Edmonds is far slower than LEMON's: over 300 s at 1.4M nodes); none when they
// disagree. The tests check one mesh once per algorithm, so the last graph's answer is kept and
// given again when the same graph (compared edge by edge) comes next: Boost on homer's graph was
// 76 % of its shared-mesh test under ASan, computed eight times.
std::optional<std::uint32_t> maximum_matching_size(std::uint32_t nodes,
                                                   std::span<const std::array<NodeId, 2>> edges) {
  struct Answered {
    std::uint32_t nodes = 0;
    std::vector<std::array<NodeId, 2>> edges;
    std::optional<std::uint32_t> maximum;
  };
  static std::optional<Answered> last;
  if (last && last->nodes == nodes && std::ranges::equal(last->edges, edges)) return last->maximum;
  std::optional<std::uint32_t> maximum = lemon_matching_size(nodes, edges);
  if (nodes <= 20000 && *maximum != boost_matching_size(nodes, edges)) maximum.reset();
  last = Answered{nodes, {edges.begin(), edges.end()}, maximum};
  return maximum;
}

// The pairing part of check_quad_result: every input face used once, the pairs pairable, and when
// `maximum` their number a maximum (by the peers) and the witness; else (Objective::quads, which
// may leave triangles) the optimum certified, and maximum_certified only when it is one. With
// all_quad the pieces of a split face are left to check_all_quad_mesh.
std::string check_pairing(const PolygonMesh& input, const QuadResult& result, bool all_quad,
                          bool flips_allowed, const CutOptions& cuts,
                          std::span<const CutCause> cross,
                          std::optional<double> max_corner_deviation, bool maximum_wanted = true) {
  const std::uint32_t faces = static_cast<std::uint32_t>(input.face_count());
  // The pairable graph, by definition: an edge in exactly two faces, both triangles without a
  // repeated vertex, whose union has four vertices.
  std::vector<NodeId> node_of(faces, kNoNode);
  std::uint32_t nodes = 0;
  for (FaceId f = 0; f < faces; ++f)
    if (input.arity(f) == 3) node_of[f] = nodes++;
  std::unordered_set<std::uint64_t> pairable;
  pairable.reserve(faces);
  std::vector<std::array<NodeId, 2>> edges;
  for (const auto& [e, fs] : FacesByEdge(input)) {
    if (fs.size() != 2 || fs[0] == fs[1] || !is_triangle(input, fs[0]) ||
        !is_triangle(input, fs[1])) {
      continue;
    }
    if (vertices_of(input, {fs[0], fs[1]}).size() != 4 ||
        extra_cut(input, cuts, cross, fs[0], fs[1], e))
      continue;
    if (max_corner_deviation &&
        pair_cost(input, std::min(fs[0], fs[1]), std::max(fs[0], fs[1])) > *max_corner_deviation) {
      continue;
    }
    pairable.insert(pair_key(fs[0], fs[1]));
    edges.push_back({node_of[fs[0]], node_of[fs[1]]});
  }
  const std::optional<std::uint32_t> peers_maximum = maximum_matching_size(nodes, edges);
  if (!peers_maximum) return "LEMON and Boost disagree";
  const std::uint32_t maximum = *peers_maximum;

  // Every input face used exactly once; the matching the quads make, on the test's own graph.
  std::vector<int> uses(faces, 0);
  std::vector<FaceId> partner(faces, kNoFace);
  std::uint64_t pairs = 0, left = 0;
  std::unordered_set<std::uint64_t> seen_pairs;
  seen_pairs.reserve(result.mesh.face_count());
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
        if (t != kNoFace && seen_pairs.insert(pair_key(t, kNoFace)).second) ++uses[t];
      continue;
    }
    if (g == kNoFace) {
      // Kept or left: exactly the input face, unless all_quad split or rebuilt it.
      if (!all_quad &&
          !std::equal(out.begin(), out.end(), input.face(f).begin(), input.face(f).end())) {
        return "output face " + std::to_string(o) + " differs from its input face " +
               std::to_string(f);
      }
      if (seen_pairs.insert(pair_key(f, kNoFace)).second) {
        ++uses[f];
        left += input.arity(f) == 3;
      }
      continue;
    }
    if (!seen_pairs.insert(pair_key(f, g)).second) continue;  // a split piece
    ++uses[f];
    ++uses[g];
    ++pairs;
    if (!pairable.count(pair_key(f, g))) {
      return "faces " + std::to_string(f) + " and " + std::to_string(g) +
             " are paired across a cut";
    }
    partner[f] = g;
    partner[g] = f;
    if (!all_quad) {
      // The quad is the union of the two triangles, in f's orientation.
      std::vector<VertexId> quad(out.begin(), out.end());
      std::sort(quad.begin(), quad.end());
      if (out.size() != 4 || quad != vertices_of(input, {f, g}))
        return "quad " + std::to_string(o) + " is not its pair";
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
  if (!maximum_wanted) {
    if (!result.stats.optimality_certified) return "the least-cost pairing is not certified";
    if (result.stats.triangles_left < nodes - 2 * maximum) {
      return "triangles_left " + std::to_string(result.stats.triangles_left) +
             " but the maximum leaves " + std::to_string(nodes - 2 * maximum);
    }
    const bool is_maximum = result.stats.triangles_left == nodes - 2 * maximum;
    if (result.stats.maximum_certified && !is_maximum) return "maximum_certified on a non-maximum";
    if (pairs != result.stats.pairs && !flips_allowed) return "pair count differs";
    return {};
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
  return {};
}

}  // namespace

std::string check_quad_result(const PolygonMesh& input, const QuadResult& result, bool all_quad,
                              bool flips_allowed, const CutOptions& cuts,
                              std::span<const CutCause> cross,
                              std::optional<double> max_corner_deviation) {
  std::string problem =
      check_pairing(input, result, all_quad, flips_allowed, cuts, cross, max_corner_deviation);
  if (problem.empty() && all_quad)
    problem = check_all_quad_mesh(input, result, KeptPolygons::either, flips_allowed).problem;
  return problem;
}

std::string check_quad_result(const PolygonMesh& input, const QuadResult& result,
                              const QuadOptions& options) {
  const bool flips_allowed = std::holds_alternative<Lrs>(options.algorithm);
  std::string problem =
      check_pairing(input, result, options.all_quad, flips_allowed, options.cuts, options.cross,
                    options.max_corner_deviation, options.objective != Objective::quads);
  if (!problem.empty() || !options.all_quad) return problem;
  const AllQuadCheck counted = check_all_quad_mesh(
      input, result, options.keep_polygons ? KeptPolygons::kept : KeptPolygons::rebuilt,
      flips_allowed);
  if (!counted.problem.empty()) return counted.problem;
  return check_all_quad_counts(input, result, options, counted);
}

}  // namespace petersen::testing

namespace petersen::testing {

namespace {

bool close(double x, double y) {
  return std::abs(x - y) <= 1e-9 * (1 + std::abs(x));
}

bool close(const Value& x, const Value& y) {
  if (x.has_value() != y.has_value()) return false;
  if (!x) return true;
  for (int d = 0; d < 3; ++d)
    if (!close((*x)[d], (*y)[d])) return false;
  return true;
}

}  // namespace

std::string check_attributes_kept(const PolygonMesh& input, const QuadResult& result) {
  const MeshAttributes &a = input.attributes, &b = result.mesh.attributes;
  const PolygonMesh& out = result.mesh;
  try {
    check_attributes(out);
  } catch (const MeshError& e) {
    return std::string("output attributes: ") + e.what();
  }
  if (a.corner_texcoord.empty() != b.corner_texcoord.empty() ||
      a.corner_normal.empty() != b.corner_normal.empty() ||
      a.has_face_attributes() != b.has_face_attributes() ||
      a.vertex_properties.size() != b.vertex_properties.size() ||
      a.material_libraries != b.material_libraries) {
    return "the output does not have the input's kinds of attributes";
  }
  const std::size_t n = input.positions.size();
  for (std::size_t k = 0; k < a.vertex_properties.size(); ++k) {
    const PropertyColumn &x = a.vertex_properties[k], &y = b.vertex_properties[k];
    if (x.name != y.name || x.type != y.type) return "vertex property " + x.name + " renamed";
    for (std::size_t v = 0; v < n; ++v) {
      if (x.values[v] != y.values[v]) {
        return "vertex property " + x.name + " of vertex " + std::to_string(v) + " changed";
      }
    }
  }
  for (FaceId o = 0; o < out.face_count(); ++o) {
    const auto [f, g] = result.sources[o];
    const auto face = out.face(o);
    const bool as_it_was =
        f != kNoFace && g == kNoFace &&
        std::equal(face.begin(), face.end(), input.face(f).begin(), input.face(f).end());
    // lrs: a quad with a triangle its flips made has no input corners to compare with; it may
    // only be made where the input has no corner or face attributes.
    if (f == kNoFace || (g == kNoFace && !as_it_was && result.stats.flipped_edges > 0)) {
      if (a.has_corner_attributes() || a.has_face_attributes()) {
        return "output face " + std::to_string(o) + " has attributes but no source triangles";
      }
      continue;
    }
    for (CutCause cause : kFaceCauses) {
      if (face_differs(cause, a, f, b, o)) {
        return "output face " + std::to_string(o) + " has another " +
               std::string(to_string(cause)) + " than its source " + std::to_string(f);
      }
    }
    // The corner of the source triangles at input vertex u: the first's, else the second's.
    auto source_corner = [&](VertexId u) {
      if (auto c = corner_at(input, f, u)) return c;
      return g == kNoFace ? std::nullopt : corner_at(input, g, u);
    };
    for (std::size_t k = 0; k < face.size(); ++k) {
      const VertexId v = face[k];
      const std::size_t oc = first_corner(out, o) + k;
      // The values corner k must have when v was made from `parents` (itself, an edge's ends, a
      // quad's corners): empty when it has them, else what differs.
      auto mismatch = [&](const std::vector<VertexId>& parents) -> std::string {
        std::string of;
        for (VertexId u : parents) {
          of += ' ';  // an append: " " + std::to_string gives GCC 12 a false -Wrestrict
          of += std::to_string(u);
        }
        const std::string where = " of vertex " + std::to_string(v) + " in output face " +
                                  std::to_string(o) + ", made from vertices" + of;
        if (v >= n) {
          for (std::size_t c = 0; c < a.vertex_properties.size(); ++c) {
            const PropertyColumn& column = a.vertex_properties[c];
            double sum = 0;
            for (VertexId u : parents) sum += column.values[u];
            double expected = sum / double(parents.size());
            if (column.type == ScalarType::float32) {
              expected = static_cast<float>(expected);  // a float column holds floats
            } else if (column.type != ScalarType::float64) {
              expected = std::round(expected);
            }
            if (!close(expected, b.vertex_properties[c].values[v])) {
              return "vertex property " + column.name + where + ", is " +
                     std::to_string(b.vertex_properties[c].values[v]) + ", not their average " +
                     std::to_string(expected);
            }
          }
        }
        for (CutCause cause : kCornerCauses) {
          Value expected;
          if (as_it_was) {
            expected = corner_value(a, cause, first_corner(input, f) + k);
          } else {
            std::array<double, 3> sum{0, 0, 0};
            bool all_have = true, all_equal = true;
            Value first_value;
            for (VertexId u : parents) {
              const auto corner = source_corner(u);
              if (!corner) return "vertex " + std::to_string(u) + " is in no source face" + where;
              const Value x = corner_value(a, cause, *corner);
              all_have &= x.has_value();
              if (u == parents.front()) first_value = x;
              all_equal &= x == first_value;
              if (x)
                for (int d = 0; d < 3; ++d) sum[d] += (*x)[d];
            }
            for (double& x : sum) x /= double(parents.size());
            // Equal values blend to themselves: a normal that is not quite of unit length (four
            // decimals in a file) is kept as it is rather than renormalised.
            if (all_equal && first_value) {
              sum = *first_value;
            } else if (cause == CutCause::normal_seam && parents.size() > 1) {
              const double length = std::hypot(sum[0], sum[1], sum[2]);
              if (length > 0)
                for (double& x : sum) x /= length;
            }
            if (all_have) expected = sum;
          }
          if (!close(expected, corner_value(b, cause, oc))) {
            return std::string(cause == CutCause::uv_seam ? "texture coordinate" : "normal") +
                   " of corner " + std::to_string(k) + where +
                   ", is not the value of the source corners";
          }
        }
        return {};
      };
      if (v < n) {
        if (std::string problem = mismatch({v}); !problem.empty()) return problem;
        continue;
      }
      // A new vertex: the midpoint of a side of its sources (their shared edge excepted) or the
      // centre of their four vertices, found by its position; where a flat or folded quad puts
      // two of these on one point, either may be the one.
      const auto& p = out.positions[v];
      // Float positions (a float PLY's) hold floats: the average rounded to float.
      const bool floats = input.attributes.position_type == ScalarType::float32;
      auto at = [&](const std::vector<VertexId>& us) {
        for (int d = 0; d < 3; ++d) {
          double sum = 0;
          for (VertexId u : us) sum += input.positions[u][d];
          const double average = sum / double(us.size());
          if (!close(floats ? static_cast<float>(average) : average, p[d])) return false;
        }
        return true;
      };
      std::vector<std::vector<VertexId>> candidates;
      std::vector<VertexId> all;
      for (FaceId s : {f, g}) {
        if (s == kNoFace) continue;
        const auto c = input.face(s);
        for (std::size_t i = 0; i < c.size(); ++i) {
          const VertexId u = c[i], w = c[(i + 1) % c.size()];
          const bool shared = g != kNoFace && corner_at(input, f, u) && corner_at(input, f, w) &&
                              corner_at(input, g, u) && corner_at(input, g, w);
          if (!shared && at({u, w})) candidates.push_back({u, w});
          if (std::find(all.begin(), all.end(), u) == all.end()) all.push_back(u);
        }
      }
      if (all.size() == 4 && at(all)) candidates.push_back(all);
      if (candidates.empty()) {
        return "new vertex " + std::to_string(v) + " of output face " + std::to_string(o) +
               " is no midpoint of a side nor the centre of its sources";
      }
      std::string problem;
      for (const auto& parents : candidates) {
        problem = mismatch(parents);
        if (problem.empty()) break;
      }
      if (!problem.empty()) return problem;
    }
  }
  return {};
}

}  // namespace petersen::testing
