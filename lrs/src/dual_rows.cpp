#include "petersen/lrs/dual_rows.hpp"

#include <stdexcept>
#include <string>

namespace petersen::lrs {

DualRows into_dual_rows(Triangulation&& tri, ExpansionResult&& expansion) {
  if (tri.live_faces_ != tri.face_capacity_) {
    throw std::logic_error("lrs::into_dual_rows: some faces are contracted away");
  }
  const FaceId faces = tri.face_capacity_;
  // `= {}` would keep the buffers (assignment from an initializer list).
  tri.out_ = HugeVector<Halfedge>();
  tri.degree_ = HugeVector<std::uint32_t>();
  tri.edge_alive_ = HugeVector<std::uint8_t>();
  // The origins in the input's ids, so that the vertex map is gone before the rows are made.
  if (!tri.input_vertex_.empty()) {
    for (auto& link : tri.links_) link.origin = tri.input_vertex_[link.origin];
    tri.input_vertex_ = std::vector<VertexId>();
  }

  // Each face's smallest halfedge, the first met in id order: where its rows and corners start.
  HugeVector<Halfedge> first(faces, kNoHalfedge);
  for (Halfedge h = 0; h < tri.links_.size(); ++h) {
    Halfedge& s = first[tri.face_[h]];
    if (s == kNoHalfedge) s = h;
  }
  // M as the side of each face it crosses (1 byte; 3: none), made into partners once the faces
  // and the triangles' links are freed: the peak holds neither the partners nor the triangles.
  constexpr std::uint8_t kNoSide = 3;
  DualRows k;
  k.rows.resize(3 * std::size_t{faces});
  HugeVector<std::uint8_t> matched_side(faces, kNoSide);
  for (FaceId f = 0; f < faces; ++f) {
    Halfedge h = first[f];
    for (std::uint8_t side = 0; side < 3; ++side, h = tri.next(h)) {
      k.rows[3 * std::size_t{f} + side] = tri.face_[Triangulation::twin(h)];
      if (!(expansion.edge_state[Triangulation::edge(h)] & kMatched)) continue;
      if (matched_side[f] != kNoSide) {
        throw std::logic_error("lrs expansion: two edges of M pair face " + std::to_string(f));
      }
      matched_side[f] = side;
    }
  }
  tri.face_ = HugeVector<FaceId>();
  expansion.edge_state = HugeVector<std::uint8_t>();

  k.triangles.resize(faces);
  for (FaceId f = 0; f < faces; ++f) {
    const Halfedge h = first[f], n = tri.next(h);
    k.triangles[f] = {tri.origin(h), tri.origin(n), tri.origin(tri.next(n))};
  }
  tri = Triangulation();
  first = HugeVector<Halfedge>();

  k.partner.resize(faces);
  for (FaceId f = 0; f < faces; ++f) {
    const std::uint8_t side = matched_side[f];
    k.partner[f] = side == kNoSide ? kNoNode : k.rows[3 * std::size_t{f} + side];
    k.unpaired += side == kNoSide;
  }
  return k;
}
}  // namespace petersen::lrs
