#pragma once
// The contraction step of LRS (paper §3.3): edge contractions down to an irreducible
// triangulation T′, recorded on a stack for the expansion step.

#include <vector>

#include "edge_contraction.hpp"
#include "petersen/graph/memory.hpp"

namespace petersen::lrs {

struct ContractionResult {
  /// Every contraction in the order done; the expansion step undoes them from the back.
  std::pmr::vector<ContractionRecord> stack;
  /// The vertices of T′ in the order they were processed (the paper's u_m, ..., u_1).
  std::pmr::vector<VertexId> processed;
};

/// Processes the live vertices in id order: contracts contractible edges incident on the vertex,
/// which survives, until it is trapped (Definition 3.1); trapped vertices stay trapped (Lemma
/// 3.1), so when every vertex is processed no edge is contractible and `tri` is irreducible: the
/// tetrahedron at genus 0 (Proposition 3.1), at most 26g − 4 vertices at genus g > 0 (Theorem
/// 3.1). The neighbours of the vertex being processed stay marked, so a link test costs the degree
/// of the other end (never a processed vertex: those are skipped) and a contraction the degree of
/// the removed vertex; an edge that failed the test is tested again only once its other end became
/// an apex of a later contraction (the only event that can make it contractible). So each test is
/// paid by an initial edge, a gained edge or an apex: O(V·d) for maximum input degree d, linear in
/// practice (bench/lrs_speed). Iterative, O(V) memory.
ContractionResult contract_to_irreducible(Triangulation& tri);

}  // namespace petersen::lrs
