#include "edge_flip.hpp"

namespace petersen::lrs {

bool is_flippable(const Triangulation& tri, Halfedge h) {
  const Halfedge g = Triangulation::twin(h);
  const VertexId c = tri.apex(h), d = tri.apex(g);
  if (c == d || tri.degree(tri.origin(h)) <= 3 || tri.degree(tri.origin(g)) <= 3) return false;
  Halfedge k = tri.out(c);
  do {
    if (tri.destination(k) == d) return false;
    k = tri.rotate_cw(k);
  } while (k != tri.out(c));
  return true;
}

void flip(Triangulation& tri, Halfedge h) {
  auto& links = tri.links_;
  const Halfedge g = Triangulation::twin(h);
  const Halfedge hn = links[h].next, hp = links[hn].next;  // b→c, c→a
  const Halfedge gn = links[g].next, gp = links[gn].next;  // a→d, d→b
  const VertexId a = links[h].origin, b = links[g].origin;
  const VertexId c = links[hp].origin, d = links[gp].origin;
  // h's face becomes [c, a, d] = c→a, a→d, d→c; g's face becomes [d, b, c] = d→b, b→c, c→d.
  links[h].next = hp;
  links[hp].next = gn;
  links[gn].next = h;
  links[g].next = gp;
  links[gp].next = hn;
  links[hn].next = g;
  links[h].origin = d;
  links[g].origin = c;
  if (tri.out_[a] == h) tri.out_[a] = gn;
  if (tri.out_[b] == g) tri.out_[b] = hn;
  --tri.degree_[a];
  --tri.degree_[b];
  ++tri.degree_[c];
  ++tri.degree_[d];
}

}  // namespace petersen::lrs
