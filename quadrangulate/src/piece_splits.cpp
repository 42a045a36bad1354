// Stage 6 on one piece of a mesh (stages.hpp: piece_parity, plan_piece_splits,
// cut_piece_into_quads): split_leftovers' T-join and cut, with the piece's border given.

#include <algorithm>
#include <string>

#include "cut_into_quads.hpp"
#include "minimum_t_join.hpp"
#include "petersen/dualize/quad_quality.hpp"
#include "petersen/graph/component_forest.hpp"
#include "petersen/quadrangulate/stages.hpp"
#include "split_plan.hpp"

namespace petersen {

namespace {

using quad_detail::repeats_a_vertex;

std::vector<std::uint8_t> kept_faces(const PolygonMesh& piece) {
  std::vector<std::uint8_t> kept(piece.face_count(), 0);
  for (FaceId f = 0; f < piece.face_count(); ++f) kept[f] = repeats_a_vertex(piece.face(f));
  return kept;
}

// Calls visit(first, end) for each edge group of the piece whose faces are none kept, and
// kept_edge(first, end) for the others.
template <class Visit, class Kept>
void for_each_edge(const PolygonHalfedges& half, const EdgeGroups& groups,
                   std::span<const std::uint8_t> kept, Visit visit, Kept kept_edge) {
  for_each_edge_group(groups, [&](std::uint32_t first, std::uint32_t end) {
    bool any_kept = false;
    for (std::uint32_t i = first; i < end; ++i) any_kept |= kept[half.face(groups.entries[i][1])];
    if (any_kept) {
      kept_edge(first, end);
    } else {
      visit(first, end);
    }
  });
}

std::array<VertexId, 2> ends_of(const PolygonHalfedges& half, std::uint32_t h) {
  const VertexId a = half.from(h), b = half.to(h);
  return {std::min(a, b), std::max(a, b)};
}

}  // namespace

PieceParity piece_parity(const PolygonMesh& piece) {
  const FaceId faces = static_cast<FaceId>(piece.face_count());
  const PolygonHalfedges half(piece);
  const EdgeGroups groups = half.group();
  const std::vector<std::uint8_t> kept = kept_faces(piece);
  PieceParity parity;
  ComponentForest forest(faces);
  auto open = [&](std::uint32_t first, std::uint32_t end) {
    if (end - first != 1) return;
    const std::uint32_t h = groups.entries[first][1];
    const auto [low, high] = ends_of(half, h);
    parity.open.push_back({low, high, half.face(h), kept[half.face(h)] != 0});
  };
  for_each_edge(
      half, groups, kept,
      [&](std::uint32_t first, std::uint32_t end) {
        open(first, end);
        if (end - first == 2) {
          forest.unite(half.face(groups.entries[first][1]),
                       half.face(groups.entries[first + 1][1]));
        }
      },
      open);
  std::sort(parity.open.begin(), parity.open.end(), [](const auto& a, const auto& b) {
    return std::tie(a.low, a.high) < std::tie(b.low, b.high);
  });
  parity.component.assign(faces, kNoNode);
  std::vector<std::uint32_t> index(faces, kNoNode);
  for (FaceId f = 0; f < faces; ++f) {
    if (kept[f]) {
      ++parity.kept_faces;
      continue;
    }
    std::uint32_t& c = index[forest.find(f)];
    if (c == kNoNode) {
      c = static_cast<std::uint32_t>(parity.component_odd.size());
      parity.component_odd.push_back(0);
    }
    parity.component[f] = c;
    parity.component_odd[c] ^= piece.arity(f) % 2;
  }
  return parity;
}

PieceSplits plan_piece_splits(const PolygonMesh& piece, const PieceSplitInput& input) {
  using quad_detail::TJoinGraph;
  const FaceId faces = static_cast<FaceId>(piece.face_count());
  const std::uint32_t outside =
      std::max<std::uint32_t>(1, static_cast<std::uint32_t>(input.outside_odd.size()));
  const PolygonHalfedges half(piece);
  const EdgeGroups groups = half.group();
  const std::vector<std::uint8_t> kept = kept_faces(piece);
  // The dual: nodes 0..faces-1 the faces, faces + i outside node i (faces: the sink).
  std::vector<std::uint8_t> odd(faces + outside, 0);
  for (FaceId f = 0; f < faces; ++f) odd[f] = !kept[f] && piece.arity(f) % 2 == 1;
  for (std::uint32_t i = 1; i < input.outside_odd.size(); ++i)
    odd[faces + i] = input.outside_odd[i];
  std::vector<std::array<NodeId, 2>> edges;
  std::vector<std::array<VertexId, 2>> edge_ends;
  for_each_edge(
      half, groups, kept,
      [&](std::uint32_t first, std::uint32_t end) {
        const std::uint32_t h = groups.entries[first][1];
        const FaceId f = half.face(h);
        if (end - first == 2) {
          const FaceId g = half.face(groups.entries[first + 1][1]);
          if (f == g) return;  // twice in one face: never split
          edges.push_back({f, g});
          edge_ends.push_back(ends_of(half, h));
          return;
        }
        if (end - first != 1) return;  // non-manifold: never split here
        const auto [low, high] = ends_of(half, h);
        const auto it = std::lower_bound(
            input.border.begin(), input.border.end(), std::array<VertexId, 2>{low, high},
            [](const PieceBorder& b, const std::array<VertexId, 2>& key) {
              return std::tie(b.low, b.high) < std::tie(key[0], key[1]);
            });
        const bool listed = it != input.border.end() && it->low == low && it->high == high;
        const std::uint32_t node = listed ? it->node : 0;
        if (node == kKeepWhole) return;
        if (node == kSplitAlready) {
          odd[f] ^= 1;
          return;
        }
        if (node >= outside) {
          throw std::invalid_argument("plan_piece_splits: outside node " + std::to_string(node) +
                                      " of " + std::to_string(outside));
        }
        edges.push_back({f, faces + node});
        edge_ends.push_back({low, high});
      },
      [](std::uint32_t, std::uint32_t) {});
  ComponentForest forest(faces + outside);
  for (const auto& [a, b] : edges) forest.unite(a, b);
  const NodeId sink = faces;
  std::vector<std::uint8_t> parity(faces + outside, 0), has_odd(faces + outside, 0);
  for (NodeId v = 0; v < faces + outside; ++v) {
    if (v == sink) continue;
    parity[forest.find(v)] ^= odd[v];
    has_odd[forest.find(v)] |= odd[v];
  }
  const NodeId sink_root = forest.find(sink);
  for (NodeId v = 0; v < faces + outside; ++v) {
    if (forest.find(v) == v && v != sink_root && parity[v]) {
      NodeId face = v;
      for (NodeId u = 0; u < faces; ++u)
        if (forest.find(u) == v && odd[u]) face = u;
      throw MeshError(
          "--all-quad part by part: the faces joined to face " + std::to_string(face) +
          " of a part have an odd number of sides in all and no edge leads from them to one that "
          "may still be split (the true boundary or a later part; non-manifold edges and the "
          "edges of faces repeating a vertex are never split part by part)");
    }
  }
  odd[sink] = parity[sink_root];
  has_odd[sink_root] |= odd[sink];
  // A minimum T-join over the components holding T nodes.
  TJoinGraph graph;
  std::vector<NodeId> node(faces + outside, kNoNode);
  for (NodeId v = 0; v < faces + outside; ++v) {
    if (!has_odd[forest.find(v)]) continue;
    node[v] = graph.node_count++;
    graph.odd.push_back(odd[v]);
  }
  std::vector<std::uint32_t> graph_edge;
  for (std::uint32_t e = 0; e < edges.size(); ++e) {
    if (node[edges[e][0]] == kNoNode) continue;
    graph.edges.push_back({node[edges[e][0]], node[edges[e][1]]});
    graph_edge.push_back(e);
  }
  PieceSplits splits;
  splits.certified = true;
  if (graph.node_count == 0) return splits;
  const quad_detail::TJoinResult join = quad_detail::minimum_t_join(graph, input.threads);
  for (EdgeId e : join.join) splits.edges.push_back(edge_ends[graph_edge[e]]);
  std::sort(splits.edges.begin(), splits.edges.end());
  splits.certified = join.certified;
  return splits;
}

PieceQuads cut_piece_into_quads(const PolygonMesh& piece,
                                std::span<const std::array<VertexId, 2>> split_edges,
                                const QuadOptions& options) {
  PolygonMesh mesh;
  mesh.positions = piece.positions;
  mesh.corners = piece.corners;
  mesh.face_start = piece.face_start;
  const auto vertices = static_cast<VertexId>(mesh.positions.size());
  const PolygonHalfedges half(mesh);
  const EdgeGroups groups = half.group();
  std::vector<VertexId> midpoint(half.count(), kNoNode);
  for (std::uint32_t h = 0; h < half.count(); ++h) {
    const auto ends = ends_of(half, h);
    const auto it = std::lower_bound(split_edges.begin(), split_edges.end(), ends);
    if (it != split_edges.end() && *it == ends) {
      midpoint[h] = vertices + static_cast<VertexId>(it - split_edges.begin());
    }
  }
  for (const auto& [a, b] : split_edges) {
    const auto& p = mesh.positions[a];
    const auto& q = mesh.positions[b];
    mesh.positions.push_back({(p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2});
  }
  const std::vector<std::uint8_t> kept = kept_faces(piece);
  std::vector<std::array<FaceId, 2>> sources(piece.face_count());
  for (FaceId f = 0; f < sources.size(); ++f) sources[f] = {f, kNoFace};
  quad_detail::QuadPieces cut =
      quad_detail::cut_into_quads(mesh, half, groups, midpoint, kept, sources, nullptr,
                                  {.centres_where_better = options.objective != Objective::pairs});
  PieceQuads out;
  out.mesh = std::move(cut.mesh);
  const VertexId first_centre = vertices + static_cast<VertexId>(split_edges.size());
  out.centre_corners.assign(cut.centres, {kNoNode, kNoNode, kNoNode, kNoNode});
  for (FaceId o = 0; o < out.mesh.face_count(); ++o) {
    for (VertexId v : out.mesh.face(o)) {
      if (v < first_centre) continue;
      // The centre's corners, as cut_into_quads blends them: all up to four, else four spread.
      const auto corners = piece.face(cut.sources[o][0]);
      const std::uint32_t n = static_cast<std::uint32_t>(corners.size());
      const std::uint32_t count = std::min<std::uint32_t>(n, 4);
      for (std::uint32_t i = 0; i < count; ++i)
        out.centre_corners[v - first_centre][i] = corners[i * n / count];
    }
  }
  const auto& p = mesh.positions;
  out.split_quality.reserve(cut.pieces.size());
  for (FaceId o : cut.pieces) {
    const auto c = out.mesh.face(o);
    out.split_quality.push_back(quad_corner_deviation(p[c[0]], p[c[1]], p[c[2]], p[c[3]]));
  }
  return out;
}

}  // namespace petersen
