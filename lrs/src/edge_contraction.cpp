#include "petersen/lrs/edge_contraction.hpp"

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
    g = tri.rotate(g);
  } while (g != tri.out(u));
  // The two apexes are always common neighbours; a third closes a non-facial 3-cycle.
  std::uint32_t common = 0;
  g = tri.out(v);
  do {
    common += marks.marked(tri.destination(g));
    g = tri.rotate(g);
  } while (g != tri.out(v));
  return common == 2;
}

ContractionRecord contract(Triangulation& tri, Halfedge h) {
  auto& next = tri.next_;
  auto& origin = tri.origin_;
  const Halfedge h1 = next[h], h2 = next[h1];  // face [u, v, x]: u→v, v→x, x→u
  const Halfedge t = Triangulation::twin(h);
  const Halfedge t1 = next[t], t2 = next[t1];  // face [v, u, y]: v→u, u→y, y→v
  const VertexId u = origin[h], v = origin[h1], x = origin[h2], y = origin[t2];
  const Halfedge a = Triangulation::twin(h1);  // x→v, dies with [v, x]
  const Halfedge d = Triangulation::twin(t2);  // v→y, dies with [v, y]

  // v's outgoing halfedges outside the two faces, from v→y round to the one before v→x, go to u.
  std::uint32_t moved = 0;
  for (Halfedge g = d; g != h1; g = tri.rotate(g), ++moved) origin[g] = u;
  // x→u takes the place of x→v, u→y the place of v→y (order matters when v has degree 3).
  Halfedge p = next[next[a]];
  next[p] = h2;
  next[h2] = next[a];
  tri.face_[h2] = tri.face_[a];
  p = next[next[d]];
  next[p] = t1;
  next[t1] = next[d];
  tri.face_[t1] = tri.face_[d];

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
  auto& next = tri.next_;
  auto& origin = tri.origin_;
  // Dead halfedges kept their last values: h→h1→h2 and t→t1 are still linked, origins intact.
  const Halfedge h = record.h, t2 = record.t2;
  const Halfedge h1 = next[h], h2 = next[h1];
  const Halfedge t = Triangulation::twin(h);
  const Halfedge t1 = next[t];
  const VertexId u = origin[h], v = origin[h1], x = origin[h2], y = origin[t2];
  const Halfedge a = Triangulation::twin(h1);
  const Halfedge d = Triangulation::twin(t2);

  // u's outgoing halfedges strictly between u→y and u→x (v's side) go to v.
  const Halfedge b = Triangulation::twin(h2);  // u→x
  std::uint32_t moved = 0;
  for (Halfedge g = tri.rotate(t1); g != b; g = tri.rotate(g), ++moved) origin[g] = v;
  // v→y takes the place of u→y, then x→v the place of x→u (the reverse of contract's order).
  Halfedge p = next[next[t1]];
  next[p] = d;
  next[d] = next[t1];
  tri.face_[d] = tri.face_[t1];
  origin[d] = v;
  p = next[next[h2]];
  next[p] = a;
  next[a] = next[h2];
  tri.face_[a] = tri.face_[h2];
  origin[a] = x;

  const FaceId f0 = tri.face_[h], f1 = tri.face_[t];
  next[h] = h1;
  next[h1] = h2;
  next[h2] = h;
  tri.face_[h2] = f0;
  next[t] = t1;
  next[t1] = t2;
  next[t2] = t;
  tri.face_[t1] = f1;
  origin[h] = u;
  origin[h1] = v;
  origin[t] = v;
  origin[t1] = u;
  origin[t2] = y;

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
