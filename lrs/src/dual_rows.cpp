#include "dual_rows.hpp"

#include <stdexcept>
#include <string>

namespace petersen::lrs {

DualRows into_dual_rows(Triangulation&& tri, ExpansionResult&& expansion) {
  if (tri.live_faces_ != tri.face_capacity_) {
    throw std::logic_error("lrs::into_dual_rows: some faces are contracted away");
  }
  const FaceId faces = tri.face_capacity_;
  const auto halfedges = static_cast<Halfedge>(tri.links_.size());
  // Faces numbered in order of their smallest halfedge (no per-halfedge face array and no first
  // halfedge per face: 16 bytes per face off the peak). The vertex and edge arrays go first
  // (`= {}` would keep the buffers).
  free_storage(tri.out_);
  free_storage(tri.degree_);
  free_storage(tri.edge_alive_);

  // The triangles with the input's vertex ids and M as the side of each face it crosses (1 byte;
  // 3: none); in the same pass each halfedge's slot in the rows (3f + side) is written over its
  // origin, which nothing reads after (a face's pass touches only its own halfedges). The edge
  // states and the vertex map go before the rows are made.
  constexpr std::uint8_t kNoSide = 3;
  DualRows k;
  k.triangles.resize(faces);
  std::pmr::vector<std::uint8_t> matched_side(faces, kNoSide);
  FaceId f = 0;
  for (Halfedge first = 0; first < halfedges; ++first) {
    if (!tri.smallest_of_face(first)) continue;
    if (f == faces) throw std::logic_error("lrs::into_dual_rows: more next cycles than faces");
    Halfedge h = first;
    for (std::uint8_t side = 0; side < 3; ++side, h = tri.next(h)) {
      VertexId& origin = tri.links_[h].origin;
      k.triangles[f][side] = tri.input_vertex(origin);
      origin = 3 * f + side;
      if (!(expansion.edge_state[Triangulation::edge(h)] & kMatched)) continue;
      if (matched_side[f] != kNoSide) {
        throw std::logic_error("lrs expansion: two edges of M pair face " + std::to_string(f));
      }
      matched_side[f] = side;
    }
    ++f;
  }
  if (f != faces) throw std::logic_error("lrs::into_dual_rows: fewer next cycles than faces");
  free_storage(tri.input_vertex_);
  free_storage(expansion.edge_state);

  // Only the slots are read from here on: each edge's two (its halfedges') are gathered into the
  // links' first half in place (link e is written after links 2e and 2e + 1 >= e are read), and
  // the second half is given back before the rows are made (12 bytes per triangle off this
  // phase's peak). Each row entry comes from the twin's slot, in
  // one sweep in edge order; M's sides become partners once the links are freed.
  const std::size_t edges = halfedges / 2;
  for (std::size_t e = 0; e < edges; ++e) {
    tri.links_[e] = {tri.links_[2 * e].origin, tri.links_[2 * e + 1].origin};
  }
  tri.links_.shrink(edges);
  k.rows.resize(3 * std::size_t{faces});
  for (std::size_t e = 0; e < edges; ++e) {
    const auto [first, second] = tri.links_[e];
    k.rows[first] = second / 3;
    k.rows[second] = first / 3;
  }
  tri = Triangulation();

  k.partner.resize(faces);
  for (f = 0; f < faces; ++f) {
    const std::uint8_t side = matched_side[f];
    k.partner[f] = side == kNoSide ? kNoNode : k.rows[3 * std::size_t{f} + side];
    k.unpaired += side == kNoSide;
  }
  return k;
}
}  // namespace petersen::lrs
