#include "petersen/dualize/pairable_graph.hpp"

#include <string>

#include "edge_groups.hpp"

namespace petersen {

std::string_view to_string(CutCause cause) {
  constexpr std::string_view kNames[kCutCauses] = {"boundary", "non_manifold", "polygon",
                                                   "degenerate", "duplicate"};
  return kNames[static_cast<int>(cause)];
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

}  // namespace

PairableGraph build_pairable_graph(const PolygonMesh& mesh) {
  check_faces(mesh);
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
    graph.inconsistent_edges += half.from(h1) == half.from(h2);
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
