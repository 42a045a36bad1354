#include "edge_contraction.hpp"

namespace petersen::lrs {

bool is_contractible(const Triangulation& tri, Halfedge h, VertexMarks& marks) {
  // Proposition 3.1: no edge of the tetrahedron is contractible.
  if (tri.live_vertices() <= 4) return false;
  const VertexId u = tri.origin(h);
  const VertexId v = tri.destination(h);
  marks.clear();
  Halfedge g = tri.out(u);
  do {
    marks.mark(tri.destination(g));
    g = tri.rotate_cw(g);
  } while (g != tri.out(u));
  // The two apexes are always common neighbours; a third closes a non-facial 3-cycle.
  std::uint32_t common = 0;
  g = tri.out(v);
  do {
    common += marks.marked(tri.destination(g));
    g = tri.rotate_cw(g);
  } while (g != tri.out(v));
  return common == 2;
}

ContractionRecord contract(Triangulation& tri, Halfedge h) {
  auto& links = tri.links_;
  const Halfedge h1 = links[h].next, h2 = links[h1].next;  // face [u, v, x]: u→v, v→x, x→u
  const Halfedge t = Triangulation::twin(h);
  const Halfedge t1 = links[t].next, t2 = links[t1].next;  // face [v, u, y]: v→u, u→y, y→v
  const VertexId u = links[h].origin, v = links[h1].origin, x = links[h2].origin,
                 y = links[t2].origin;
  const Halfedge a = Triangulation::twin(h1);  // x→v, dies with [v, x]
  const Halfedge d = Triangulation::twin(t2);  // v→y, dies with [v, y]

  // v's outgoing halfedges outside the two faces, from v→y round to the one before v→x, go to u
  // (walked clockwise from v→x, ending at v→u).
  std::uint32_t moved = 0;
  for (Halfedge g = tri.rotate_cw(h1); g != t; g = tri.rotate_cw(g), ++moved) links[g].origin = u;
  // x→u takes the place of x→v, u→y the place of v→y (order matters when v has degree 3).
  Halfedge p = links[links[a].next].next;
  links[p].next = h2;
  links[h2].next = links[a].next;
  p = links[links[d].next].next;
  links[p].next = t1;
  links[t1].next = links[d].next;

  const std::uint32_t removed_degree = moved + 2;
  tri.out_[u] = t1;
  tri.out_[x] = h2;
  tri.out_[y] = Triangulation::twin(t1);
  tri.out_[v] = kNoHalfedge;
  tri.degree_[u] += removed_degree - 4;
  --tri.degree_[x];
  --tri.degree_[y];
  tri.edge_alive_[Triangulation::edge(h)] = 0;
  tri.edge_alive_[Triangulation::edge(h1)] = 0;
  tri.edge_alive_[Triangulation::edge(t2)] = 0;
  --tri.live_vertices_;
  tri.live_edges_ -= 3;
  tri.live_faces_ -= 2;
  return {h, t2, removed_degree};
}

void split(Triangulation& tri, const ContractionRecord& record) {
  auto& links = tri.links_;
  // Dead halfedges kept their last values: h→h1→h2 and t→t1 are still linked, origins intact.
  const Halfedge h = record.h, t2 = record.t2;
  const Halfedge h1 = links[h].next, h2 = links[h1].next;
  const Halfedge t = Triangulation::twin(h);
  const Halfedge t1 = links[t].next;
  const VertexId u = links[h].origin, v = links[h1].origin, x = links[h2].origin,
                 y = links[t2].origin;
  const Halfedge a = Triangulation::twin(h1);
  const Halfedge d = Triangulation::twin(t2);

  // u's outgoing halfedges strictly between u→y and u→x (v's side) go to v (walked clockwise).
  const Halfedge b = Triangulation::twin(h2);  // u→x
  std::uint32_t moved = 0;
  for (Halfedge g = tri.rotate_cw(b); g != t1; g = tri.rotate_cw(g), ++moved) links[g].origin = v;
  // v→y takes the place of u→y, then x→v the place of x→u (the reverse of contract's order).
  Halfedge p = links[links[t1].next].next;
  links[p].next = d;
  links[d].next = links[t1].next;
  links[d].origin = v;
  p = links[links[h2].next].next;
  links[p].next = a;
  links[a].next = links[h2].next;
  links[a].origin = x;

  links[h].next = h1;
  links[h1].next = h2;
  links[h2].next = h;
  links[t].next = t1;
  links[t1].next = t2;
  links[t2].next = t;
  links[h].origin = u;
  links[h1].origin = v;
  links[t].origin = v;
  links[t1].origin = u;
  links[t2].origin = y;

  tri.out_[u] = h;
  tri.out_[v] = h1;
  tri.degree_[v] = moved + 3;
  tri.degree_[u] = tri.degree_[u] + 1 - moved;
  ++tri.degree_[x];
  ++tri.degree_[y];
  tri.edge_alive_[Triangulation::edge(h)] = 1;
  tri.edge_alive_[Triangulation::edge(h1)] = 1;
  tri.edge_alive_[Triangulation::edge(t2)] = 1;
  ++tri.live_vertices_;
  tri.live_edges_ += 3;
  tri.live_faces_ += 2;
}

}  // namespace petersen::lrs
