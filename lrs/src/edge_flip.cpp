#include "petersen/lrs/edge_flip.hpp"

namespace petersen::lrs {

bool is_flippable(const Triangulation& tri, Halfedge h) {
  const Halfedge g = Triangulation::twin(h);
  const VertexId c = tri.apex(h), d = tri.apex(g);
  if (c == d || tri.degree(tri.origin(h)) <= 3 || tri.degree(tri.origin(g)) <= 3) return false;
  Halfedge k = tri.out(c);
  do {
    if (tri.destination(k) == d) return false;
    k = tri.rotate(k);
  } while (k != tri.out(c));
  return true;
}

void flip(Triangulation& tri, Halfedge h) {
  auto& next = tri.next_;
  const Halfedge g = Triangulation::twin(h);
  const Halfedge hn = next[h], hp = next[hn];  // b→c, c→a
  const Halfedge gn = next[g], gp = next[gn];  // a→d, d→b
  const VertexId a = tri.origin_[h], b = tri.origin_[g];
  const VertexId c = tri.origin_[hp], d = tri.origin_[gp];
  const FaceId f = tri.face_[h], f2 = tri.face_[g];
  // Face f becomes [c, a, d] = c→a, a→d, d→c; face f2 becomes [d, b, c] = d→b, b→c, c→d.
  next[h] = hp;
  next[hp] = gn;
  next[gn] = h;
  next[g] = gp;
  next[gp] = hn;
  next[hn] = g;
  tri.face_[gn] = f;
  tri.face_[hn] = f2;
  tri.origin_[h] = d;
  tri.origin_[g] = c;
  if (tri.out_[a] == h) tri.out_[a] = gn;
  if (tri.out_[b] == g) tri.out_[b] = hn;
  --tri.degree_[a];
  --tri.degree_[b];
  ++tri.degree_[c];
  ++tri.degree_[d];
}

}  // namespace petersen::lrs
