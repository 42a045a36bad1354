#include "expansion_step.hpp"

#include <stdexcept>
#include <string>

#include "edge_flip.hpp"

namespace petersen::lrs {
namespace {

[[noreturn]] void invariant_broken(const char* what, VertexId v) {
  throw std::logic_error(std::string("lrs expansion: ") + what + " at vertex " + std::to_string(v));
}

}  // namespace

ExpansionResult expand_and_match(Triangulation& tri, std::span<const ContractionRecord> stack) {
  ExpansionResult result;
  auto& state = result.edge_state;
  state.assign(tri.edge_capacity(), 0);
  const auto edge = [](Halfedge h) { return Triangulation::edge(h); };
  const auto insert = [&](Halfedge h) {
    state[edge(h)] |= kMatched;
    ++result.matched_edges;
  };
  const auto flip_flagged = [&](Halfedge h) {
    flip(tri, h);
    state[edge(h)] ^= kFlipped;
  };

  // Splits are undone in stack order, so the halfedges of later splits are known ahead: ask for
  // them in three stages, each reading only what the previous stage's hints brought in (the
  // records' halfedges, then their successors, then the second successor and the vertices).
  constexpr std::size_t kAhead = 8;
  const auto ahead = [&](std::size_t k) -> const ContractionRecord* {
    return k < stack.size() ? &stack[stack.size() - 1 - k] : nullptr;
  };
  for (std::size_t i = 0; i < stack.size(); ++i) {
    if (const ContractionRecord* far = ahead(i + 3 * kAhead)) {
      tri.prefetch(far->h);
      tri.prefetch(far->t2);
    }
    if (const ContractionRecord* mid = ahead(i + 2 * kAhead)) {
      tri.prefetch(tri.next(mid->h));
      tri.prefetch(tri.next(Triangulation::twin(mid->h)));
    }
    if (const ContractionRecord* near = ahead(i + kAhead)) {
      const Halfedge h2 = tri.next(tri.next(near->h));
      tri.prefetch(h2);
      __builtin_prefetch(&state[edge(h2)]);
      tri.prefetch_vertex(tri.origin(near->h));
      tri.prefetch_vertex(tri.origin(h2));
      tri.prefetch_vertex(tri.origin(near->t2));
    }
    const ContractionRecord& record = *ahead(i);
    // Halfedges of the faces the split revives: [u, v, x] = h, h1, h2 and [v, u, y] = t, t1, t2.
    const Halfedge h = record.h, t2 = record.t2;
    const Halfedge h1 = tri.next(h), h2 = tri.next(h1);
    const Halfedge t1 = tri.next(Triangulation::twin(h));
    // Split edges [u, x] = edge(h2) and [u, y] = edge(t1) are never safe, so never flipped.
    if ((state[edge(h2)] | state[edge(t1)]) & kFlipped) {
      invariant_broken("a split edge is flipped", tri.origin(h));
    }
    const bool ux = (state[edge(h2)] & kMatched) != 0;
    const bool uy = (state[edge(t1)] & kMatched) != 0;
    split(tri, record);  // Algorithm 3.1 line 5: EXPAND
    const VertexId v = tri.origin(h1);
    const Halfedge d = Triangulation::twin(t2);  // v→y; v's edges run h1, t, d, ... round v

    if (!ux && !uy) {
      // Algorithm 3.1 line 7: [u, v] pairs the two new faces.
      ++result.cases[0];
      insert(h);
    } else if (record.removed_degree == 3) {
      // Algorithm 3.2 (degree 3 in T_ij). If K holds the flip of [x, y], the split handed v that
      // flipped edge, [v, z], between [v, y] and [v, x]: unflip it so that v has degree 3 in K.
      ++result.cases[1];
      if (tri.degree(v) != 3) {
        const Halfedge vz = tri.rotate(d);
        if (tri.degree(v) != 4 || !(state[edge(vz)] & kFlipped)) {
          invariant_broken("degree-3 split with more than the flip of [x, y] on its side", v);
        }
        flip_flagged(vz);
        ++result.unflips;
      }
      if (ux && uy) {
        insert(tri.next(d));  // [x, y], in the face [v, y, x]
      } else if (ux) {
        insert(t2);  // [v, y]
      } else {
        insert(h1);  // [v, x]
      }
    } else if (record.removed_degree == 4 && tri.degree(v) == 4) {
      // Algorithm 3.3 (degree 4 in T_ij, and [x, z], [y, z] not flipped: otherwise K would give v
      // the flip of those too and a degree above 4).
      ++result.cases[2];
      if (ux && uy) {
        insert(tri.rotate(d));  // [v, z]
      } else if (ux) {
        flip_flagged(h1);  // [v, x]
        insert(h);
      } else {
        flip_flagged(t2);  // [v, y]
        insert(h);
      }
    } else {
      // Algorithm 3.4 (degree above 4 in T_ij, or in K).
      ++result.cases[3];
      if (ux) flip_flagged(h1);
      if (uy) flip_flagged(t2);
      insert(h);
    }
  }
  for (const std::uint8_t s : state) result.flipped_edges += (s & kFlipped) != 0;
  return result;
}

}  // namespace petersen::lrs
