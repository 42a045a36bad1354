// Stages 3 and 4 of the front door (stages.hpp): the output faces, and their quads' figures.

#include <algorithm>

#include "petersen/dualize/quad_of.hpp"
#include "petersen/graph/parallel.hpp"
#include "petersen/quadrangulate/stages.hpp"

namespace petersen {

namespace {

// Per face, its node (kNoNode for a polygon); empty when node v is face v. Decided by the mesh:
// node_face is empty both when every face is a triangle and when none is.
std::pmr::vector<NodeId> node_of_faces(const PolygonMesh& mesh, const PairableGraph& graph) {
  std::pmr::vector<NodeId> face_node;
  if (!mesh.all_triangles()) {
    face_node.assign(mesh.face_count(), kNoNode);
    for (NodeId v = 0; v < graph.node_count; ++v) face_node[graph.node_face[v]] = v;
  }
  return face_node;
}

// Appends faces to an output whose arrays are sized exactly, so that none grows past what it
// holds: a pair turns six corners into four.
class FaceWriter {
 public:
  FaceWriter(OutputFaces& out, bool with_sources) : out_(out), with_sources_(with_sources) {}

  void reserve(std::size_t faces, std::size_t corners, bool has_pairs) {
    out_.result.mesh.corners.reserve(corners);
    if (has_pairs) out_.result.mesh.face_start.reserve(faces + 1);
    if (with_sources_) out_.result.sources.reserve(faces);
    out_.kinds.reserve(faces);
  }
  void add(std::span<const VertexId> corners, FaceKind kind, std::array<FaceId, 2> sources) {
    out_.result.mesh.add_face(corners);
    if (with_sources_) out_.result.sources.push_back(sources);
    out_.kinds.push_back(kind);
  }

 private:
  OutputFaces& out_;
  bool with_sources_;
};

// The faces in input order: a pair's quad where its first triangle was, every other face as it is.
// `face_count` is the input's (its corners may have been freed when lrs paired it whole: every
// node is then kLrsNode, and no face is read).
void add_faces_in_input_order(const PolygonMesh& mesh, FaceId face_count,
                              const PairableGraph& graph, std::span<const NodeId> partner_of,
                              FaceWriter& writer, QuadStats& stats) {
  const std::pmr::vector<NodeId> face_node = node_of_faces(mesh, graph);
  for (FaceId f = 0; f < face_count; ++f) {
    // A pair's second triangle is anywhere in the mesh: fetching its corners a few faces ahead
    // takes a quarter off this loop's time on armadillo-sub2.
    if (constexpr FaceId kAhead = 8; f + kAhead < face_count) {
      const NodeId ahead = face_node.empty() ? f + kAhead : face_node[f + kAhead];
      const NodeId partner = ahead == kNoNode ? kNoNode : partner_of[ahead];
      if (partner < graph.node_count) __builtin_prefetch(mesh.face(graph.face_of(partner)).data());
    }
    const NodeId v = face_node.empty() ? f : face_node[f];
    const NodeId partner = v == kNoNode ? kNoNode : partner_of[v];
    if (v == kNoNode || partner == kNoNode) {
      writer.add(mesh.face(f), v != kNoNode ? FaceKind::left : FaceKind::kept, {f, kNoFace});
      stats.triangles_left += v != kNoNode;
    } else if (partner != kLrsNode && v < partner) {
      const FaceId g = graph.face_of(partner);
      writer.add(quad_of(mesh.face(f), mesh.face(g)), FaceKind::pair, {f, g});
      ++stats.pairs;
    }
  }
}

}  // namespace

OutputFaces output_faces(const PolygonMesh& mesh, const PairableGraph& graph,
                         TrianglePairing pairing, Positions positions, bool with_sources,
                         QuadStats& stats) {
  // An all-triangle mesh has a node per face: its count holds when lrs freed the corners.
  const FaceId face_count =
      mesh.all_triangles() ? graph.node_count : static_cast<FaceId>(mesh.face_count());
  const std::size_t corners_in =
      mesh.all_triangles() ? 3 * std::size_t{graph.node_count} : mesh.corners.size();
  // The result is on the positions' resource (QuadOptions::memory), made there, not assigned.
  std::pmr::memory_resource* const memory = positions.get_allocator().resource();
  OutputFaces out{.result = {.mesh = PolygonMesh(memory),
                             .sources = std::pmr::vector<std::array<FaceId, 2>>(memory)}};
  out.result.mesh.positions = std::move(positions);
  std::size_t paired_nodes = 0;
  for (NodeId partner : pairing.partner) paired_nodes += partner != kNoNode;
  FaceWriter writer(out, with_sources);
  writer.reserve(face_count - paired_nodes / 2, corners_in - paired_nodes, paired_nodes > 0);
  add_faces_in_input_order(mesh, face_count, graph, pairing.partner, writer, stats);
  for (const LrsQuad& quad : pairing.lrs_quads) {
    writer.add(quad.corners, FaceKind::pair, quad.sources);
    ++stats.pairs;
  }
  for (NodeId v : pairing.tutte_set) out.result.tutte_set.push_back(graph.face_of(v));
  return out;
}

QualityFigures measure_quads(const PolygonMesh& out, std::span<const FaceKind> kinds,
                             std::uint32_t threads) {
  // Each face's quad_corner_deviation, −1 for a face that is not a pair's quad; measured in
  // blocks on the threads, written in full (on the mesh's resource, which may reuse memory the
  // stages before freed).
  const FaceId out_faces = static_cast<FaceId>(out.face_count());
  RawArray<double> costs = make_raw_array<double>(out_faces, out.memory());
  constexpr FaceId kBlock = 1 << 16;
  run_parallel(threads, (out_faces + kBlock - 1) / kBlock, [&](std::uint32_t block) {
    const auto& p = out.positions;
    const FaceId end = std::min(out_faces, (block + 1) * kBlock);
    for (FaceId o = block * kBlock; o < end; ++o) {
      // The corners' positions are random reads (on armadillo-sub2, 65 % of the measure's
      // samples wait on them): fetched a few faces ahead, both ends of each 24-byte position.
      constexpr FaceId kAhead = 8;
      if (o + kAhead < end) {
        for (VertexId v : out.face(o + kAhead)) {
          __builtin_prefetch(p[v].data());
          __builtin_prefetch(p[v].data() + 2);
        }
      }
      const auto c = out.face(o);
      const bool pair_quad = kinds[o] == FaceKind::pair;
      costs[o] = pair_quad ? quad_corner_deviation(p[c[0]], p[c[1]], p[c[2]], p[c[3]]) : -1.0;
    }
  });
  // Gathered and summed in face order, so that the figures do not depend on the threads.
  const std::span<double> all_costs(costs.get(), out_faces);
  const auto quad_costs_end =
      std::remove_if(all_costs.begin(), all_costs.end(), [](double c) { return c < 0; });
  return quality_figures_in_place({all_costs.begin(), quad_costs_end});
}

}  // namespace petersen
