#include "petersen/lrs/contraction_step.hpp"

namespace petersen::lrs {
namespace {

// How many neighbours of w are marked (the marks hold the neighbours of the processed vertex).
std::uint32_t marked_neighbours(const Triangulation& tri, VertexId w, const VertexMarks& marks) {
  std::uint32_t count = 0;
  const Halfedge first = tri.out(w);
  Halfedge g = first;
  do {
    count += marks.marked(tri.destination(g));
    g = tri.rotate(g);
  } while (g != first);
  return count;
}

}  // namespace

ContractionResult contract_to_irreducible(Triangulation& tri) {
  ContractionResult result;
  result.stack.reserve(tri.live_vertices());
  VertexMarks neighbours(tri.vertex_capacity());
  for (VertexId u = 0; u < tri.vertex_capacity(); ++u) {
    if (!tri.vertex_alive(u)) continue;  // contracted into an earlier vertex, or unreferenced
    result.processed.push_back(u);
    neighbours.clear();
    Halfedge g = tri.out(u);
    do {
      neighbours.mark(tri.destination(g));
      g = tri.rotate(g);
    } while (g != tri.out(u));
    // Walk round u; u is trapped once degree(u) edges in a row fail the link condition.
    std::uint32_t fails = 0;
    while (fails < tri.degree(u)) {
      const VertexId w = tri.destination(g);
      // Link condition with N(u) marked: the two apexes are the only common neighbours. The
      // tetrahedron has none contractible (Proposition 3.1).
      if (tri.live_vertices() > 4 && marked_neighbours(tri, w, neighbours) == 2) {
        Halfedge k = tri.out(w);
        do {
          if (tri.destination(k) != u) neighbours.mark(tri.destination(k));
          k = tri.rotate(k);
        } while (k != tri.out(w));
        neighbours.unmark(w);
        const Halfedge next_at_u = tri.next(Triangulation::twin(g));  // u→y survives
        result.stack.push_back(contract(tri, g));
        g = next_at_u;
        fails = 0;
      } else {
        ++fails;
        g = tri.rotate(g);
      }
    }
  }
  return result;
}

}  // namespace petersen::lrs
