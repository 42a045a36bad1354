#include "reduction/engine.hpp"

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "petersen/graph/memory.hpp"
#include "petersen/graph/stopwatch.hpp"
#include "reduction/brute_force.hpp"

namespace petersen::reduction {

namespace {

// The next step for forbidden edge f: reduce a simple edge e = {u, v} adjacent to f (Biedl et
// al.), with a1 = f so that f travels to n13. A simple edge exists at an end of f unless both
// ends of f carry a digon; then the digon at f's first end is contracted (its edge e is matched
// on lifting, f travels to the edge joining the digon's two outer neighbours).
Step next_step(const ReductionGraph& g, EdgeId f) {
  for (int side = 0; side < 2; ++side) {
    const NodeId u = g.end(f, side);
    EdgeId o[2];
    for (int k = 0, j = 0; k < 3; ++k)
      if (g.slot(u, k) != f) o[j++] = g.slot(u, k);
    const NodeId fx = g.other_end(f, u);
    for (int k = 0; k < 2; ++k) {
      const NodeId v = g.other_end(o[k], u);
      if (v == fx || v == g.other_end(o[1 - k], u)) continue;  // o[k] is not a simple edge
      EdgeId b[2];
      for (int s = 0, j = 0; s < 3; ++s)
        if (g.slot(v, s) != o[k]) b[j++] = g.slot(v, s);
      return {u, v, o[k], f, o[1 - k], b[0], b[1], kNoEdge, kNoEdge};
    }
  }
  const NodeId u = g.end(f, 0);
  EdgeId o[2];
  for (int k = 0, j = 0; k < 3; ++k)
    if (g.slot(u, k) != f) o[j++] = g.slot(u, k);
  const NodeId v = g.other_end(o[0], u);
  EdgeId third = kNoEdge;
  for (int s = 0; s < 3; ++s)
    if (g.slot(v, s) != o[0] && g.slot(v, s) != o[1]) third = g.slot(v, s);
  return {u, v, o[0], f, o[1], third, kNoEdge, kNoEdge, kNoEdge};
}

}  // namespace

Matching reduce_and_lift(ReductionGraph g, std::span<const std::uint32_t> component,
                         std::uint32_t components, EdgeId forbidden, Chooser& chooser,
                         bool check_each_step, ReductionStats& stats) {
  const std::uint32_t n = g.node_count();
  Stopwatch reduce_clock;
  // Each component's size and its forbidden edge (the caller's, or an arbitrary one).
  std::vector<std::uint32_t> size(components, 0);
  std::vector<EdgeId> first(components, kNoEdge);
  for (NodeId v = 0; v < n; ++v) {
    ++size[component[v]];
    if (first[component[v]] == kNoEdge) first[component[v]] = g.slot(v, 0);
  }
  if (forbidden != kNoEdge) first[component[g.end(forbidden, 0)]] = forbidden;

  std::pmr::vector<Step> steps;
  steps.reserve(n / 2);
  std::pmr::vector<EdgeId> mate(n, kNoEdge);
  for (std::uint32_t c = 0; c < components; ++c) {
    EdgeId f = first[c];
    for (std::uint32_t remaining = size[c]; remaining > 2; remaining -= 2) {
      Step step = next_step(g, f);
      if (step.b4 != kNoEdge) {
        const EdgeId gone[5] = {step.e, step.a1, step.a2, step.b3, step.b4};
        chooser.remove(g, gone);
        if (!chooser.choose_h1(g, step)) std::swap(step.b3, step.b4);
        g.apply(step);
        const EdgeId added[2] = {step.n13, step.n24};
        chooser.add(g, added);
        ++stats.reductions;
      } else {
        const EdgeId gone[4] = {step.e, step.a1, step.a2, step.b3};
        chooser.remove(g, gone);
        g.apply(step);
        chooser.add(g, std::span<const EdgeId>(&step.n13, 1));
        ++stats.digon_reductions;
      }
      f = step.n13;
      steps.push_back(step);
      if (check_each_step) {
        if (!is_connected_bridgeless(g, components))
          throw std::logic_error("reduction " + std::to_string(steps.size()) + " at edge " +
                                 std::to_string(step.e) + " left a bridge or split a component");
        chooser.verify(g);
      }
    }
    // A theta graph is left (paper Appendix A): match one of its edges other than f.
    const NodeId p = g.end(f, 0);
    const EdgeId m = g.slot(p, 0) != f ? g.slot(p, 0) : g.slot(p, 1);
    mate[p] = mate[g.other_end(m, p)] = m;
  }
  stats.replacement_searches = chooser.replacement_searches();
  stats.cover_swaps = chooser.cover_swaps();
  stats.reduce_seconds = reduce_clock.seconds();

  // Appendix A, cases (i)-(iii); n13 carries the forbidden edge, so case (iv) never arises.
  Stopwatch lift_clock;
  for (auto s = steps.rbegin(); s != steps.rend(); ++s) {
    const NodeId x1 = g.other_end(s->a1, s->u);
    if (mate[x1] == s->n13) {
      const NodeId x3 = g.other_end(s->b3, s->v);
      mate[x1] = mate[s->u] = s->a1;
      mate[x3] = mate[s->v] = s->b3;
      ++stats.lift_cases[1];
    } else if (s->n24 != kNoEdge && mate[g.other_end(s->a2, s->u)] == s->n24) {
      const NodeId x2 = g.other_end(s->a2, s->u), x4 = g.other_end(s->b4, s->v);
      mate[x2] = mate[s->u] = s->a2;
      mate[x4] = mate[s->v] = s->b4;
      ++stats.lift_cases[2];
    } else {
      mate[s->u] = mate[s->v] = s->e;
      ++stats.lift_cases[0];
    }
  }
  stats.lift_seconds = lift_clock.seconds();
  Matching matching;
  matching.mate_edge = std::move(mate);
  return matching;
}

}  // namespace petersen::reduction
