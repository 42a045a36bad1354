#include "petersen/dualize/dual.hpp"

#include <string>

#include "petersen/mesh/edge_groups.hpp"

namespace petersen {

namespace {

std::string edge_name(VertexId a, VertexId b) {
  return "edge (" + std::to_string(a) + ", " + std::to_string(b) + ")";
}

// Throws MeshError naming the first triangle with a corner out of range or a repeated corner,
// and refuses meshes past 32-bit halfedge and dual edge ids. corner(t, k) is corner k of t.
template <class Corner>
void check_corners(std::size_t face_count, std::size_t vertex_count, Corner corner) {
  // 3F halfedges and 3F/2 dual edges must fit in 32-bit ids.
  if (face_count > 0x55555555u) {
    throw MeshError("mesh has " + std::to_string(face_count) +
                    " triangles; at most 1431655765 are supported");
  }
  for (FaceId t = 0; t < face_count; ++t) {
    const VertexId tri[3] = {corner(t, 0), corner(t, 1), corner(t, 2)};
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

// Throws MeshError for an edge whose group of halfedges [group, end) is not two triangles
// running along it in opposite directions; from(h) and to(h) are halfedge h's ends.
template <class Entry, class From, class To>
void check_edge(Entry group, Entry end, From from, To to) {
  const HalfedgeId h1 = (*group)[1];
  const VertexId a = from(h1), b = to(h1);
  const FaceId t1 = h1 / 3;
  if (end - group == 1) {
    throw MeshError("boundary " + edge_name(a, b) + ": only triangle " + std::to_string(t1) +
                    " has it");
  }
  if (end - group > 2) {
    throw MeshError("non-manifold " + edge_name(a, b) + ": in " + std::to_string(end - group) +
                    " triangles (" + std::to_string(t1) + ", " + std::to_string(group[1][1] / 3) +
                    ", " + std::to_string(group[2][1] / 3) + (end - group > 3 ? ", ...)" : ")"));
  }
  const HalfedgeId h2 = group[1][1];
  if (from(h2) == a) {
    throw MeshError("inconsistent orientation at " + edge_name(a, b) + ": triangles " +
                    std::to_string(t1) + " and " + std::to_string(h2 / 3) + " both run from " +
                    std::to_string(a) + " to " + std::to_string(b));
  }
}

// The dual of the triangles t < face_count with corners corner(t, 0..2) over vertex_count
// vertices (see build_dual).
template <class Corner>
Dual dual_of(std::size_t face_count_in, std::size_t vertex_count, Corner corner) {
  check_corners(face_count_in, vertex_count, corner);
  const std::uint32_t face_count = static_cast<std::uint32_t>(face_count_in);
  const std::uint32_t halfedge_count = 3 * face_count;
  auto from = [&](HalfedgeId h) { return corner(h / 3, h % 3); };
  auto to = [&](HalfedgeId h) { return corner(h / 3, (h % 3 + 1) % 3); };
  EdgeGroups groups =
      group_halfedges(vertex_count, halfedge_count, from, to, [](HalfedgeId) { return true; });
  const auto& start = groups.start;
  auto& bucket = groups.entries;

  // Dual edge e is written over bucket[e]: by then the 2e + 2 entries its edges consumed lie
  // behind the read position, so the bucket's memory doubles as the edge list.
  // node_edges[3t + k], the dual edge across edge k of triangle t, keeps the triangle's order.
  std::pmr::vector<EdgeId> node_edges(halfedge_count);
  auto& edges = bucket;
  EdgeId edge_count = 0;
  for (std::size_t v = 0; v < vertex_count; ++v) {
    const auto first = bucket.begin() + start[v], last = bucket.begin() + start[v + 1];
    for (auto group = first; group != last;) {
      auto end = group + 1;
      while (end != last && (*end)[0] == (*group)[0]) ++end;
      check_edge(group, end, from, to);
      const HalfedgeId h1 = (*group)[1], h2 = group[1][1];
      node_edges[h1] = node_edges[h2] = edge_count;
      edges[edge_count++] = {h1 / 3, h2 / 3};
      group = end;
    }
  }
  std::pmr::vector<NodeId> edge_ends(2 * std::size_t{edge_count});
  for (EdgeId e = 0; e < edge_count; ++e) {
    edge_ends[2 * e] = edges[e][0];
    edge_ends[2 * e + 1] = edges[e][1];
  }
  bucket = {};
  // Every halfedge has exactly one twin in another triangle: from_incidence cannot fail here.
  return Dual{CubicGraph::from_incidence(std::move(node_edges), std::move(edge_ends))};
}

}  // namespace

Dual build_dual(const PolygonMesh& mesh) {
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    if (mesh.arity(f) != 3) {
      throw MeshError("face " + std::to_string(f) + " has " + std::to_string(mesh.arity(f)) +
                      " corners; the dual is built on triangles only");
    }
  }
  // Every face a triangle: face t's corners are corners[3t..3t + 2], whatever face_start holds.
  const VertexId* corners = mesh.corners.data();
  return dual_of(mesh.face_count(), mesh.positions.size(),
                 [corners](FaceId t, std::uint32_t k) { return corners[3 * std::size_t{t} + k]; });
}

CubicGraph dual_graph(const PolygonMesh& mesh) {
  return build_dual(mesh).graph;
}

}  // namespace petersen
