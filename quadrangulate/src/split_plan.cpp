#include "split_plan.hpp"

#include <algorithm>
#include <string>

#include "minimum_t_join.hpp"
#include "parity_system.hpp"
#include "petersen/graph/component_forest.hpp"

namespace petersen::quad_detail {

bool repeats_a_vertex(std::span<const VertexId> corners) {
  if (corners.size() <= 8) {  // the usual faces: no allocation
    for (std::size_t i = 0; i < corners.size(); ++i)
      for (std::size_t j = i + 1; j < corners.size(); ++j)
        if (corners[i] == corners[j]) return true;
    return false;
  }
  std::vector<VertexId> sorted(corners.begin(), corners.end());
  std::sort(sorted.begin(), sorted.end());
  return std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
}

namespace {

using Sources = std::span<const std::array<FaceId, 2>>;

// The edges that may be split, by how many faces they have: edges of two faces and boundary edges
// (the dual's edges, `twin` kNoNode for the boundary's sink) and non-manifold edges (all their
// halfedges). Per face, whether it borders a kept face, for the error that names --keep-polygons.
struct SplittableEdges {
  std::vector<std::array<std::uint32_t, 2>> dual;  // {halfedge, twin}
  std::vector<std::uint32_t> non_manifold_start{0};
  std::vector<std::uint32_t> non_manifold_halfedges;
  std::vector<std::uint8_t> borders_kept;  // the kept_faces reasons of the faces beside it
};

// Per face: why it is kept as it is (kKeptPolygon, kKeptDegenerate), or 0. A face that repeats a
// vertex has no cut into quads that repeats none, so wherever it must change it is kept instead:
// the rest of the mesh is still made quads (its sides are never split, so it stays as it was).
std::vector<std::uint8_t> kept_faces(const PolygonMesh& mesh, std::span<const FaceKind> kinds,
                                     bool keep_polygons) {
  std::vector<std::uint8_t> kept(mesh.face_count(), 0);
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    if (keep_polygons && kinds[f] == FaceKind::kept && mesh.arity(f) != 3) {
      kept[f] = kKeptPolygon;
    } else if (kinds[f] != FaceKind::pair && repeats_a_vertex(mesh.face(f))) {
      kept[f] = kKeptDegenerate;
    }
  }
  return kept;
}

SplittableEdges splittable_edges(const PolygonHalfedges& half, const EdgeGroups& groups,
                                 std::span<const std::uint8_t> kept, std::size_t face_count) {
  SplittableEdges edges;
  edges.borders_kept.assign(face_count, 0);
  for_each_edge_group(groups, [&](std::uint32_t first, std::uint32_t end) {
    std::uint8_t reasons = 0;
    for (std::uint32_t i = first; i < end; ++i) reasons |= kept[half.face(groups.entries[i][1])];
    if (reasons != 0) {
      for (std::uint32_t i = first; i < end; ++i)
        edges.borders_kept[half.face(groups.entries[i][1])] |= reasons;
      return;
    }
    const std::uint32_t h1 = groups.entries[first][1];
    if (end - first == 1) {
      edges.dual.push_back({h1, kNoNode});
    } else if (end - first == 2) {
      const std::uint32_t h2 = groups.entries[first + 1][1];
      if (half.face(h1) != half.face(h2)) edges.dual.push_back({h1, h2});
    } else {
      for (std::uint32_t i = first; i < end; ++i) {
        edges.non_manifold_halfedges.push_back(groups.entries[i][1]);
      }
      edges.non_manifold_start.push_back(
          static_cast<std::uint32_t>(edges.non_manifold_halfedges.size()));
    }
  });
  return edges;
}

// The work of plan_splits: the faces' parities, the dual's components (the sink is node F) and
// the plan being filled.
class Planner {
 public:
  Planner(const PolygonMesh& mesh, const PolygonHalfedges& half, const EdgeGroups& groups,
          std::span<const FaceKind> kinds, Sources sources, bool keep_polygons)
      : half_(half),
        sources_(sources),
        keep_polygons_(keep_polygons),
        faces_(static_cast<FaceId>(mesh.face_count())),
        forest_(faces_ + 1) {
    plan_.kept = kept_faces(mesh, kinds, keep_polygons);
    for (std::uint8_t reason : plan_.kept) plan_.degenerate_faces += reason == kKeptDegenerate;
    edges_ = splittable_edges(half, groups, plan_.kept, faces_);
    odd_.resize(faces_ + 1, 0);
    for (FaceId f = 0; f < faces_; ++f) odd_[f] = !plan_.kept[f] && mesh.arity(f) % 2 == 1;
    for (const auto& [h, twin] : edges_.dual) {
      forest_.unite(half.face(h), twin == kNoNode ? faces_ : half.face(twin));
    }
  }

  SplitPlan plan(std::uint32_t threads) && {
    split_non_manifold_edges();
    split_minimum_t_join(threads);
    return std::move(plan_);
  }

 private:
  // Per root of the forest: the parity of its component's T faces.
  std::vector<std::uint8_t> component_parity() {
    std::vector<std::uint8_t> parity(faces_ + 1, 0);
    for (FaceId f = 0; f < faces_; ++f) parity[forest_.find(f)] ^= odd_[f];
    return parity;
  }

  void add_split(std::span<const std::uint32_t> halfedges) {
    plan_.halfedges.insert(plan_.halfedges.end(), halfedges.begin(), halfedges.end());
    plan_.edge_start.push_back(static_cast<std::uint32_t>(plan_.halfedges.size()));
  }

  std::span<const std::uint32_t> non_manifold_edge(std::uint32_t i) const {
    const auto& start = edges_.non_manifold_start;
    return {edges_.non_manifold_halfedges.data() + start[i], start[i + 1] - start[i]};
  }

  // The closed components of odd parity, made even by splitting non-manifold edges: each flips
  // the components of its faces (with multiplicity mod 2); the sink's component needs nothing.
  void split_non_manifold_edges() {
    const std::vector<std::uint8_t> parity = component_parity();
    const NodeId sink = forest_.find(faces_);
    std::vector<std::uint32_t> target;
    for (FaceId f = 0; f < faces_; ++f)
      if (forest_.find(f) == f && f != sink && parity[f]) target.push_back(f);
    if (target.empty()) return;
    const std::uint32_t count = static_cast<std::uint32_t>(edges_.non_manifold_start.size() - 1);
    std::vector<std::vector<std::uint32_t>> columns(count);
    for (std::uint32_t i = 0; i < count; ++i) {
      std::vector<std::uint32_t>& rows = columns[i];
      for (std::uint32_t h : non_manifold_edge(i)) {
        const NodeId root = forest_.find(half_.face(h));
        if (root != sink) rows.push_back(root);
      }
      std::sort(rows.begin(), rows.end());
      std::vector<std::uint32_t> odd_rows;  // a row twice flips nothing
      for (std::size_t k = 0; k < rows.size();) {
        std::size_t e = k;
        while (e < rows.size() && rows[e] == rows[k]) ++e;
        if ((e - k) % 2 == 1) odd_rows.push_back(rows[k]);
        k = e;
      }
      rows = std::move(odd_rows);
    }
    const ParitySolution solution = solve_parity_system(columns, std::move(target));
    if (solution.stuck != ParitySolution::kNoRow) refuse(solution.stuck);
    for (std::uint32_t i : solution.chosen) {
      add_split(non_manifold_edge(i));
      for (std::uint32_t h : non_manifold_edge(i)) odd_[half_.face(h)] ^= 1;
    }
    plan_.non_manifold_splits = solution.chosen.size();
  }

  [[noreturn]] void refuse(FaceId root) {
    std::uint8_t walls = 0;
    for (FaceId f = 0; f < faces_; ++f)
      if (forest_.find(f) == root) walls |= edges_.borders_kept[f];
    std::string message =
        "--all-quad: no all-quad mesh exists on these faces: the faces joined to input face " +
        std::to_string(sources_[root][0]) +
        " across edges of two faces have an odd total number of sides, and no choice of "
        "non-manifold edges to split makes it even (a midpoint adds one side to every face on "
        "its edge)";
    if ((walls & kKeptPolygon) && keep_polygons_) {
      message +=
          "; --keep-polygons keeps the polygons around them whole, and without it they "
          "may be split";
    }
    if (walls & kKeptDegenerate) {
      message += "; faces beside them repeat a vertex, and are kept as they are";
    }
    throw MeshError(message);
  }

  // A minimum T-join of the dual over the components that hold T faces; the sink is one node,
  // whose parity makes its component's even.
  void split_minimum_t_join(std::uint32_t threads) {
    const std::vector<std::uint8_t> parity = component_parity();
    std::vector<std::uint8_t> has_odd(faces_ + 1, 0);
    for (FaceId f = 0; f < faces_; ++f) has_odd[forest_.find(f)] |= odd_[f];
    TJoinGraph graph;
    std::vector<NodeId> node(faces_ + 1, kNoNode);
    for (FaceId f = 0; f <= faces_; ++f) {
      if (!has_odd[forest_.find(f)]) continue;
      node[f] = graph.node_count++;
      graph.odd.push_back(f == faces_ ? parity[forest_.find(f)] : odd_[f]);
    }
    std::vector<std::uint32_t> dual_edge;
    for (std::uint32_t i = 0; i < edges_.dual.size(); ++i) {
      const auto [h, twin] = edges_.dual[i];
      const FaceId a = half_.face(h), b = twin == kNoNode ? faces_ : half_.face(twin);
      if (node[a] == kNoNode) continue;
      graph.edges.push_back({node[a], node[b]});
      dual_edge.push_back(i);
    }
    const TJoinResult join = minimum_t_join(graph, threads);
    for (EdgeId e : join.join) {
      const auto& halfedges = edges_.dual[dual_edge[e]];
      add_split({halfedges.data(), std::size_t(halfedges[1] == kNoNode ? 1 : 2)});
    }
    for (std::uint32_t h : edges_.non_manifold_halfedges)
      plan_.non_manifold_beside_odd |= has_odd[forest_.find(half_.face(h))] != 0;
    plan_.minimum = plan_.non_manifold_splits + join.join.size();
    plan_.join_certified = join.certified;
  }

  const PolygonHalfedges& half_;
  Sources sources_;
  bool keep_polygons_;
  FaceId faces_;
  ComponentForest forest_;
  SplitPlan plan_;
  SplittableEdges edges_;
  std::vector<std::uint8_t> odd_;  // per face: odd side count, with the splits chosen so far
};

}  // namespace

SplitPlan plan_splits(const PolygonMesh& mesh, const PolygonHalfedges& half,
                      const EdgeGroups& groups, std::span<const FaceKind> kinds,
                      std::span<const std::array<FaceId, 2>> sources, bool keep_polygons,
                      std::uint32_t threads) {
  return Planner(mesh, half, groups, kinds, sources, keep_polygons).plan(threads);
}

}  // namespace petersen::quad_detail
