#include "petersen/dualize/dual.hpp"

#include <string>

#include "petersen/mesh/edge_groups.hpp"

namespace petersen {

namespace {

std::string edge_name(VertexId a, VertexId b) {
  return "edge (" + std::to_string(a) + ", " + std::to_string(b) + ")";
}

void check_corners(const TriangleMesh& mesh) {
  const std::size_t vertex_count = mesh.positions.size();
  // 3F halfedges and 3F/2 dual edges must fit in 32-bit ids.
  if (mesh.triangles.size() > 0x55555555u) {
    throw MeshError("mesh has " + std::to_string(mesh.triangles.size()) +
                    " triangles; at most 1431655765 are supported");
  }
  for (FaceId t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    for (VertexId v : tri) {
      if (v >= vertex_count) {
        throw MeshError("triangle " + std::to_string(t) + " has corner " + std::to_string(v) +
                        " out of range (" + std::to_string(vertex_count) + " vertices)");
      }
    }
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0]) {
      throw MeshError("triangle " + std::to_string(t) + " is degenerate (corners " +
                      std::to_string(tri[0]) + ", " + std::to_string(tri[1]) + ", " +
                      std::to_string(tri[2]) + ")");
    }
  }
}

}  // namespace

Dual build_dual(const TriangleMesh& mesh) {
  check_corners(mesh);
  const std::uint32_t face_count = static_cast<std::uint32_t>(mesh.triangles.size());
  const std::uint32_t halfedge_count = 3 * face_count;
  auto from = [&](HalfedgeId h) { return halfedge_from(mesh, h); };
  auto to = [&](HalfedgeId h) { return halfedge_to(mesh, h); };
  EdgeGroups groups = group_halfedges(mesh, {});
  const auto& start = groups.start;
  auto& bucket = groups.entries;
  const std::size_t vertex_count = mesh.positions.size();

  // Dual edge e is written over bucket[e]: by then the 2e + 2 entries its edges consumed lie
  // behind the read position, so the bucket's memory doubles as the edge list.
  // node_edges[3t + k], the dual edge across edge k of triangle t, keeps the triangle's order.
  HugeVector<EdgeId> node_edges(halfedge_count);
  auto& edges = bucket;
  EdgeId edge_count = 0;
  for (std::size_t v = 0; v < vertex_count; ++v) {
    const auto first = bucket.begin() + start[v], last = bucket.begin() + start[v + 1];
    for (auto group = first; group != last;) {
      auto end = group + 1;
      while (end != last && (*end)[0] == (*group)[0]) ++end;
      const HalfedgeId h1 = (*group)[1];
      const VertexId a = from(h1), b = to(h1);
      const FaceId t1 = h1 / 3;
      if (end - group == 1) {
        throw MeshError("boundary " + edge_name(a, b) + ": only triangle " + std::to_string(t1) +
                        " has it");
      }
      if (end - group > 2) {
        throw MeshError("non-manifold " + edge_name(a, b) + ": in " + std::to_string(end - group) +
                        " triangles (" + std::to_string(t1) + ", " +
                        std::to_string(group[1][1] / 3) + ", " + std::to_string(group[2][1] / 3) +
                        (end - group > 3 ? ", ...)" : ")"));
      }
      const HalfedgeId h2 = group[1][1];
      if (from(h2) == a) {
        throw MeshError("inconsistent orientation at " + edge_name(a, b) + ": triangles " +
                        std::to_string(t1) + " and " + std::to_string(h2 / 3) + " both run from " +
                        std::to_string(a) + " to " + std::to_string(b));
      }
      node_edges[h1] = node_edges[h2] = edge_count;
      edges[edge_count++] = {h1 / 3, h2 / 3};
      group = end;
    }
  }
  HugeVector<NodeId> edge_ends(2 * std::size_t{edge_count});
  for (EdgeId e = 0; e < edge_count; ++e) {
    edge_ends[2 * e] = edges[e][0];
    edge_ends[2 * e + 1] = edges[e][1];
  }
  bucket = {};
  // Every halfedge has exactly one twin in another triangle: from_incidence cannot fail here.
  return Dual{CubicGraph::from_incidence(std::move(node_edges), std::move(edge_ends))};
}

CubicGraph dual_graph(const TriangleMesh& mesh) {
  return build_dual(mesh).graph;
}

}  // namespace petersen
