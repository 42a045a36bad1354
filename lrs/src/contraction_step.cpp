#include "contraction_step.hpp"
namespace petersen::lrs {
namespace {

// Per-vertex flags: processed, and neighbour of the vertex being processed. One byte holds both,
// so the link test's walk reads one array a quarter the size of VertexMarks' stamps: that walk is
// most of the contraction step's time, stalled on these random reads and the star's halfedges.
enum VertexFlag : std::uint8_t { kProcessed = 1, kNeighbour = 2 };

// How many neighbours of w = origin(first) are neighbours of the processed vertex, counted up to
// 3: a third already fails the link condition, so the walk round w stops there. It starts at
// `first`, whose cache line the caller just read, rather than at out(w), a random read.
std::uint32_t marked_neighbours(const Triangulation& tri, Halfedge first,
                                const std::pmr::vector<std::uint8_t>& flags) {
  std::uint32_t count = 0;
  Halfedge g = first;
  do {
    count += (flags[tri.destination(g)] & kNeighbour) != 0;
    g = tri.rotate_cw(g);
  } while (g != first && count < 3);
  return count;
}

}  // namespace

ContractionResult contract_to_irreducible(Triangulation& tri) {
  ContractionResult result;
  result.stack.reserve(tri.live_vertices());
  result.processed.reserve(tri.live_vertices());
  std::pmr::vector<std::uint8_t> flags(tri.vertex_capacity(), 0);
  // Edges [u, w] whose contractibility may have changed, last in first out, pushed so that they
  // come out in counter-clockwise order round u: u sweeps round and round, as a walk round its
  // rotation would, which keeps the expansion's flips few.
  std::vector<EdgeId> untested;
  for (VertexId u = 0; u < tri.vertex_capacity(); ++u) {
    if (!tri.vertex_alive(u)) continue;  // contracted into an earlier vertex, or unreferenced
    flags[u] |= kProcessed;
    result.processed.push_back(u);
    untested.clear();
    // Pushed clockwise from out(u)'s predecessor, out(u) last, so they pop counter-clockwise.
    Halfedge g = tri.out(u);
    do {
      g = tri.rotate_cw(g);
      flags[tri.destination(g)] |= kNeighbour;
      untested.push_back(Triangulation::edge(g));
    } while (g != tri.out(u));
    // Process u until it is trapped (Definition 3.1). Contracting [u, v] changes the common
    // neighbours of u and w, or the apexes of [u, w], only when w is an apex x or y of [u, v]; any
    // other edge [u, w] can only gain common neighbours. So an edge found non-contractible is
    // tested again only after its end became an apex, and u is trapped when none is left.
    while (!untested.empty()) {
      const EdgeId e = untested.back();
      untested.pop_back();
      if (!tri.edge_alive(e)) continue;
      g = tri.origin(2 * e) == u ? 2 * e : 2 * e + 1;
      const VertexId w = tri.destination(g);
      if (flags[w] & kProcessed) continue;  // trapped, and stays trapped (Lemma 3.1)
      // Link condition with N(u) marked: the two apexes are the only common neighbours; the
      // tetrahedron has no contractible edge (Proposition 3.1).
      if (tri.live_vertices() <= 4 || marked_neighbours(tri, Triangulation::twin(g), flags) != 2)
        continue;
      // w's edges from [w, y] round to [w, x] become u's; all but those two are new to u.
      const Halfedge t1 = tri.next(Triangulation::twin(g));  // u→y
      const Halfedge wx = tri.next(g);                       // w→x
      // Walked clockwise from [w, x] to [w, y], so that they pop counter-clockwise round u.
      untested.push_back(Triangulation::edge(tri.prev(g)));  // [u, x], an apex: test again
      const Halfedge wy = Triangulation::twin(tri.next(t1));
      for (Halfedge k = tri.rotate_cw(wx); k != wy; k = tri.rotate_cw(k)) {
        flags[tri.destination(k)] |= kNeighbour;
        untested.push_back(Triangulation::edge(k));
      }
      flags[w] &= static_cast<std::uint8_t>(~kNeighbour);
      untested.push_back(Triangulation::edge(t1));  // [u, y], an apex: test again, first
      result.stack.push_back(contract(tri, g));
    }
    // The flagged vertices are exactly u's neighbours now (a contraction flags the removed
    // vertex's neighbours but the two apexes, which are flagged already): clear them for the next.
    g = tri.out(u);
    do {
      flags[tri.destination(g)] &= static_cast<std::uint8_t>(~kNeighbour);
      g = tri.rotate_cw(g);
    } while (g != tri.out(u));
  }
  return result;
}

}  // namespace petersen::lrs
