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

using Sources = HugeVector<std::array<FaceId, 2>>;

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

// The edges of three or more faces, as lists of their halfedges: splitting one, the last resort of
// a search, gives every face on it the midpoint.
struct NonManifoldEdges {
  std::vector<std::uint32_t> edge_of;  // per halfedge: its edge's index, or kNoNode
  std::vector<std::vector<std::uint32_t>> halfedges;
};

NonManifoldEdges non_manifold_edges_of(const Halfedges& half) {
  NonManifoldEdges edges{std::vector<std::uint32_t>(half.count(), kNoNode), {}};
  const EdgeGroups groups = half.group();
  for_each_edge_group(groups, [&](std::uint32_t first, std::uint32_t end) {
    if (end - first < 3) return;
    const auto index = static_cast<std::uint32_t>(edges.halfedges.size());
    std::vector<std::uint32_t>& members = edges.halfedges.emplace_back();
    for (std::uint32_t i = first; i < end; ++i) {
      edges.edge_of[groups.entries[i][1]] = index;
      members.push_back(groups.entries[i][1]);
    }
  });
  return edges;
}

// Where paths cross a face: the sides (corner positions) they enter and leave by, and the midpoint
// vertex on each (kNoNode where none crosses).
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

// Appends a new vertex at the average of `corners`, and with attributes what it is made of.
VertexId add_vertex_between(PolygonMesh& mesh, std::vector<Blend>* new_vertices, Blend corners) {
  std::array<double, 3> points[4];
  std::size_t n = 0;
  for (; n < 4 && corners[n] != kNoAttribute; ++n) points[n] = mesh.positions[corners[n]];
  mesh.positions.push_back(average({points, n}));
  if (new_vertices != nullptr) new_vertices->push_back(corners);
  return static_cast<VertexId>(mesh.positions.size() - 1);
}

// Where a search for a path ends: its last face, and the halfedge the path leaves it by (a boundary
// or non-manifold edge), kNoNode when the path ends in a left triangle.
struct PathEnd {
  FaceId target = kNoFace;
  std::uint32_t exit = kNoNode;
};

// The paths from each left triangle and the midpoints on them: which faces they cross, where.
// Each path is a breadth-first search over pair quads not on a path yet; O(r) for the region r it
// explores.
class LeftoverJoiner {
 public:
  LeftoverJoiner(PolygonMesh& mesh, const Halfedges& half, const std::vector<FaceKind>& kinds,
                 const Sources& sources, std::vector<Blend>* new_vertices)
      : mesh_(mesh),
        half_(half),
        kinds_(kinds),
        sources_(sources),
        new_vertices_(new_vertices),
        non_manifold_(non_manifold_edges_of(half)),
        used_(kinds.size(), 0),
        crossing_(kinds.size()),
        reached_by_(kinds.size(), kUnreached) {}

  // Joins every left triangle, in face order; a quad that got one midpoint from a split
  // non-manifold edge is joined right after the path that split it.
  std::vector<Crossing> join_all() && {
    const auto face_count = static_cast<FaceId>(kinds_.size());
    for (FaceId s = 0; s < face_count; ++s) {
      if (kinds_[s] != FaceKind::left || used_[s]) continue;
      check_not_degenerate(s);
      used_[s] = 1;
      join(s);
      while (!pending_.empty()) {
        const FaceId g = pending_.back();
        pending_.pop_back();
        join(g);
      }
    }
    return std::move(crossing_);
  }

 private:
  void check_not_degenerate(FaceId s) const {
    const auto corners = mesh_.face(s);
    if (corners[0] == corners[1] || corners[1] == corners[2] || corners[2] == corners[0]) {
      throw MeshError("--all-quad: left triangle (input face " + std::to_string(sources_[s][0]) +
                      ") repeats a vertex; it cannot become a quad");
    }
  }

  // From face s (a left triangle, or a quad with one midpoint) to the nearest free left triangle
  // or boundary edge, failing both to the nearest non-manifold edge it may split; splits along
  // the path found.
  void join(FaceId s) {
    const PathEnd end = find_path(s);
    const VertexId exit_midpoint = split_along_path(s, end);
    for (FaceId f : visited_) reached_by_[f] = kUnreached;
    if (end.exit != kNoNode && non_manifold_.edge_of[end.exit] != kNoNode) {
      split_other_faces_of(end.exit, exit_midpoint);
    }
  }

  bool usable_at_split(FaceId g) const {
    return !used_[g] && (kinds_[g] == FaceKind::left || kinds_[g] == FaceKind::pair);
  }

  // Whether face f may end a path at halfedge h, a non-manifold edge: every other face on the edge
  // is a free left triangle or a free quad (each such quad then starts a path of its own).
  bool may_split_non_manifold(FaceId f, std::uint32_t h) const {
    if (non_manifold_.edge_of[h] == kNoNode) return false;
    bool all_usable = true;
    for (std::uint32_t other : non_manifold_.halfedges[non_manifold_.edge_of[h]]) {
      all_usable &= other == h || (half_.face(other) != f && usable_at_split(half_.face(other)));
    }
    return all_usable;
  }

  void reach(FaceId g, std::uint32_t entry) {
    reached_by_[g] = entry;
    visited_.push_back(g);
  }

  // Breadth-first from s; reached_by_ holds the halfedge each face was entered by.
  PathEnd find_path(FaceId s) {
    visited_.assign(1, s);
    queue_.assign(1, s);
    reached_by_[s] = kStart;
    PathEnd end, last_resort;
    for (std::size_t head = 0; head < queue_.size() && end.target == kNoFace; ++head) {
      const FaceId f = queue_[head];
      const std::uint32_t first = half_.first(f);
      for (std::uint32_t k = 0; k < mesh_.arity(f) && end.target == kNoFace; ++k) {
        const std::uint32_t h = first + k;
        if (half_.twin[h] == kBlocked) {
          if (last_resort.target == kNoFace && may_split_non_manifold(f, h)) last_resort = {f, h};
          continue;
        }
        if (reached_by_[f] == h) continue;  // the side the search came in by
        if (half_.twin[h] == kBoundary) {
          end = {f, h};
          break;
        }
        const FaceId g = half_.face(half_.twin[h]);
        if (used_[g] || reached_by_[g] != kUnreached) continue;
        if (kinds_[g] == FaceKind::left) {
          reach(g, half_.twin[h]);
          end = {g, kNoNode};
        } else if (kinds_[g] == FaceKind::pair) {
          reach(g, half_.twin[h]);
          queue_.push_back(g);
        }
      }
    }
    if (end.target == kNoFace) end = last_resort;
    if (end.target == kNoFace) {
      throw MeshError("--all-quad: face " + std::to_string(sources_[s][0]) +
                      " (input) can reach no left triangle, no boundary edge and no non-manifold "
                      "edge it could split, across edges of two faces and quads not already "
                      "split; no all-quad mesh on these vertices");
    }
    return end;
  }

  VertexId split_edge(std::uint32_t h) {
    return add_vertex_between(mesh_, new_vertices_,
                              {half_.from(h), half_.to(h), kNoAttribute, kNoAttribute});
  }

  void cross(FaceId f, std::uint32_t h, VertexId midpoint) {
    Crossing& c = crossing_[f];
    const int slot = c.side[0] == kNoNode ? 0 : 1;
    c.side[slot] = h - half_.first(f);
    c.midpoint[slot] = midpoint;
  }

  // Walks back from the path's end to s, splitting each edge crossed (the exit first). Returns the
  // exit's midpoint, kNoNode when the path ends in a left triangle.
  VertexId split_along_path(FaceId s, PathEnd end) {
    VertexId exit_midpoint = kNoNode;
    if (end.exit != kNoNode) {
      exit_midpoint = split_edge(end.exit);
      cross(end.target, end.exit, exit_midpoint);
    } else {
      used_[end.target] = 1;
    }
    if (kinds_[end.target] == FaceKind::pair) used_[end.target] = 1;
    for (FaceId f = end.target; f != s;) {
      const std::uint32_t entry = reached_by_[f];  // f's halfedge, twin in the previous face
      const VertexId m = split_edge(entry);
      cross(f, entry, m);
      const std::uint32_t back = half_.twin[entry];
      const FaceId previous = half_.face(back);
      cross(previous, back, m);
      if (kinds_[f] == FaceKind::pair) used_[f] = 1;
      f = previous;
    }
    return exit_midpoint;
  }

  // A path left by non-manifold edge `exit`: the edge's other faces take its midpoint too.
  void split_other_faces_of(std::uint32_t exit, VertexId midpoint) {
    for (std::uint32_t other : non_manifold_.halfedges[non_manifold_.edge_of[exit]]) {
      if (other == exit) continue;
      const FaceId g = half_.face(other);
      if (!usable_at_split(g)) {  // the path itself went through it
        throw MeshError("--all-quad: the split of a non-manifold edge beside input face " +
                        std::to_string(sources_[g][0]) +
                        " meets a face already split; no all-quad mesh found");
      }
      cross(g, other, midpoint);
      used_[g] = 1;
      if (kinds_[g] == FaceKind::pair) pending_.push_back(g);
    }
  }

  PolygonMesh& mesh_;
  const Halfedges& half_;
  const std::vector<FaceKind>& kinds_;
  const Sources& sources_;
  std::vector<Blend>* new_vertices_;  // null without attributes
  const NonManifoldEdges non_manifold_;
  std::vector<std::uint8_t> used_;  // a left triangle already joined, or a quad already on a path
  std::vector<Crossing> crossing_;
  std::vector<std::uint32_t> reached_by_;  // the halfedge a search entered by
  std::vector<FaceId> visited_, queue_;
  std::vector<FaceId> pending_;  // quads with one midpoint from a non-manifold split
};

// A piece's corner, by its place in the face it is cut from: corner k, the midpoint of side k
// (k + kSide), or the face's centre (kCentre).
constexpr std::uint32_t kSide = 8, kCentre = 16;

// The output faces after the splits, and with attributes what each face and corner is made from.
struct RebuiltFaces {
  PolygonMesh mesh;
  Sources sources;
  std::vector<FaceId> face_of;
  std::vector<Blend> corner_from;
  std::uint64_t pieces = 0;  // faces made by the splits
};

// The faces again, with every crossed face replaced by its pieces (same sources).
class FaceRebuilder {
 public:
  FaceRebuilder(PolygonMesh& mesh, const Halfedges& half, const Sources& sources,
                std::vector<Blend>* new_vertices)
      : mesh_(mesh), half_(half), sources_(sources), new_vertices_(new_vertices) {}

  RebuiltFaces rebuild(std::span<const Crossing> crossing, std::size_t input_vertices) && {
    out_.mesh.corners.reserve(mesh_.corners.size() + 8 * (mesh_.positions.size() - input_vertices));
    for (FaceId f = 0; f < crossing.size(); ++f) {
      const Crossing& c = crossing[f];
      if (c.side[0] == kNoNode) {
        add_as_is(f);
      } else if (mesh_.arity(f) == 3) {
        add_split_triangle(f, c);
      } else {
        add_split_quad(f, c);
      }
    }
    return std::move(out_);
  }

 private:
  bool carry() const { return new_vertices_ != nullptr; }

  void add_as_is(FaceId f) {
    const auto q = mesh_.face(f);
    out_.mesh.add_face(q);
    out_.sources.push_back(sources_[f]);
    if (!carry()) return;
    out_.face_of.push_back(f);
    for (std::uint32_t k = 0; k < q.size(); ++k) {
      out_.corner_from.push_back({half_.first(f) + k, kNoAttribute, kNoAttribute, kNoAttribute});
    }
  }

  // A piece of face f: its vertices, and the same corners by their place in f, whose corner
  // values each blends.
  void add_piece(FaceId f, const std::array<VertexId, 4>& corners,
                 std::initializer_list<std::uint32_t> places) {
    out_.mesh.add_face(corners);
    out_.sources.push_back(sources_[f]);
    ++out_.pieces;
    if (!carry()) return;
    out_.face_of.push_back(f);
    const std::uint32_t first = half_.first(f), n = mesh_.arity(f);
    for (std::uint32_t k : places) {
      if (k == kCentre) {
        out_.corner_from.push_back({first, first + 1, first + 2, first + 3});
      } else if (k >= kSide) {
        out_.corner_from.push_back(
            {first + k - kSide, first + (k - kSide + 1) % n, kNoAttribute, kNoAttribute});
      } else {
        out_.corner_from.push_back({first + k, kNoAttribute, kNoAttribute, kNoAttribute});
      }
    }
  }

  // A left triangle with one midpoint m on side i: (q_i, m, q_i+1, q_i+2).
  void add_split_triangle(FaceId f, const Crossing& c) {
    const auto q = mesh_.face(f);
    const std::uint32_t i = c.side[0];
    add_piece(f, {q[i], c.midpoint[0], q[(i + 1) % 3], q[(i + 2) % 3]},
              {i, kSide + i, (i + 1) % 3, (i + 2) % 3});
  }

  // A quad crossed through sides i and j with midpoints mi, mj: two quads when the path goes
  // straight through, three around a new centre vertex when it turns.
  void add_split_quad(FaceId f, const Crossing& c) {
    const auto q = mesh_.face(f);
    std::uint32_t i = c.side[0], j = c.side[1];
    VertexId mi = c.midpoint[0], mj = c.midpoint[1];
    if ((i + 3) % 4 == j) {  // j just before i: swap so that j = i + 1 or i + 2
      std::swap(i, j);
      std::swap(mi, mj);
    }
    const VertexId a = q[i], b = q[(i + 1) % 4], cc = q[(i + 2) % 4], d = q[(i + 3) % 4];
    const std::uint32_t ia = i, ib = (i + 1) % 4, ic = (i + 2) % 4, id = (i + 3) % 4;
    if (j == ic) {
      add_piece(f, {a, mi, mj, d}, {ia, kSide + ia, kSide + ic, id});
      add_piece(f, {mi, b, cc, mj}, {kSide + ia, ib, ic, kSide + ic});
      return;
    }
    const VertexId x = add_vertex_between(mesh_, new_vertices_, {a, b, cc, d});
    add_piece(f, {a, mi, x, d}, {ia, kSide + ia, kCentre, id});
    add_piece(f, {mi, b, mj, x}, {kSide + ia, ib, kSide + ib, kCentre});
    add_piece(f, {x, mj, cc, d}, {kCentre, kSide + ib, ic, id});
  }

  PolygonMesh& mesh_;
  const Halfedges& half_;
  const Sources& sources_;
  std::vector<Blend>* new_vertices_;  // null without attributes
  RebuiltFaces out_;
};

}  // namespace

void split_leftovers(QuadResult& result, const std::vector<FaceKind>& kinds) {
  PolygonMesh& mesh = result.mesh;
  const Halfedges half = halfedges_of(mesh);
  const std::size_t input_vertices = mesh.positions.size();
  // With attributes: what each new vertex is made from.
  const bool carry = !mesh.attributes.empty();
  std::vector<Blend> new_vertices;
  std::vector<Blend>* const blends = carry ? &new_vertices : nullptr;

  const std::vector<Crossing> crossing =
      LeftoverJoiner(mesh, half, kinds, result.sources, blends).join_all();
  RebuiltFaces rebuilt =
      FaceRebuilder(mesh, half, result.sources, blends).rebuild(crossing, input_vertices);

  PolygonMesh& out = rebuilt.mesh;
  if (carry) {
    out.attributes = derived_attributes(mesh.attributes, input_vertices, rebuilt.face_of,
                                        rebuilt.corner_from, new_vertices);
  }
  out.attributes.position_type = mesh.attributes.position_type;
  // A float PLY is written back as float: the new vertices are held as floats, so that the result
  // is what the file will hold (a midpoint of two floats needs up to 25 bits).
  for (std::size_t v = input_vertices; v < mesh.positions.size(); ++v) {
    for (double& x : mesh.positions[v]) x = held_as(out.attributes.position_type, x);
  }
  out.positions = std::move(mesh.positions);
  result.stats.added_vertices = out.positions.size() - input_vertices;
  result.stats.split_quads = rebuilt.pieces;
  result.mesh = std::move(out);
  result.sources = std::move(rebuilt.sources);
}

}  // namespace petersen::quad_detail
