#pragma once
// The topology of any polygon mesh counted with plain containers (std::map, union-find), sharing
// nothing with the library's edge grouping or surface check: for tests of the generators and of
// every transformation that must keep a surface's topology (quadrangulate's all-quad splits).

#include <algorithm>
#include <cstdint>
#include <map>
#include <numeric>
#include <queue>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include "petersen/mesh/mesh.hpp"

namespace petersen::testing {

/// What the counting finds. Orientability is judged over the edges of exactly two faces: a BFS
/// gives each face a sign so that two faces on an edge run along it in opposite directions once
/// their signs are applied; the surface is orientable when no edge contradicts the signs.
struct MeshCensus {
  std::size_t vertices = 0;  ///< referenced
  std::size_t edges = 0;
  std::size_t faces = 0;
  std::size_t boundary_edges = 0;      ///< in one face
  std::size_t non_manifold_edges = 0;  ///< in three or more faces
  std::size_t inconsistent_edges = 0;  ///< two faces run along it the same way
  std::size_t boundary_loops = 0;      ///< connected pieces of the boundary edges
  std::size_t components = 0;          ///< faces joined through shared vertices
  std::size_t edge_components = 0;     ///< faces joined through shared edges
  std::size_t pinched_vertices = 0;    ///< faces around it form more than one edge-connected fan
  std::size_t non_triangles = 0;
  bool orientable = true;
  std::int64_t euler() const {
    return std::int64_t(vertices) - std::int64_t(edges) + std::int64_t(faces);
  }
};

/// One component of faces joined through shared edges: its χ (its referenced vertices − its
/// edges + its faces; a vertex shared with another component counts in both), its boundary
/// loops and whether it is orientable. Ordered, so that two meshes' lists compare as multisets.
struct ComponentCensus {
  std::int64_t euler = 0;
  std::size_t boundary_loops = 0;
  bool orientable = true;
  auto operator<=>(const ComponentCensus&) const = default;
};

namespace detail {

struct UnionFind {
  std::vector<std::size_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  std::size_t find(std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void join(std::size_t a, std::size_t b) { parent[find(a)] = find(b); }
};

using Edge = std::pair<VertexId, VertexId>;
inline Edge undirected(VertexId a, VertexId b) {
  return {std::min(a, b), std::max(a, b)};
}

/// For each undirected edge, the faces along it (a face once per side it has there) and whether
/// each runs from the smaller vertex; sides from a vertex to itself are no edge.
inline std::map<Edge, std::vector<std::pair<std::size_t, bool>>> edge_faces(
    const PolygonMesh& mesh) {
  std::map<Edge, std::vector<std::pair<std::size_t, bool>>> on_edge;
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    const auto face = mesh.face(f);
    for (std::size_t k = 0; k < face.size(); ++k) {
      const VertexId a = face[k], b = face[(k + 1) % face.size()];
      if (a != b) on_edge[undirected(a, b)].push_back({f, a < b});
    }
  }
  return on_edge;
}

/// Signs for the faces by BFS over the edges of two faces (see MeshCensus); false at the first
/// contradiction in each component, recorded per face's component root in `orientable`.
inline void orient(const std::vector<std::vector<std::pair<std::size_t, bool>>>& neighbours,
                   std::vector<bool>& consistent) {
  std::vector<int> sign(neighbours.size(), 0);
  for (std::size_t start = 0; start < neighbours.size(); ++start) {
    if (sign[start] != 0) continue;
    sign[start] = 1;
    std::queue<std::size_t> queue;
    queue.push(start);
    while (!queue.empty()) {
      const std::size_t f = queue.front();
      queue.pop();
      for (const auto& [g, same_way] : neighbours[f]) {
        const int wanted = same_way ? -sign[f] : sign[f];
        if (sign[g] == 0) {
          sign[g] = wanted;
          queue.push(g);
        } else if (sign[g] != wanted) {
          consistent[f] = false;
        }
      }
    }
  }
}

/// Vertices where the faces around form more than one fan (joined through edges at the vertex).
inline std::size_t count_pinched(const PolygonMesh& mesh) {
  std::map<VertexId, std::vector<FaceId>> around;
  for (FaceId f = 0; f < mesh.face_count(); ++f)
    for (VertexId v : mesh.face(f)) around[v].push_back(f);
  std::size_t pinched = 0;
  for (const auto& [v, at_v] : around) {
    UnionFind fans(mesh.face_count());
    std::map<Edge, FaceId> first_on;
    for (FaceId f : at_v) {
      const auto face = mesh.face(f);
      for (std::size_t k = 0; k < face.size(); ++k) {
        const VertexId a = face[k], b = face[(k + 1) % face.size()];
        if (a != v && b != v) continue;
        auto [it, inserted] = first_on.try_emplace(undirected(a, b), f);
        if (!inserted) fans.join(it->second, f);
      }
    }
    std::set<std::size_t> fan_roots;
    for (FaceId f : at_v) fan_roots.insert(fans.find(f));
    pinched += fan_roots.size() > 1;
  }
  return pinched;
}

}  // namespace detail

/// The census of the whole mesh (see MeshCensus). O(C log C) for C corners, plus the fans.
inline MeshCensus census(const PolygonMesh& mesh) {
  using detail::UnionFind;
  MeshCensus c;
  c.faces = mesh.face_count();
  std::set<VertexId> referenced;
  UnionFind surface(mesh.positions.size()), boundary(mesh.positions.size());
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    const auto face = mesh.face(f);
    referenced.insert(face.begin(), face.end());
    for (VertexId v : face) surface.join(face[0], v);
    c.non_triangles += face.size() != 3;
  }
  c.vertices = referenced.size();
  std::set<std::size_t> roots;
  for (VertexId v : referenced) roots.insert(surface.find(v));
  c.components = roots.size();

  const auto on_edge = detail::edge_faces(mesh);
  c.edges = on_edge.size();
  std::set<VertexId> boundary_vertices;
  std::vector<std::vector<std::pair<std::size_t, bool>>> neighbours(c.faces);
  UnionFind through_edges(c.faces);
  for (const auto& [edge, along] : on_edge) {
    for (const auto& [f, from_smaller] : along) through_edges.join(along[0].first, f);
    if (along.size() == 1) {
      ++c.boundary_edges;
      boundary.join(edge.first, edge.second);
      boundary_vertices.insert(edge.first);
    }
    if (along.size() >= 3) ++c.non_manifold_edges;
    if (along.size() == 2) {
      const bool same_way = along[0].second == along[1].second;
      c.inconsistent_edges += same_way;
      neighbours[along[0].first].push_back({along[1].first, same_way});
      neighbours[along[1].first].push_back({along[0].first, same_way});
    }
  }
  roots.clear();
  for (std::size_t f = 0; f < c.faces; ++f) roots.insert(through_edges.find(f));
  c.edge_components = roots.size();
  roots.clear();
  for (VertexId v : boundary_vertices) roots.insert(boundary.find(v));
  c.boundary_loops = roots.size();
  std::vector<bool> consistent(c.faces, true);
  detail::orient(neighbours, consistent);
  c.orientable = std::all_of(consistent.begin(), consistent.end(), [](bool b) { return b; });
  c.pinched_vertices = detail::count_pinched(mesh);
  return c;
}

/// The census of each component of faces joined through shared edges, sorted. Sorted arrays
/// rather than maps: it runs on meshes of a million faces. O(C log C).
inline std::vector<ComponentCensus> component_census(const PolygonMesh& mesh) {
  using detail::Edge;
  const std::size_t faces = mesh.face_count();
  // (edge, face, runs from the smaller vertex), sorted: the sides of an edge are adjacent.
  std::vector<std::tuple<Edge, FaceId, bool>> sides;
  sides.reserve(mesh.corners.size());
  for (FaceId f = 0; f < faces; ++f) {
    const auto face = mesh.face(f);
    for (std::size_t k = 0; k < face.size(); ++k) {
      const VertexId a = face[k], b = face[(k + 1) % face.size()];
      if (a != b) sides.push_back({detail::undirected(a, b), f, a < b});
    }
  }
  std::sort(sides.begin(), sides.end());
  detail::UnionFind through_edges(faces);
  for (std::size_t i = 1; i < sides.size(); ++i) {
    if (std::get<0>(sides[i]) == std::get<0>(sides[i - 1]))
      through_edges.join(std::get<1>(sides[i - 1]), std::get<1>(sides[i]));
  }
  std::vector<std::size_t> index(faces, faces);  // face -> its component's entry
  std::size_t components = 0;
  for (std::size_t f = 0; f < faces; ++f) {
    const std::size_t root = through_edges.find(f);
    if (index[root] == faces) index[root] = components++;
    index[f] = index[root];
  }
  std::vector<ComponentCensus> out(components);
  std::vector<std::pair<std::size_t, VertexId>> vertices;  // (component, vertex)
  for (FaceId f = 0; f < faces; ++f) {
    out[index[f]].euler += 1;
    for (VertexId v : mesh.face(f)) vertices.push_back({index[f], v});
  }
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  for (const auto& [k, v] : vertices) out[k].euler += 1;
  std::vector<std::vector<std::pair<std::size_t, bool>>> neighbours(faces);
  detail::UnionFind boundary(mesh.positions.size());
  std::vector<std::pair<std::size_t, VertexId>> boundary_vertices;  // (component, vertex)
  for (std::size_t i = 0, j = 0; i < sides.size(); i = j) {
    while (j < sides.size() && std::get<0>(sides[j]) == std::get<0>(sides[i])) ++j;
    const auto& [edge, f, from_smaller] = sides[i];
    out[index[f]].euler -= 1;
    if (j - i == 1) {
      boundary.join(edge.first, edge.second);
      boundary_vertices.push_back({index[f], edge.first});
    }
    if (j - i == 2) {
      const FaceId g = std::get<1>(sides[i + 1]);
      const bool same_way = from_smaller == std::get<2>(sides[i + 1]);
      neighbours[f].push_back({g, same_way});
      neighbours[g].push_back({f, same_way});
    }
  }
  std::vector<std::pair<std::size_t, std::size_t>> loops;  // (component, boundary root)
  for (const auto& [k, v] : boundary_vertices) loops.push_back({k, boundary.find(v)});
  std::sort(loops.begin(), loops.end());
  loops.erase(std::unique(loops.begin(), loops.end()), loops.end());
  for (const auto& [k, root] : loops) ++out[k].boundary_loops;
  std::vector<bool> consistent(faces, true);
  detail::orient(neighbours, consistent);
  for (std::size_t f = 0; f < faces; ++f)
    out[index[f]].orientable = out[index[f]].orientable && consistent[f];
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace petersen::testing
