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

  // Each face's smallest halfedge, the first met in id order: where its rows and corners start.
  HugeVector<Halfedge> first(faces, kNoHalfedge);
  for (Halfedge h = 0; h < tri.links_.size(); ++h) {
    Halfedge& s = first[tri.face_[h]];
    if (s == kNoHalfedge) s = h;
  }
  DualRows k;
  k.rows.resize(3 * std::size_t{faces});
  k.partner.assign(faces, kNoNode);
  for (FaceId f = 0; f < faces; ++f) {
    Halfedge h = first[f];
    for (std::size_t side = 0; side < 3; ++side, h = tri.next(h)) {
      const NodeId across = tri.face_[Triangulation::twin(h)];
      k.rows[3 * std::size_t{f} + side] = across;
      if (!(expansion.edge_state[Triangulation::edge(h)] & kMatched)) continue;
      if (k.partner[f] != kNoNode) {
        throw std::logic_error("lrs expansion: two edges of M pair face " + std::to_string(f));
      }
      k.partner[f] = across;
    }
    k.unpaired += k.partner[f] == kNoNode;
  }
  tri.face_ = HugeVector<FaceId>();
  expansion.edge_state = HugeVector<std::uint8_t>();

  k.triangles.resize(faces);
  for (FaceId f = 0; f < faces; ++f) {
    const Halfedge h = first[f], n = tri.next(h);
    k.triangles[f] = {tri.input_vertex(tri.origin(h)), tri.input_vertex(tri.origin(n)),
                      tri.input_vertex(tri.origin(tri.next(n)))};
  }
  tri = Triangulation();
  return k;
}

}  // namespace petersen::lrs
