#include "petersen/mesh/surface_check.hpp"

#include <algorithm>
#include <numeric>

#include "petersen/mesh/edge_groups.hpp"

namespace petersen {

namespace {

// Union-find with path halving: iterative, near-linear.
struct DisjointSets {
  std::vector<std::uint32_t> parent;
  explicit DisjointSets(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(std::uint32_t x, std::uint32_t y) {
    x = find(x);
    y = find(y);
    if (x != y) parent[std::max(x, y)] = std::min(x, y);
  }
};

// Marks triangles that can take part in the edge analysis and reports the others.
std::vector<std::uint8_t> triangle_validity(const TriangleMesh& mesh, SurfaceReport& report) {
  std::vector<std::uint8_t> usable(mesh.triangles.size(), 1);
  for (FaceId t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    if (std::any_of(tri.begin(), tri.end(),
                    [&](VertexId v) { return v >= mesh.positions.size(); })) {
      report.out_of_range_triangles.add(t);
      usable[t] = 0;
    } else if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0]) {
      report.degenerate_triangles.add(t);
      usable[t] = 0;
    }
  }
  return usable;
}

void find_duplicates(const TriangleMesh& mesh, const std::vector<std::uint8_t>& usable,
                     SurfaceReport& report) {
  // Sort (sorted corners, triangle); a triangle equal to its predecessor is a duplicate.
  std::vector<std::pair<std::array<VertexId, 3>, FaceId>> keys;
  keys.reserve(mesh.triangles.size());
  for (FaceId t = 0; t < mesh.triangles.size(); ++t) {
    if (!usable[t]) continue;
    auto corners = mesh.triangles[t];
    std::sort(corners.begin(), corners.end());
    keys.push_back({corners, t});
  }
  std::sort(keys.begin(), keys.end());
  std::vector<FaceId> duplicates;
  for (std::size_t i = 1; i < keys.size(); ++i) {
    if (keys[i].first == keys[i - 1].first) duplicates.push_back(keys[i].second);
  }
  std::sort(duplicates.begin(), duplicates.end());
  for (FaceId t : duplicates) report.duplicate_triangles.add(t);
}

// "(a, b)", built by appends: GCC 12 gives a false -Wrestrict on chains of operator+ here.
std::string edge_text(EdgeRef e) {
  std::string text = "(";
  text += std::to_string(e.a);
  text += ", ";
  text += std::to_string(e.b);
  text += ")";
  return text;
}

}  // namespace

bool SurfaceReport::closed() const {
  return faces > 0 && out_of_range_triangles.empty() && degenerate_triangles.empty() &&
         duplicate_triangles.empty() && boundary_edges.empty() && non_manifold_edges.empty() &&
         inconsistent_edges.empty();
}

SurfaceReport inspect_surface(const TriangleMesh& mesh) {
  SurfaceReport report;
  report.faces = static_cast<std::uint32_t>(mesh.triangles.size());
  const std::vector<std::uint8_t> usable = triangle_validity(mesh, report);
  find_duplicates(mesh, usable, report);
  const EdgeGroups groups = group_halfedges(mesh, usable);

  // Triangles sharing an edge share a component; corners at a vertex whose triangles share an
  // edge through it share a fan (corner c = 3t + k is corner k of triangle t).
  DisjointSets triangles(mesh.triangles.size()), corners(3 * mesh.triangles.size());
  const auto& entries = groups.entries;
  for (std::size_t v = 0; v + 1 < groups.start.size(); ++v) {
    for (std::uint32_t i = groups.start[v]; i < groups.start[v + 1];) {
      std::uint32_t end = i + 1;
      while (end < groups.start[v + 1] && entries[end][0] == entries[i][0]) ++end;
      const std::uint32_t h = entries[i][1];
      const EdgeRef edge{halfedge_from(mesh, h), halfedge_to(mesh, h)};
      ++report.edges;
      if (end - i == 1) report.boundary_edges.add(edge);
      if (end - i > 2) report.non_manifold_edges.add(edge);
      if (end - i == 2 && halfedge_from(mesh, entries[i + 1][1]) == edge.a) {
        report.inconsistent_edges.add(edge);
      }
      for (std::uint32_t j = i + 1; j < end; ++j) {
        const std::uint32_t g = entries[j][1];
        triangles.unite(h / 3, g / 3);
        // Corner of h at vertex x, corner of g at the same vertex.
        for (VertexId x : {edge.a, edge.b}) {
          const std::uint32_t ch = halfedge_from(mesh, h) == x ? h : h / 3 * 3 + (h % 3 + 1) % 3;
          const std::uint32_t cg = halfedge_from(mesh, g) == x ? g : g / 3 * 3 + (g % 3 + 1) % 3;
          corners.unite(ch, cg);
        }
      }
      i = end;
    }
  }

  // Fans per vertex: a set's root is one of its corners, all at the same vertex.
  std::vector<std::uint32_t> fans(mesh.positions.size(), 0);
  std::uint64_t fan_count = 0, valid_faces = 0;
  for (FaceId t = 0; t < mesh.triangles.size(); ++t) {
    if (!usable[t]) continue;
    ++valid_faces;
    if (triangles.find(t) == t) ++report.edge_components;
    for (std::uint32_t k = 0; k < 3; ++k) {
      if (corners.find(3 * t + k) == 3 * t + k) {
        ++fans[mesh.triangles[t][k]];
        ++fan_count;
      }
    }
  }
  // Referenced by any triangle, even an invalid one, as long as the index names a vertex.
  std::vector<std::uint8_t> referenced(mesh.positions.size(), 0);
  for (const auto& tri : mesh.triangles)
    for (VertexId v : tri)
      if (v < mesh.positions.size()) referenced[v] = 1;
  DisjointSets pieces(mesh.positions.size());
  for (FaceId t = 0; t < mesh.triangles.size(); ++t) {
    if (!usable[t]) continue;
    pieces.unite(mesh.triangles[t][0], mesh.triangles[t][1]);
    pieces.unite(mesh.triangles[t][0], mesh.triangles[t][2]);
  }
  for (VertexId v = 0; v < mesh.positions.size(); ++v) {
    if (fans[v] > 0 && pieces.find(v) == v) ++report.components;
    if (!referenced[v]) report.unreferenced_vertices.add(v);
    if (fans[v] > 1) report.pinched_vertices.add(v);
  }
  report.vertices =
      static_cast<std::uint32_t>(mesh.positions.size() - report.unreferenced_vertices.count);
  report.euler_characteristic =
      std::int64_t{report.vertices} - std::int64_t(report.edges) + std::int64_t(valid_faces);
  if (report.closed()) {
    // Each component is a closed orientable surface once pinched vertices are split into fans:
    // sum of (2 - 2 g_i) = fans - E + F.
    const std::int64_t chi =
        std::int64_t(fan_count) - std::int64_t(report.edges) + std::int64_t(valid_faces);
    report.genus = static_cast<std::uint32_t>((2 * std::int64_t{report.edge_components} - chi) / 2);
  }
  return report;
}

std::string describe(const SurfaceReport& r) {
  std::string out = "V " + std::to_string(r.vertices) + ", E " + std::to_string(r.edges) + ", F " +
                    std::to_string(r.faces) + ", components " + std::to_string(r.components) +
                    " (" + std::to_string(r.edge_components) + " through edges), V - E + F " +
                    std::to_string(r.euler_characteristic) + ", genus " +
                    (r.genus ? std::to_string(*r.genus) : std::string("-")) + "\n";
  auto list = [&](const char* what, const auto& findings, auto name) {
    if (findings.empty()) return;
    out += std::string(what) + ": " + std::to_string(findings.count) + " (";
    for (std::size_t i = 0; i < findings.first.size(); ++i) {
      out += (i ? ", " : "") + name(findings.first[i]);
    }
    out += findings.count > findings.first.size() ? ", ...)\n" : ")\n";
  };
  auto index = [](std::uint32_t i) { return std::to_string(i); };
  list("triangles with a corner out of range", r.out_of_range_triangles, index);
  list("degenerate triangles", r.degenerate_triangles, index);
  list("duplicate triangles", r.duplicate_triangles, index);
  list("boundary edges", r.boundary_edges, edge_text);
  list("non-manifold edges", r.non_manifold_edges, edge_text);
  list("inconsistently oriented edges", r.inconsistent_edges, edge_text);
  list("pinched vertices", r.pinched_vertices, index);
  list("unreferenced vertices", r.unreferenced_vertices, index);
  return out;
}

void require_closed_surface(const TriangleMesh& mesh, const SurfaceRequirements& requirements) {
  require_closed_surface(inspect_surface(mesh), requirements);
}

void require_closed_surface(const SurfaceReport& r, const SurfaceRequirements& requirements) {
  auto fail = [&](const std::string& what) { throw MeshError("not a closed surface: " + what); };
  auto edge = [](const char* what, EdgeRef e, std::uint64_t count) {
    return std::string(what) + " edge " + edge_text(e) + " (" + std::to_string(count) +
           " such edges)";
  };
  auto element = [](const char* what, std::uint32_t i, std::uint64_t count) {
    return std::string(what) + " " + std::to_string(i) + " (" + std::to_string(count) + " in all)";
  };
  if (r.faces == 0) fail("no triangles");
  if (!r.out_of_range_triangles.empty()) {
    fail(element("corner out of range in triangle", r.out_of_range_triangles.first[0],
                 r.out_of_range_triangles.count));
  }
  if (!r.degenerate_triangles.empty()) {
    fail(element("degenerate triangle", r.degenerate_triangles.first[0],
                 r.degenerate_triangles.count));
  }
  if (!r.duplicate_triangles.empty()) {
    fail(
        element("duplicate triangle", r.duplicate_triangles.first[0], r.duplicate_triangles.count));
  }
  if (!r.boundary_edges.empty()) {
    fail(edge("boundary", r.boundary_edges.first[0], r.boundary_edges.count));
  }
  if (!r.non_manifold_edges.empty()) {
    fail(edge("non-manifold", r.non_manifold_edges.first[0], r.non_manifold_edges.count));
  }
  if (!r.inconsistent_edges.empty()) {
    fail(
        edge("inconsistently oriented", r.inconsistent_edges.first[0], r.inconsistent_edges.count));
  }
  if (!requirements.allow_pinched_vertices && !r.pinched_vertices.empty()) {
    fail(element("pinched vertex", r.pinched_vertices.first[0], r.pinched_vertices.count));
  }
  if (!requirements.allow_several_components && r.edge_components > 1) {
    fail(std::to_string(r.edge_components) + " components (triangles joined through edges)");
  }
}

}  // namespace petersen
