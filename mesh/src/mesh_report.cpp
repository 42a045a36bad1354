#include "petersen/mesh/mesh_report.hpp"

#include <string>
#include <vector>

#include "petersen/mesh/edge_groups.hpp"

namespace petersen {

namespace {

struct DisjointSets {
  std::vector<std::uint32_t> parent;
  explicit DisjointSets(std::size_t n) : parent(n) {
    for (std::size_t i = 0; i < n; ++i) parent[i] = static_cast<std::uint32_t>(i);
  }
  std::uint32_t find(std::uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  }
  void join(std::uint32_t a, std::uint32_t b) { parent[find(a)] = find(b); }
};

}  // namespace

MeshReport inspect_mesh(const PolygonMesh& mesh) {
  MeshReport report;
  const std::uint32_t face_count = static_cast<std::uint32_t>(mesh.face_count());
  report.vertices = mesh.positions.size();
  report.faces = face_count;
  std::vector<std::uint8_t> referenced(mesh.positions.size(), 0);
  for (VertexId v : mesh.corners) referenced[v] = 1;
  for (std::uint8_t r : referenced) report.referenced_vertices += r;
  for (FaceId f = 0; f < face_count; ++f) {
    ++report.faces_by_arity[mesh.arity(f)];
    const auto c = mesh.face(f);
    bool repeats = false;
    for (std::size_t i = 0; i < c.size(); ++i)
      for (std::size_t j = 0; j < i; ++j) repeats |= c[i] == c[j];
    report.degenerate_faces += repeats;
  }

  const PolygonHalfedges half(mesh);
  const EdgeGroups groups = half.group();
  DisjointSets faces(face_count), boundary(mesh.positions.size());
  // Orientation: faces joined across an edge of two faces, with a parity bit saying whether one
  // must be reversed to agree with the other (they run along the edge the same way).
  struct Join {
    FaceId a, b;
    bool flip;
  };
  std::vector<Join> joins;
  std::vector<std::uint8_t> on_boundary(mesh.positions.size(), 0);
  for_each_edge_group(groups, [&](std::uint32_t first, std::uint32_t end) {
    ++report.edges;
    const std::uint32_t h1 = groups.entries[first][1];
    for (std::uint32_t i = first + 1; i < end; ++i)
      faces.join(half.face(h1), half.face(groups.entries[i][1]));
    if (end - first == 1) {
      ++report.boundary_edges;
      boundary.join(half.from(h1), half.to(h1));
      on_boundary[half.from(h1)] = on_boundary[half.to(h1)] = 1;
    } else if (end - first > 2) {
      ++report.non_manifold_edges;
    } else {
      const std::uint32_t h2 = groups.entries[first + 1][1];
      const bool same_way = half.from(h1) == half.from(h2);
      report.inconsistent_edges += same_way;
      joins.push_back({half.face(h1), half.face(h2), same_way});
    }
  });
  for (FaceId f = 0; f < face_count; ++f) report.components += faces.find(f) == f;
  for (VertexId v = 0; v < mesh.positions.size(); ++v) {
    report.boundary_loops += on_boundary[v] && boundary.find(v) == v;
  }
  // Two-colouring with parity, by a disjoint-set forest that keeps each face's parity to its root;
  // union by rank keeps the walks O(log F) without path compression.
  std::vector<std::uint32_t> parent(face_count);
  std::vector<std::uint8_t> parity(face_count, 0), rank(face_count, 0);
  for (FaceId f = 0; f < face_count; ++f) parent[f] = f;
  auto find = [&](FaceId f, std::uint8_t& p) {
    p = 0;
    while (parent[f] != f) {
      p ^= parity[f];
      f = parent[f];
    }
    return f;
  };
  for (const Join& join : joins) {
    std::uint8_t pa = 0, pb = 0;
    const FaceId ra = find(join.a, pa), rb = find(join.b, pb);
    if (ra == rb) {
      if ((pa ^ pb) != join.flip) report.orientable = false;
    } else {
      const auto [child, root] = rank[ra] < rank[rb] ? std::pair{ra, rb} : std::pair{rb, ra};
      parent[child] = root;
      parity[child] = pa ^ pb ^ join.flip;
      rank[root] += rank[child] == rank[root];
    }
  }
  report.euler_characteristic = std::int64_t(report.referenced_vertices) -
                                std::int64_t(report.edges) + std::int64_t(report.faces);
  if (report.boundary_edges == 0 && report.non_manifold_edges == 0 && report.orientable) {
    report.genus = (2 * std::int64_t(report.components) - report.euler_characteristic) / 2;
  }
  return report;
}

std::string describe(const MeshReport& r) {
  std::string text = "vertices " + std::to_string(r.vertices) + " (" +
                     std::to_string(r.referenced_vertices) + " referenced), edges " +
                     std::to_string(r.edges) + ", faces " + std::to_string(r.faces) + "\n";
  text += "faces by corners:";
  for (const auto& [arity, count] : r.faces_by_arity) {
    // Appended piece by piece: g++ 12 warns (-Wrestrict, a false positive) on " " + string&&.
    text += ' ';
    text += std::to_string(arity);
    text += ": ";
    text += std::to_string(count);
  }
  text += "\ncomponents " + std::to_string(r.components) + ", Euler characteristic " +
          std::to_string(r.euler_characteristic);
  if (r.genus) text += ", genus " + std::to_string(*r.genus);
  text += "\nboundary edges " + std::to_string(r.boundary_edges) + " in " +
          std::to_string(r.boundary_loops) + " loops, non-manifold edges " +
          std::to_string(r.non_manifold_edges) + ", degenerate faces " +
          std::to_string(r.degenerate_faces) + "\n";
  text += std::string(r.orientable ? "orientable" : "not orientable") + ", " +
          std::to_string(r.inconsistent_edges) + " edges with inconsistent orientation\n";
  text += r.boundary_edges == 0 && r.non_manifold_edges == 0 ? "closed surface\n"
                                                             : "not a closed surface\n";
  return text;
}

}  // namespace petersen
