#include "all_quad.hpp"

#include <algorithm>
#include <string>

#include "carry_attributes.hpp"
#include "petersen/mesh/edge_groups.hpp"

namespace petersen::quad_detail {

namespace {

constexpr std::uint32_t kBoundary = 0xFFFFFFFFu;   // twin of a halfedge on the boundary
constexpr std::uint32_t kBlocked = 0xFFFFFFFEu;    // an edge of three or more faces
constexpr std::uint32_t kUnreached = 0xFFFFFFFFu;  // a face no search has reached
constexpr std::uint32_t kStart = 0xFFFFFFFDu;      // the face a search starts from

// The output mesh's halfedges with the twin of each: the other halfedge of an edge of exactly two
// faces, kBoundary for an edge of one face, kBlocked otherwise.
struct Halfedges : PolygonHalfedges {
  std::vector<std::uint32_t> twin;
};

Halfedges halfedges_of(const PolygonMesh& mesh) {
  Halfedges half{PolygonHalfedges(mesh), {}};
  half.twin.assign(half.count(), kBlocked);
  const EdgeGroups groups = half.group();
  for_each_edge_group(groups, [&](std::uint32_t first, std::uint32_t end) {
    const std::uint32_t h1 = groups.entries[first][1];
    if (end - first == 1) {
      half.twin[h1] = kBoundary;
    } else if (end - first == 2) {
      const std::uint32_t h2 = groups.entries[first + 1][1];
      if (half.face(h1) != half.face(h2)) {
        half.twin[h1] = h2;
        half.twin[h2] = h1;
      }
    }
  });
  return half;
}

// Where a path crosses a face: the sides (corner positions) it enters and leaves by, and the
// midpoint vertex on each (kNoNode where it does not cross).
struct Crossing {
  std::uint32_t side[2] = {kNoNode, kNoNode};
  VertexId midpoint[2] = {kNoNode, kNoNode};
};

std::array<double, 3> average(std::span<const std::array<double, 3>> points) {
  std::array<double, 3> sum{0, 0, 0};
  for (const auto& p : points)
    for (int d = 0; d < 3; ++d) sum[d] += p[d];
  for (double& x : sum) x /= double(points.size());
  return sum;
}

}  // namespace

void split_leftovers(QuadResult& result, const std::vector<FaceKind>& kinds) {
  PolygonMesh& mesh = result.mesh;
  const Halfedges half = halfedges_of(mesh);
  const std::uint32_t face_count = static_cast<std::uint32_t>(mesh.face_count());
  const std::size_t input_vertices = mesh.positions.size();

  // used: a left triangle already joined, or a quad already on a path.
  std::vector<std::uint8_t> used(face_count, 0);
  std::vector<Crossing> crossing(face_count);
  std::vector<std::uint32_t> reached_by(face_count,
                                        kUnreached);  // the halfedge a search entered by
  std::vector<FaceId> visited, queue;
  // With attributes: what each new vertex, output corner and output face is made from.
  const bool carry = !mesh.attributes.empty();
  std::vector<Blend> new_vertices, corner_from;
  std::vector<FaceId> face_of;
  auto midpoint_of = [&](std::uint32_t h) {
    const std::array<double, 3> ends[2] = {mesh.positions[half.from(h)],
                                           mesh.positions[half.to(h)]};
    mesh.positions.push_back(average(ends));
    if (carry) new_vertices.push_back({half.from(h), half.to(h), kNoAttribute, kNoAttribute});
    return static_cast<VertexId>(mesh.positions.size() - 1);
  };
  auto cross = [&](FaceId f, std::uint32_t h, VertexId m) {
    Crossing& c = crossing[f];
    const int slot = c.side[0] == kNoNode ? 0 : 1;
    c.side[slot] = h - half.first(f);
    c.midpoint[slot] = m;
  };

  // A non-manifold edge's halfedges, for the last resort below: splitting it gives every face on
  // it the midpoint.
  std::vector<std::uint32_t> group_of(half.count(), kNoNode);
  std::vector<std::vector<std::uint32_t>> groups;
  {
    const EdgeGroups edges = half.group();
    for_each_edge_group(edges, [&](std::uint32_t first, std::uint32_t end) {
      if (end - first < 3) return;
      groups.emplace_back();
      for (std::uint32_t i = first; i < end; ++i) {
        group_of[edges.entries[i][1]] = static_cast<std::uint32_t>(groups.size() - 1);
        groups.back().push_back(edges.entries[i][1]);
      }
    });
  }
  // Quads that got one midpoint from a split non-manifold edge and need a path of their own.
  std::vector<FaceId> pending;
  auto usable_at_split = [&](FaceId g) {
    return !used[g] && (kinds[g] == FaceKind::left || kinds[g] == FaceKind::pair);
  };

  // From face s (a left triangle, or a quad with one midpoint): breadth-first over pair quads not
  // on a path yet, to the nearest free left triangle or boundary edge; failing both, to the
  // nearest non-manifold edge whose other faces are all free left triangles or free quads (each
  // such quad then starts a path of its own). Splits along the path found.
  auto join = [&](FaceId s) {
    visited.assign(1, s);
    queue.assign(1, s);
    reached_by[s] = kStart;
    FaceId target = kNoFace;
    std::uint32_t exit = kNoNode;  // the halfedge the path leaves its last face by
    FaceId split_face = kNoFace;   // the last resort: a face beside a non-manifold edge
    std::uint32_t split_exit = kNoNode;
    for (std::size_t head = 0; head < queue.size() && target == kNoFace; ++head) {
      const FaceId f = queue[head];
      const std::uint32_t first = half.first(f);
      for (std::uint32_t k = 0; k < mesh.arity(f) && target == kNoFace; ++k) {
        const std::uint32_t h = first + k;
        if (half.twin[h] == kBlocked) {
          if (split_face == kNoFace && group_of[h] != kNoNode) {
            bool all_usable = true;
            for (std::uint32_t other : groups[group_of[h]]) {
              all_usable &=
                  other == h || (half.face(other) != f && usable_at_split(half.face(other)));
            }
            if (all_usable) {
              split_face = f;
              split_exit = h;
            }
          }
          continue;
        }
        if (reached_by[f] == h) continue;  // the side the search came in by
        if (half.twin[h] == kBoundary) {
          target = f;
          exit = h;
          break;
        }
        const FaceId g = half.face(half.twin[h]);
        if (used[g] || reached_by[g] != kUnreached) continue;
        if (kinds[g] == FaceKind::left) {
          reached_by[g] = half.twin[h];
          visited.push_back(g);
          target = g;
        } else if (kinds[g] == FaceKind::pair) {
          reached_by[g] = half.twin[h];
          visited.push_back(g);
          queue.push_back(g);
        }
      }
    }
    if (target == kNoFace && split_face != kNoFace) {
      target = split_face;
      exit = split_exit;
    }
    if (target == kNoFace) {
      throw MeshError("--all-quad: face " + std::to_string(result.sources[s][0]) +
                      " (input) can reach no left triangle, no boundary edge and no non-manifold "
                      "edge it could split, across edges of two faces and quads not already "
                      "split; no all-quad mesh on these vertices");
    }
    // Walk back from the target, splitting each edge crossed.
    VertexId exit_midpoint = kNoNode;
    if (exit != kNoNode) {
      exit_midpoint = midpoint_of(exit);
      cross(target, exit, exit_midpoint);
    } else {
      used[target] = 1;
    }
    if (kinds[target] == FaceKind::pair) used[target] = 1;
    for (FaceId f = target; f != s;) {
      const std::uint32_t entry = reached_by[f];  // f's halfedge, twin in the previous face
      const VertexId m = midpoint_of(entry);
      cross(f, entry, m);
      const std::uint32_t back = half.twin[entry];
      const FaceId previous = half.face(back);
      cross(previous, back, m);
      if (kinds[f] == FaceKind::pair) used[f] = 1;
      f = previous;
    }
    for (FaceId f : visited) reached_by[f] = kUnreached;
    if (exit != kNoNode && group_of[exit] != kNoNode) {
      for (std::uint32_t other : groups[group_of[exit]]) {
        if (other == exit) continue;
        const FaceId g = half.face(other);
        if (!usable_at_split(g)) {  // the path itself went through it
          throw MeshError("--all-quad: the split of a non-manifold edge beside input face " +
                          std::to_string(result.sources[g][0]) +
                          " meets a face already split; no all-quad mesh found");
        }
        cross(g, other, exit_midpoint);
        used[g] = 1;
        if (kinds[g] == FaceKind::pair) pending.push_back(g);
      }
    }
  };

  for (FaceId s = 0; s < face_count; ++s) {
    if (kinds[s] != FaceKind::left || used[s]) continue;
    const auto corners = mesh.face(s);
    if (corners[0] == corners[1] || corners[1] == corners[2] || corners[2] == corners[0]) {
      throw MeshError("--all-quad: left triangle (input face " +
                      std::to_string(result.sources[s][0]) +
                      ") repeats a vertex; it cannot become a quad");
    }
    used[s] = 1;
    join(s);
    while (!pending.empty()) {
      const FaceId g = pending.back();
      pending.pop_back();
      join(g);
    }
  }

  // The faces again, with every crossed face replaced by its pieces (same sources).
  PolygonMesh out;
  HugeVector<std::array<FaceId, 2>> sources;
  out.corners.reserve(mesh.corners.size() + 8 * (mesh.positions.size() - input_vertices));
  std::uint64_t pieces = 0;
  for (FaceId f = 0; f < face_count; ++f) {
    const auto q = mesh.face(f);
    const Crossing& c = crossing[f];
    // The corners of each piece added below: a corner of f (its position k in f), or the
    // midpoint of f's side k (k + kSide), or f's centre (kCentre); f's own corner values blended.
    constexpr std::uint32_t kSide = 8, kCentre = 16;
    auto made_of = [&](std::initializer_list<std::uint32_t> piece) {
      if (!carry) return;
      face_of.push_back(f);
      const std::uint32_t first = half.first(f), n = mesh.arity(f);
      for (std::uint32_t k : piece) {
        if (k == kCentre) {
          corner_from.push_back({first, first + 1, first + 2, first + 3});
        } else if (k >= kSide) {
          corner_from.push_back(
              {first + k - kSide, first + (k - kSide + 1) % n, kNoAttribute, kNoAttribute});
        } else {
          corner_from.push_back({first + k, kNoAttribute, kNoAttribute, kNoAttribute});
        }
      }
    };
    if (c.side[0] == kNoNode) {
      out.add_face(q);
      sources.push_back(result.sources[f]);
      if (carry) {
        face_of.push_back(f);
        for (std::uint32_t k = 0; k < q.size(); ++k) {
          corner_from.push_back({half.first(f) + k, kNoAttribute, kNoAttribute, kNoAttribute});
        }
      }
      continue;
    }
    if (q.size() == 3) {
      // A left triangle with one midpoint m on side i: (q_i, m, q_i+1, q_i+2).
      const std::uint32_t i = c.side[0];
      const std::array<VertexId, 4> quad{q[i], c.midpoint[0], q[(i + 1) % 3], q[(i + 2) % 3]};
      out.add_face(quad);
      made_of({i, kSide + i, (i + 1) % 3, (i + 2) % 3});
      sources.push_back(result.sources[f]);
      ++pieces;
      continue;
    }
    // A quad crossed through sides i and j with midpoints mi, mj.
    std::uint32_t i = c.side[0], j = c.side[1];
    VertexId mi = c.midpoint[0], mj = c.midpoint[1];
    if ((i + 3) % 4 == j) {  // j just before i: swap so that j = i + 1 or i + 2
      std::swap(i, j);
      std::swap(mi, mj);
    }
    const VertexId a = q[i], b = q[(i + 1) % 4], cc = q[(i + 2) % 4], d = q[(i + 3) % 4];
    const std::uint32_t ia = i, ib = (i + 1) % 4, ic = (i + 2) % 4, id = (i + 3) % 4;
    if (j == (i + 2) % 4) {
      const std::array<VertexId, 4> left{a, mi, mj, d}, right{mi, b, cc, mj};
      out.add_face(left);
      made_of({ia, kSide + ia, kSide + ic, id});
      out.add_face(right);
      made_of({kSide + ia, ib, ic, kSide + ic});
      sources.push_back(result.sources[f]);
      sources.push_back(result.sources[f]);
      pieces += 2;
    } else {
      const std::array<double, 3> corners[4] = {mesh.positions[a], mesh.positions[b],
                                                mesh.positions[cc], mesh.positions[d]};
      mesh.positions.push_back(average(corners));
      if (carry) new_vertices.push_back({a, b, cc, d});
      const VertexId x = static_cast<VertexId>(mesh.positions.size() - 1);
      const std::array<VertexId, 4> first{a, mi, x, d}, second{mi, b, mj, x}, third{x, mj, cc, d};
      out.add_face(first);
      made_of({ia, kSide + ia, kCentre, id});
      out.add_face(second);
      made_of({kSide + ia, ib, kSide + ib, kCentre});
      out.add_face(third);
      made_of({kCentre, kSide + ib, ic, id});
      for (int k = 0; k < 3; ++k) sources.push_back(result.sources[f]);
      pieces += 3;
    }
  }
  if (carry) {
    out.attributes =
        derived_attributes(mesh.attributes, input_vertices, face_of, corner_from, new_vertices);
  }
  out.attributes.position_type = mesh.attributes.position_type;
  // A float PLY is written back as float: its new vertices are held as floats now, so that the
  // result is what the file will hold (found by fuzz/quad_fuzzer.cpp: a midpoint of two floats
  // needs up to 25 bits).
  for (std::size_t v = input_vertices; v < mesh.positions.size(); ++v) {
    for (double& x : mesh.positions[v]) x = held_as(out.attributes.position_type, x);
  }
  out.positions = std::move(mesh.positions);
  result.stats.added_vertices = out.positions.size() - input_vertices;
  result.stats.split_quads = pieces;
  result.mesh = std::move(out);
  result.sources = std::move(sources);
}

}  // namespace petersen::quad_detail
