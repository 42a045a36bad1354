#include "petersen/lrs/lrs.hpp"

#include <chrono>

#include "petersen/dualize/quads.hpp"
#include "petersen/lrs/contraction_step.hpp"
#include "petersen/lrs/expansion_step.hpp"
#include "petersen/matching/augment.hpp"

namespace petersen {

LrsResult quadrangulate_lrs(const TriangleMesh& mesh, const LrsOptions& options) {
  using Clock = std::chrono::steady_clock;
  const auto since = [](Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
  };
  LrsResult result;
  LrsStats& stats = result.stats;
  const auto begin = Clock::now();
  auto start = begin;

  // The triangulation and the contraction's records die before the augmentation, whose search
  // state then reuses their memory (huge_pages.hpp: fresh pages are slow on virtual machines).
  {
    lrs::Triangulation tri =
        lrs::Triangulation::from_mesh(mesh, lrs::Triangulation::Numbering::spatial);
    stats.genus = tri.genus();
    stats.vertices = tri.live_vertices();
    stats.edges = tri.live_edges();
    stats.faces = tri.live_faces();
    stats.setup_seconds = since(begin);

    start = Clock::now();
    const lrs::ContractionResult contraction = lrs::contract_to_irreducible(tri);
    stats.contraction_seconds = since(start);
    stats.contractions = contraction.stack.size();
    stats.irreducible_vertices = tri.live_vertices();
    stats.irreducible_faces = tri.live_faces();

    start = Clock::now();
    const lrs::ExpansionResult expansion = lrs::expand_and_match(tri, contraction.stack);
    stats.expansion_seconds = since(start);
    // K as a mesh first, counted with the quads, so that K's dual can free the triangulation's
    // vertex and edge arrays before it is made.
    start = Clock::now();
    result.flipped_mesh = tri.to_mesh(mesh.positions);
    stats.quads_seconds = since(start);
    start = Clock::now();
    result.dual = std::move(tri).dual_graph();
    result.matching = lrs::matching_of(result.dual, expansion);
    stats.unpaired_after_expansion = result.matching.unmatched_count();
    stats.flipped_edges = expansion.flipped_edges;
    stats.unflips = expansion.unflips;
    for (int c = 0; c < 4; ++c) stats.expansion_cases[c] = expansion.cases[c];
  }
  stats.expansion_seconds += since(start);

  start = Clock::now();
  stats.augmenting_paths =
      augment_matching(result.dual, result.matching, options.augment).augmenting_paths;
  stats.augment_seconds = since(start);

  start = Clock::now();
  result.quads = quads_from_matching(result.flipped_mesh, result.dual, result.matching);
  stats.quads_seconds += since(start);
  stats.total_seconds = since(begin);
  return result;
}

}  // namespace petersen
