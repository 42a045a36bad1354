#include "petersen/mesh/mesh_report.hpp"

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "petersen/graph/component_forest.hpp"
#include "petersen/mesh/edge_groups.hpp"

namespace petersen {

namespace {

void join(ComponentForest& forest, std::uint32_t a, std::uint32_t b) {
  const std::array<NodeId, 2> ends{a, b};
  forest.join(ends);
}

// Counts the faces by arity and the referenced vertices, and names the faces with a corner out of
// range and the degenerate ones. Returns which faces are usable (in range), empty when all are.
std::vector<std::uint8_t> count_faces(const PolygonMesh& mesh, MeshReport& report) {
  const auto face_count = static_cast<FaceId>(mesh.face_count());
  const std::size_t vertex_count = mesh.positions.size();
  std::vector<std::uint8_t> usable, referenced(vertex_count, 0);
  for (FaceId f = 0; f < face_count; ++f) {
    ++report.faces_by_arity[mesh.arity(f)];
    const auto c = mesh.face(f);
    bool in_range = true, repeats = false;
    for (std::size_t i = 0; i < c.size(); ++i) {
      if (c[i] >= vertex_count) {
        in_range = false;
        continue;
      }
      referenced[c[i]] = 1;
      for (std::size_t j = 0; j < i; ++j) repeats |= c[i] == c[j];
    }
    if (!in_range) {
      if (usable.empty()) usable.assign(face_count, 1);
      usable[f] = 0;
      report.out_of_range_faces.add(f);
    } else if (repeats) {
      report.degenerate_faces.add(f);
    }
  }
  for (VertexId v = 0; v < vertex_count; ++v) {
    if (referenced[v]) {
      ++report.referenced_vertices;
    } else {
      report.unreferenced_vertices.add(v);
    }
  }
  return usable;
}

// The halfedges of the usable faces grouped by edge (all faces when `usable` is empty).
EdgeGroups group_usable(const PolygonMesh& mesh, const PolygonHalfedges& half,
                        const std::vector<std::uint8_t>& usable) {
  if (usable.empty()) return half.group();
  const auto halfedges = [&](auto visit) {
    half.for_each([&](std::uint32_t h, VertexId a, VertexId b) {
      if (usable[half.face(h)]) visit(h, a, b);
    });
  };
  const std::pmr::vector<std::uint32_t> start = bucket_starts(mesh.positions.size(), halfedges);
  return group_halfedges_in(start, 0, mesh.positions.size(), halfedges);
}

// Two faces joined across an edge of two faces, and whether one must be reversed to agree with
// the other (they run along the edge the same way).
struct Join {
  FaceId a, b;
  bool flip;
};

// What one pass over the edges gathers besides the report's counts: faces joined through edges
// (components), corners joined around their vertex across edges (fans), boundary edges joined at
// their ends (loops), and the joins the orientation check needs.
struct EdgeScan {
  ComponentForest faces, corners, boundary;
  std::vector<std::uint8_t> on_boundary;
  std::vector<Join> joins;
};

// Whether faces f and g, both on edge {a, b}, have the same corners (duplicate_faces' judgement,
// made here within an edge's faces so that the report needs no sort of all faces). Triangles, the
// common case, compare their third vertices.
bool same_face(const PolygonMesh& mesh, FaceId f, FaceId g, EdgeRef edge) {
  if (f == g || mesh.arity(f) != mesh.arity(g)) return false;
  if (mesh.arity(f) == 3) {
    const auto third = [&](FaceId t) {
      const auto c = mesh.face(t);
      return std::uint64_t{c[0]} + c[1] + c[2] - edge.a - edge.b;
    };
    return third(f) == third(g);
  }
  const auto sorted = [&](FaceId t) {
    const auto c = mesh.face(t);
    std::vector<VertexId> corners(c.begin(), c.end());
    std::sort(corners.begin(), corners.end());
    return corners;
  };
  return sorted(f) == sorted(g);
}

// Every edge once: its group of halfedges names it a boundary, non-manifold or inconsistent edge.
// Two faces with the same corners share all their edges, so each duplicate is found within a
// group. O(H + sum of squared group sizes).
EdgeScan scan_edges(const PolygonMesh& mesh, const PolygonHalfedges& half, const EdgeGroups& groups,
                    MeshReport& report) {
  EdgeScan scan{ComponentForest(static_cast<std::uint32_t>(mesh.face_count()), {}),
                ComponentForest(half.count(), {}),
                ComponentForest(static_cast<std::uint32_t>(mesh.positions.size()), {}),
                std::vector<std::uint8_t>(mesh.positions.size(), 0),
                {}};
  std::vector<std::uint8_t> duplicate(mesh.face_count(), 0);
  const auto corner_at = [&](std::uint32_t h, VertexId x) {
    return half.from(h) == x ? h : half.next(h);
  };
  for_each_edge_group(groups, [&](std::uint32_t first, std::uint32_t end) {
    ++report.edges;
    const std::uint32_t h1 = groups.entries[first][1];
    const EdgeRef edge{half.from(h1), half.to(h1)};
    for (std::uint32_t i = first + 1; i < end; ++i) {
      const std::uint32_t g = groups.entries[i][1];
      join(scan.faces, half.face(h1), half.face(g));
      join(scan.corners, corner_at(h1, edge.a), corner_at(g, edge.a));
      join(scan.corners, corner_at(h1, edge.b), corner_at(g, edge.b));
      for (std::uint32_t j = first; j < i; ++j) {
        const FaceId f1 = half.face(groups.entries[j][1]), f2 = half.face(g);
        if (same_face(mesh, f1, f2, edge)) duplicate[std::max(f1, f2)] = 1;
      }
    }
    if (end - first == 1) {
      report.boundary_edges.add(edge);
      join(scan.boundary, edge.a, edge.b);
      scan.on_boundary[edge.a] = scan.on_boundary[edge.b] = 1;
    } else if (end - first > 2) {
      report.non_manifold_edges.add(edge);
    } else {
      const std::uint32_t h2 = groups.entries[first + 1][1];
      const bool same_way = half.from(h2) == edge.a;
      if (same_way) report.inconsistent_edges.add(edge);
      scan.joins.push_back({half.face(h1), half.face(h2), same_way});
    }
  });
  for (FaceId f = 0; f < duplicate.size(); ++f) {
    if (duplicate[f]) report.duplicate_faces.add(f);
  }
  return scan;
}

// Two-colouring with parity, by a disjoint-set forest that keeps each face's parity to its root;
// union by rank keeps the walks O(log F) without path compression.
bool orientable(std::size_t face_count, const std::vector<Join>& joins) {
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
      if ((pa ^ pb) != join.flip) return false;
    } else {
      const auto [child, root] = rank[ra] < rank[rb] ? std::pair{ra, rb} : std::pair{rb, ra};
      parent[child] = root;
      parity[child] = pa ^ pb ^ join.flip;
      rank[root] += rank[child] == rank[root];
    }
  }
  return true;
}

// Components, boundary loops and pinched vertices from the forests; returns how many vertices
// splitting every pinched vertex into its fans would add. Two faces sharing a vertex lie in one
// fan there (joined through edges) or in two fans of a pinched vertex, so joining the faces around
// each pinched vertex turns the edge components into the vertex components. O(C α(C)).
std::uint64_t count_pieces(const PolygonMesh& mesh, const PolygonHalfedges& half,
                           const std::vector<std::uint8_t>& usable, EdgeScan& scan,
                           MeshReport& report) {
  const auto for_each_corner = [&](auto visit) {
    for (FaceId f = 0; f < mesh.face_count(); ++f) {
      if (!usable.empty() && !usable[f]) continue;
      const std::uint32_t first = half.first(f);
      for (std::uint32_t c = first; c < first + mesh.arity(f); ++c) visit(f, c);
    }
  };
  const auto face_roots = [&] {
    std::uint64_t roots = 0;
    for (FaceId f = 0; f < mesh.face_count(); ++f) {
      roots += (usable.empty() || usable[f]) && scan.faces.find(f) == f;
    }
    return roots;
  };
  std::vector<std::uint32_t> fans(mesh.positions.size(), 0);
  for_each_corner(
      [&](FaceId, std::uint32_t c) { fans[mesh.corners[c]] += scan.corners.find(c) == c; });
  std::uint64_t extra_fans = 0;
  for (VertexId v = 0; v < mesh.positions.size(); ++v) {
    report.boundary_loops += scan.on_boundary[v] && scan.boundary.find(v) == v;
    if (fans[v] > 1) {
      report.pinched_vertices.add(v);
      extra_fans += fans[v] - 1;
    }
  }
  report.components = face_roots();
  report.vertex_components = report.components;
  if (report.pinched_vertices.empty()) return extra_fans;
  std::vector<FaceId> face_at(mesh.positions.size(), kNoFace);
  for_each_corner([&](FaceId f, std::uint32_t c) {
    const VertexId v = mesh.corners[c];
    if (fans[v] < 2) return;
    if (face_at[v] == kNoFace) {
      face_at[v] = f;
    } else {
      join(scan.faces, face_at[v], f);
    }
  });
  report.vertex_components = face_roots();
  return extra_fans;
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

bool MeshReport::closed() const {
  return faces > 0 && out_of_range_faces.empty() && degenerate_faces.empty() &&
         duplicate_faces.empty() && boundary_edges.empty() && non_manifold_edges.empty() &&
         inconsistent_edges.empty();
}

MeshReport inspect_mesh(const PolygonMesh& mesh) {
  MeshReport report;
  report.vertices = mesh.positions.size();
  report.faces = mesh.face_count();
  const std::vector<std::uint8_t> usable = count_faces(mesh, report);
  const PolygonHalfedges half(mesh);
  const EdgeGroups groups = group_usable(mesh, half, usable);
  EdgeScan scan = scan_edges(mesh, half, groups, report);
  report.orientable = orientable(mesh.face_count(), scan.joins);
  const std::uint64_t extra_fans = count_pieces(mesh, half, usable, scan, report);
  report.euler_characteristic = std::int64_t(report.referenced_vertices) -
                                std::int64_t(report.edges) +
                                std::int64_t(report.faces - report.out_of_range_faces.count);
  if (report.boundary_edges.empty() && report.non_manifold_edges.empty() && report.orientable) {
    // Each component is a closed orientable surface once pinched vertices are split into fans:
    // the sum of (2 - 2 g_i) is χ plus the vertices the split adds.
    const std::int64_t split_chi = report.euler_characteristic + std::int64_t(extra_fans);
    report.genus = (2 * std::int64_t(report.components) - split_chi) / 2;
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
  text += "\nboundary edges " + std::to_string(r.boundary_edges.count) + " in " +
          std::to_string(r.boundary_loops) + " loops, non-manifold edges " +
          std::to_string(r.non_manifold_edges.count) + ", degenerate faces " +
          std::to_string(r.degenerate_faces.count) + ", duplicate faces " +
          std::to_string(r.duplicate_faces.count) + "\n";
  text += std::string(r.orientable ? "orientable" : "not orientable") + ", " +
          std::to_string(r.inconsistent_edges.count) + " edges with inconsistent orientation\n";
  text += r.boundary_edges.empty() && r.non_manifold_edges.empty() ? "closed surface\n"
                                                                   : "not a closed surface\n";
  return text;
}

void require_closed_surface(const PolygonMesh& mesh, const SurfaceRequirements& requirements) {
  require_closed_surface(inspect_mesh(mesh), requirements);
}

void require_closed_surface(const MeshReport& r, const SurfaceRequirements& requirements) {
  auto fail = [&](const std::string& what) { throw MeshError("not a closed surface: " + what); };
  auto edge = [](const char* what, const Findings<EdgeRef>& found) {
    return std::string(what) + " edge " + edge_text(found.first[0]) + " (" +
           std::to_string(found.count) + " such edges)";
  };
  auto element = [](const std::string& what, const auto& found) {
    return what + " " + std::to_string(found.first[0]) + " (" + std::to_string(found.count) +
           " in all)";
  };
  // Elements are named as the mesh has them: triangles, unless some face is not one.
  const bool triangles = std::all_of(r.faces_by_arity.begin(), r.faces_by_arity.end(),
                                     [](const auto& arity) { return arity.first == 3; });
  const std::string face = triangles ? "triangle" : "face";
  if (r.faces == 0) fail("no triangles");
  if (!r.out_of_range_faces.empty()) {
    fail(element("corner out of range in " + face, r.out_of_range_faces));
  }
  if (!r.degenerate_faces.empty()) fail(element("degenerate " + face, r.degenerate_faces));
  if (!r.duplicate_faces.empty()) fail(element("duplicate " + face, r.duplicate_faces));
  if (!r.boundary_edges.empty()) fail(edge("boundary", r.boundary_edges));
  if (!r.non_manifold_edges.empty()) fail(edge("non-manifold", r.non_manifold_edges));
  if (!r.inconsistent_edges.empty()) fail(edge("inconsistently oriented", r.inconsistent_edges));
  if (!requirements.allow_pinched_vertices && !r.pinched_vertices.empty()) {
    fail(element("pinched vertex", r.pinched_vertices));
  }
  if (!requirements.allow_several_components && r.components > 1) {
    fail(std::to_string(r.components) + " components (" + face + "s joined through edges)");
  }
}

}  // namespace petersen
