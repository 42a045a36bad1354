#include "petersen/lrs/dual_rows.hpp"

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
  // halfedge per face: 16 bytes per face at the peak before). The vertex and edge arrays go first
  // (`= {}` would keep the buffers).
  tri.out_ = HugeVector<Halfedge>();
  tri.degree_ = HugeVector<std::uint32_t>();
  tri.edge_alive_ = HugeVector<std::uint8_t>();

  // The triangles with the input's vertex ids, and in the same pass each face's number written
  // over its halfedges' origins, which nothing reads after (a face's pass touches only its own
  // halfedges).
  DualRows k;
  k.triangles.resize(faces);
  FaceId f = 0;
  for (Halfedge h = 0; h < halfedges; ++h) {
    if (!tri.smallest_of_face(h)) continue;
    if (f == faces) throw std::logic_error("lrs::into_dual_rows: more next cycles than faces");
    const Halfedge n = tri.next(h), p = tri.next(n);
    k.triangles[f] = {tri.input_vertex(tri.links_[h].origin),
                      tri.input_vertex(tri.links_[n].origin),
                      tri.input_vertex(tri.links_[p].origin)};
    tri.links_[h].origin = tri.links_[n].origin = tri.links_[p].origin = f;
    ++f;
  }
  if (f != faces) throw std::logic_error("lrs::into_dual_rows: fewer next cycles than faces");
  tri.input_vertex_ = std::vector<VertexId>();

  // M as the side of each face it crosses (1 byte; 3: none), made into partners once the links
  // are freed: the peak holds neither the partners nor the links' and rows' successors.
  constexpr std::uint8_t kNoSide = 3;
  k.rows.resize(3 * std::size_t{faces});
  HugeVector<std::uint8_t> matched_side(faces, kNoSide);
  f = 0;
  for (Halfedge first = 0; first < halfedges; ++first) {
    if (!tri.smallest_of_face(first)) continue;
    Halfedge h = first;
    for (std::uint8_t side = 0; side < 3; ++side, h = tri.next(h)) {
      k.rows[3 * std::size_t{f} + side] = tri.links_[Triangulation::twin(h)].origin;
      if (!(expansion.edge_state[Triangulation::edge(h)] & kMatched)) continue;
      if (matched_side[f] != kNoSide) {
        throw std::logic_error("lrs expansion: two edges of M pair face " + std::to_string(f));
      }
      matched_side[f] = side;
    }
    ++f;
  }
  tri = Triangulation();
  expansion.edge_state = HugeVector<std::uint8_t>();

  k.partner.resize(faces);
  for (f = 0; f < faces; ++f) {
    const std::uint8_t side = matched_side[f];
    k.partner[f] = side == kNoSide ? kNoNode : k.rows[3 * std::size_t{f} + side];
    k.unpaired += side == kNoSide;
  }
  return k;
}
}  // namespace petersen::lrs
