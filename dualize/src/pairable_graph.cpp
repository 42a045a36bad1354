#include "petersen/dualize/pairable_graph.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "edge_groups.hpp"

namespace petersen {

namespace {

constexpr std::string_view kCauseNames[kCutCauses] = {
    "boundary", "non_manifold", "polygon",   "degenerate",    "duplicate",
    "user",     "sharp",        "uv_seam",   "normal_seam",   "material",
    "group",    "object",       "smoothing", "face_property", "shape"};

}  // namespace

std::string_view to_string(CutCause cause) {
  return kCauseNames[static_cast<int>(cause)];
}

std::optional<CutCause> parse_cut_cause(std::string_view name) {
  for (int c = 0; c < kCutCauses; ++c)
    if (kCauseNames[c] == name) return CutCause(c);
  return std::nullopt;
}

namespace {

// Corners in range, three or more per face, ids that fit: checked once at the door.
void check_faces(const PolygonMesh& mesh) {
  const std::size_t faces = mesh.face_count();
  // Halfedges (one per corner) and nodes are 32-bit; 3 per triangle and 3/2 edges per triangle.
  if (mesh.corners.size() > 0xFFFFFFF0u) {
    throw MeshError("mesh has " + std::to_string(mesh.corners.size()) +
                    " face corners; at most 4294967280 are supported");
  }
  const std::size_t vertex_count = mesh.positions.size();
  for (std::size_t f = 0; f < faces; ++f) {
    const auto corners = mesh.face(static_cast<FaceId>(f));
    if (corners.size() < 3) {
      throw MeshError("face " + std::to_string(f) + " has " + std::to_string(corners.size()) +
                      " corners; a face needs at least 3");
    }
    for (VertexId v : corners) {
      if (v >= vertex_count) {
        throw MeshError("face " + std::to_string(f) + " has corner " + std::to_string(v) +
                        " out of range (" + std::to_string(vertex_count) + " vertices)");
      }
    }
  }
}

bool repeats_a_vertex(std::span<const VertexId> corners) {
  for (std::size_t i = 0; i < corners.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (corners[i] == corners[j]) return true;
  return false;
}

void check_sizes(const PolygonMesh& mesh, const CutOptions& cuts) {
  auto check = [](std::span<const std::uint32_t> ids, std::size_t expected, const char* name) {
    if (!ids.empty() && ids.size() != expected) {
      throw MeshError(std::string(name) + " has " + std::to_string(ids.size()) + " entries for " +
                      std::to_string(expected));
    }
  };
  check(cuts.corner_uv, mesh.corners.size(), "texture coordinate ids per corner");
  check(cuts.corner_normal, mesh.corners.size(), "normal ids per corner");
  check(cuts.face_material, mesh.face_count(), "materials per face");
  check(cuts.face_group, mesh.face_count(), "groups per face");
  check(cuts.face_object, mesh.face_count(), "objects per face");
  check(cuts.face_smoothing, mesh.face_count(), "smoothing groups per face");
  check(cuts.face_property, mesh.face_count(), "face properties per face");
  for (const auto& [a, b] : cuts.user_edges) {
    if (a >= mesh.positions.size() || b >= mesh.positions.size()) {
      throw MeshError("cut edge (" + std::to_string(a) + ", " + std::to_string(b) +
                      ") names a vertex out of range (" + std::to_string(mesh.positions.size()) +
                      " vertices)");
    }
  }
}

std::array<double, 3> normal_of(const PolygonMesh& mesh, std::span<const VertexId> t) {
  const auto& p = mesh.positions;
  std::array<double, 3> u, v;
  for (int d = 0; d < 3; ++d) {
    u[d] = p[t[1]][d] - p[t[0]][d];
    v[d] = p[t[2]][d] - p[t[0]][d];
  }
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

}  // namespace

PairableGraph build_pairable_graph(const PolygonMesh& mesh, const CutOptions& cuts) {
  check_faces(mesh);
  check_sizes(mesh, cuts);
  std::vector<std::uint64_t> user_edges;
  for (const auto& [a, b] : cuts.user_edges) {
    user_edges.push_back(std::uint64_t{std::min(a, b)} << 32 | std::max(a, b));
  }
  std::sort(user_edges.begin(), user_edges.end());
  const bool triangles_only = mesh.all_triangles();
  const std::uint32_t face_count = static_cast<std::uint32_t>(mesh.face_count());
  const std::uint32_t halfedge_count = static_cast<std::uint32_t>(mesh.corners.size());

  const PolygonHalfedges half(mesh);

  // Triangles become nodes in face order; a face repeating a vertex is degenerate.
  PairableGraph graph;
  HugeVector<NodeId> face_node;
  std::vector<std::uint8_t> degenerate(face_count, 0);
  for (FaceId f = 0; f < face_count; ++f) degenerate[f] = repeats_a_vertex(mesh.face(f));
  if (triangles_only) {
    graph.node_count = face_count;
  } else {
    face_node.assign(face_count, kNoNode);
    for (FaceId f = 0; f < face_count; ++f) {
      if (mesh.arity(f) != 3) continue;
      face_node[f] = graph.node_count++;
      graph.node_face.push_back(f);
    }
  }
  auto node_of = [&](FaceId f) { return triangles_only ? f : face_node[f]; };

  const EdgeGroups groups = half.group();
  graph.node_edges.assign(3 * std::size_t{graph.node_count}, kNoEdge);
  HugeVector<NodeId>& ends = graph.edge_ends;
  ends.reserve(triangles_only ? halfedge_count : 0);
  auto cut = [&](CutCause cause) { ++graph.cuts.by_cause[static_cast<int>(cause)]; };
  const auto& entries = groups.entries;
  for_each_edge_group(groups, [&](std::uint32_t first, std::uint32_t end) {
    ++graph.mesh_edges;
    const std::uint32_t copies = end - first;
    const std::uint32_t h1 = entries[first][1];
    const std::uint32_t h2 = copies == 2 ? entries[first + 1][1] : 0;
    if (copies == 1) return cut(CutCause::boundary);
    if (copies > 2) return cut(CutCause::non_manifold);
    const FaceId f1 = half.face(h1), f2 = half.face(h2);
    if (f1 == f2 || degenerate[f1] || degenerate[f2]) return cut(CutCause::degenerate);
    if (mesh.arity(f1) != 3 || mesh.arity(f2) != 3) return cut(CutCause::polygon);
    // The corner of each triangle opposite the shared edge: after its end.
    const std::uint32_t k1 = h1 - half.first(f1), k2 = h2 - half.first(f2);
    const VertexId opposite1 = mesh.corners[half.first(f1) + (k1 + 2) % 3];
    const VertexId opposite2 = mesh.corners[half.first(f2) + (k2 + 2) % 3];
    if (opposite1 == opposite2) return cut(CutCause::duplicate);
    const VertexId a = half.from(h1), b = half.to(h1);
    const bool same_way = half.from(h2) == a;
    if (!user_edges.empty() &&
        std::binary_search(user_edges.begin(), user_edges.end(),
                           std::uint64_t{std::min(a, b)} << 32 | std::max(a, b))) {
      return cut(CutCause::user);
    }
    if (cuts.sharp_angle_degrees) {
      const auto n1 = normal_of(mesh, mesh.face(f1));
      auto n2 = normal_of(mesh, mesh.face(f2));
      if (same_way)
        for (double& x : n2) x = -x;  // orient f2 as f1
      const double dot = n1[0] * n2[0] + n1[1] * n2[1] + n1[2] * n2[2];
      const double norms = std::sqrt((n1[0] * n1[0] + n1[1] * n1[1] + n1[2] * n1[2]) *
                                     (n2[0] * n2[0] + n2[1] * n2[1] + n2[2] * n2[2]));
      // A zero-area triangle has no normal: its fold is unknown, so the edge is cut.
      if (!(norms > 0)) return cut(CutCause::sharp);
      // The fold in degrees, compared as the option says ("more than DEG"): comparing cosines
      // instead cut a cube's exact 90-degree edges at DEG = 90, since cos(90°) is 6e-17, not 0.
      const double fold = std::acos(std::clamp(dot / norms, -1.0, 1.0)) * 180.0 / std::numbers::pi;
      if (fold > *cuts.sharp_angle_degrees) return cut(CutCause::sharp);
    }
    // The corners of a and b in each face: h1 is a's corner in f1; in f2, a's corner is h2 when
    // f2 runs along the edge the same way, else the next one.
    const std::uint32_t a2 = same_way ? h2 : half.next(h2), b2 = same_way ? half.next(h2) : h2;
    auto seam = [&](std::span<const std::uint32_t> id) {
      return !id.empty() && (id[h1] != id[a2] || id[half.next(h1)] != id[b2]);
    };
    if (seam(cuts.corner_uv)) return cut(CutCause::uv_seam);
    if (seam(cuts.corner_normal)) return cut(CutCause::normal_seam);
    auto border = [&](std::span<const std::uint32_t> id) {
      return !id.empty() && id[f1] != id[f2];
    };
    if (border(cuts.face_material)) return cut(CutCause::material);
    if (border(cuts.face_group)) return cut(CutCause::group);
    if (border(cuts.face_object)) return cut(CutCause::object);
    if (border(cuts.face_smoothing)) return cut(CutCause::smoothing);
    if (border(cuts.face_property)) return cut(CutCause::face_property);
    graph.inconsistent_edges += same_way;
    const EdgeId e = graph.edge_count();
    const NodeId n1 = node_of(f1), n2 = node_of(f2);
    graph.node_edges[3 * std::size_t{n1} + k1] = e;
    graph.node_edges[3 * std::size_t{n2} + k2] = e;
    ends.push_back(n1);
    ends.push_back(n2);
  });
  graph.cubic = 2 * std::size_t{graph.edge_count()} == graph.node_edges.size();
  return graph;
}

}  // namespace petersen
