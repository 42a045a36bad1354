// --all-quad part by part (all_quad.hpp): the parts' parities, the seam graph, each part's
// T-join in part order, and its cut into quads.

#include "petersen/partition/all_quad.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <tuple>

#include "petersen/graph/component_forest.hpp"
#include "petersen/quadrangulate/stages.hpp"

namespace petersen {

namespace {

using Ends = std::array<VertexId, 2>;

// A part's faces over its own vertices (0..V-1 in ascending global order, so that the order of
// edges is the same in both numberings), with their positions when the part has them.
struct Piece {
  PolygonMesh mesh;
  std::vector<VertexId> global;  // per local vertex
};

Piece piece_of(const PartFaces& faces) {
  Piece piece;
  piece.global.assign(faces.corners.begin(), faces.corners.end());
  std::sort(piece.global.begin(), piece.global.end());
  piece.global.erase(std::unique(piece.global.begin(), piece.global.end()), piece.global.end());
  PolygonMesh& mesh = piece.mesh;
  mesh.corners.resize(faces.corners.size());
  for (std::size_t c = 0; c < faces.corners.size(); ++c) {
    mesh.corners[c] = static_cast<VertexId>(
        std::lower_bound(piece.global.begin(), piece.global.end(), faces.corners[c]) -
        piece.global.begin());
  }
  const bool triangles =
      std::all_of(faces.arity.begin(), faces.arity.end(), [](std::uint8_t n) { return n == 3; });
  if (!triangles) {
    mesh.face_start.resize(faces.arity.size() + 1);
    mesh.face_start[0] = 0;
    for (std::size_t f = 0; f < faces.arity.size(); ++f)
      mesh.face_start[f + 1] = mesh.face_start[f] + faces.arity[f];
  }
  if (mesh.corners.size() != (triangles ? 3 * faces.arity.size() : mesh.face_start.back())) {
    throw std::invalid_argument("PartFaces: the arities do not add up to the corners");
  }
  mesh.positions.resize(piece.global.size());
  if (!faces.corner_positions.empty()) {
    if (faces.corner_positions.size() != faces.corners.size()) {
      throw std::invalid_argument("PartFaces: one position per corner");
    }
    for (std::size_t c = 0; c < mesh.corners.size(); ++c)
      mesh.positions[mesh.corners[c]] = faces.corner_positions[c];
  }
  return piece;
}

Ends global_ends(const Piece& piece, VertexId low, VertexId high) {
  return {piece.global[low], piece.global[high]};
}

const SplitSeams::Edge* find_seam(const SplitSeams& seams, Ends key) {
  const auto it = std::lower_bound(seams.edges.begin(), seams.edges.end(), key,
                                   [](const SplitSeams::Edge& e, const Ends& k) {
                                     return std::tie(e.low, e.high) < std::tie(k[0], k[1]);
                                   });
  if (it == seams.edges.end() || it->low != key[0] || it->high != key[1]) return nullptr;
  return &*it;
}

bool contains(std::span<const Ends> sorted, Ends key) {
  return std::binary_search(sorted.begin(), sorted.end(), key);
}

// The piece's edges with a midpoint among `midpoints` (global, ascending), in piece ids,
// ascending.
std::vector<Ends> split_edges_of(const Piece& piece, std::span<const Ends> midpoints) {
  std::vector<Ends> split;
  const PolygonMesh& mesh = piece.mesh;
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    const auto c = mesh.face(f);
    for (std::size_t k = 0; k < c.size(); ++k) {
      const VertexId a = std::min(c[k], c[(k + 1) % c.size()]);
      const VertexId b = std::max(c[k], c[(k + 1) % c.size()]);
      if (a != b && contains(midpoints, global_ends(piece, a, b))) split.push_back({a, b});
    }
  }
  std::sort(split.begin(), split.end());
  split.erase(std::unique(split.begin(), split.end()), split.end());
  return split;
}

}  // namespace

PartParity part_parity(const PartFaces& faces) {
  const Piece piece = piece_of(faces);
  PieceParity parity = piece_parity(piece.mesh);
  PartParity out;
  out.faces = piece.mesh.face_count();
  out.kept_faces = parity.kept_faces;
  out.component_odd = std::move(parity.component_odd);
  out.border.reserve(parity.open.size());
  for (const PieceOpenEdge& e : parity.open) {
    const std::uint32_t c = parity.component[e.face];
    out.border.push_back({piece.global[e.low], piece.global[e.high], c == kNoNode ? 0 : c, e.kept});
  }
  return out;
}

SplitSeams split_seams(std::span<const PartParity> parts) {
  SplitSeams seams;
  struct Record {
    VertexId low, high;
    std::uint32_t node;
    bool kept;
  };
  std::vector<Record> records;
  seams.node_start.push_back(0);
  for (const PartParity& part : parts) {
    const std::uint32_t base = seams.node_start.back();
    for (const SplitBorderEdge& e : part.border)
      records.push_back({e.low, e.high, base + e.component, e.kept});
    seams.node_odd.insert(seams.node_odd.end(), part.component_odd.begin(),
                          part.component_odd.end());
    seams.node_start.push_back(base + static_cast<std::uint32_t>(part.component_odd.size()));
  }
  std::sort(records.begin(), records.end(), [](const Record& a, const Record& b) {
    return std::tie(a.low, a.high, a.node) < std::tie(b.low, b.high, b.node);
  });
  for (std::size_t i = 0; i < records.size();) {
    std::size_t end = i;
    bool kept = false;
    while (end < records.size() && records[end].low == records[i].low &&
           records[end].high == records[i].high) {
      kept |= records[end].kept;
      ++end;
    }
    SplitSeams::Edge edge{records[i].low, records[i].high, SplitSeams::kSeamWhole,
                          SplitSeams::kSeamWhole};
    if (!kept && end - i == 1) {
      edge.a = records[i].node;
      edge.b = SplitSeams::kSeamSink;
      ++seams.boundary_edges;
    } else if (!kept && end - i == 2) {
      edge.a = records[i].node;
      edge.b = records[i + 1].node;
      ++seams.cut_edges;
    } else {
      ++seams.whole_edges;
    }
    seams.edges.push_back(edge);
    i = end;
  }
  return seams;
}

PartSplitPlan plan_part_all_quad(const PartFaces& faces, std::uint32_t part,
                                 const SplitSeams& seams,
                                 std::span<const std::array<VertexId, 2>> earlier_cut_midpoints,
                                 const QuadOptions& options) {
  if (part + 1 >= seams.node_start.size()) {
    throw std::invalid_argument("plan_part_all_quad: no part " + std::to_string(part));
  }
  const Piece piece = piece_of(faces);
  const PieceParity parity = piece_parity(piece.mesh);
  const std::uint32_t own_first = seams.node_start[part], later = seams.node_start[part + 1];
  const auto nodes = static_cast<std::uint32_t>(seams.node_odd.size());
  // The later parts' nodes, flipped by the cut midpoints chosen so far (each flips its later
  // end), and their groups: components of the seam graph over the later parts and the sink.
  std::vector<std::uint8_t> odd(seams.node_odd.begin(), seams.node_odd.end());
  for (const Ends& key : earlier_cut_midpoints) {
    const SplitSeams::Edge* e = find_seam(seams, key);
    if (e != nullptr && e->b < nodes) odd[e->b] ^= 1;
  }
  const std::uint32_t sink = nodes;
  ComponentForest forest(nodes + 1);
  for (const SplitSeams::Edge& e : seams.edges) {
    if (e.a == SplitSeams::kSeamWhole || e.a < later) continue;
    forest.unite(e.a, e.b == SplitSeams::kSeamSink ? sink : e.b);
  }
  std::vector<std::uint8_t> group_odd(nodes + 1, 0);
  for (std::uint32_t v = later; v < nodes; ++v) group_odd[forest.find(v)] ^= odd[v];
  // The border: each open edge of the piece, by what lies across it.
  std::vector<PieceBorder> border;
  std::vector<std::uint8_t> is_cut, outside_odd{0};
  std::vector<std::uint32_t> outside_of(nodes + 1, kNoNode);
  std::vector<Ends> split_already;
  for (const PieceOpenEdge& open : parity.open) {
    const Ends key = global_ends(piece, open.low, open.high);
    const SplitSeams::Edge* e = find_seam(seams, key);
    if (e == nullptr) {
      throw std::invalid_argument("plan_part_all_quad: edge " + std::to_string(key[0]) + "-" +
                                  std::to_string(key[1]) + " is not in the seams");
    }
    std::uint32_t node = kKeepWhole;
    bool cut = false;
    if (e->a == SplitSeams::kSeamWhole) {
      node = kKeepWhole;
    } else if (e->b == SplitSeams::kSeamSink) {
      node = 0;
    } else {
      const std::uint32_t other = e->a >= own_first && e->a < later ? e->b : e->a;
      if (other < own_first) {
        node = contains(earlier_cut_midpoints, key) ? kSplitAlready : kKeepWhole;
        if (node == kSplitAlready) split_already.push_back({open.low, open.high});
      } else {
        cut = true;
        const std::uint32_t root = forest.find(other);
        if (root == forest.find(sink)) {
          node = 0;
        } else {
          if (outside_of[root] == kNoNode) {
            outside_of[root] = static_cast<std::uint32_t>(outside_odd.size());
            outside_odd.push_back(group_odd[root]);
          }
          node = outside_of[root];
        }
      }
    }
    border.push_back({open.low, open.high, node});
    is_cut.push_back(cut);
  }
  const PieceSplits splits = plan_piece_splits(
      piece.mesh, {.border = border, .outside_odd = outside_odd, .threads = options.threads});
  PartSplitPlan plan;
  plan.certified = splits.certified;
  for (const Ends& local : splits.edges) {
    const Ends key = global_ends(piece, local[0], local[1]);
    plan.midpoints.push_back(key);
    const auto it = std::lower_bound(border.begin(), border.end(), local,
                                     [](const PieceBorder& b, const Ends& k) {
                                       return std::tie(b.low, b.high) < std::tie(k[0], k[1]);
                                     });
    if (it != border.end() && it->low == local[0] && it->high == local[1] &&
        is_cut[it - border.begin()]) {
      plan.cut_midpoints.push_back(key);
    }
  }
  // The cut, to count the faces and centres before anything is written.
  std::vector<Ends> all_split = splits.edges;
  all_split.insert(all_split.end(), split_already.begin(), split_already.end());
  std::sort(all_split.begin(), all_split.end());
  PieceQuads quads = cut_piece_into_quads(piece.mesh, all_split, options);
  plan.faces = quads.mesh.face_count();
  plan.split_quality = std::move(quads.split_quality);
  for (auto corners : quads.centre_corners) {
    for (VertexId& v : corners)
      if (v != kNoNode) v = piece.global[v];
    plan.centre_corners.push_back(corners);
  }
  return plan;
}

PolygonMesh part_all_quads(const PartFaces& faces,
                           std::span<const std::array<VertexId, 2>> midpoints,
                           VertexId vertex_count, VertexId first_centre,
                           const QuadOptions& options) {
  const Piece piece = piece_of(faces);
  const std::vector<Ends> split = split_edges_of(piece, midpoints);
  PieceQuads quads = cut_piece_into_quads(piece.mesh, split, options);
  const auto local = static_cast<VertexId>(piece.global.size());
  const auto midpoint_end = local + static_cast<VertexId>(split.size());
  for (VertexId& v : quads.mesh.corners) {
    if (v < local) {
      v = piece.global[v];
    } else if (v < midpoint_end) {
      const Ends key = global_ends(piece, split[v - local][0], split[v - local][1]);
      v = vertex_count +
          static_cast<VertexId>(std::lower_bound(midpoints.begin(), midpoints.end(), key) -
                                midpoints.begin());
    } else {
      v = first_centre + (v - midpoint_end);
    }
  }
  return std::move(quads.mesh);
}

}  // namespace petersen
