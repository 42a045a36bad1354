#pragma once
// The front door of LRS, the paper's new algorithm (§3.3–3.4): a closed triangle mesh to a quad
// mesh on the same vertices, by contraction to an irreducible triangulation, expansion with edge
// flips and pairing (Algorithms 3.1–3.4), then augmenting paths.
//
// Limitation (the paper's first, §5): the expansion flips edges, so the quads pair the triangles
// of K — the input with some edges flipped — not of the input itself. The quad mesh has the
// input's vertices and surface, but some of its edges (the flipped ones) are not input edges, and
// its quads need not be unions of input triangles. Use sg/ps/ds when the pairing must be of the
// input's own triangles.

#include <cstdint>

#include "petersen/mesh/mesh.hpp"
#include "petersen/graph/cubic_graph.hpp"
#include "petersen/matching/matching.hpp"
#include "petersen/matching/perfect_matching.hpp"

namespace petersen {

struct LrsOptions {
  /// How the ℓ faces left unpaired by the expansion are paired (Tarjan's augmenting paths).
  Augment augment = Augment::local;
};

/// Statistics of one run, in the paper's terms (Table 4.3 columns and §5's flip count).
struct LrsStats {
  double setup_seconds = 0;        ///< surface check and the halfedge triangulation
  double contraction_seconds = 0;  ///< contraction step, down to T′
  double expansion_seconds = 0;    ///< expansion step, plus K's dual graph and M on it
  double augment_seconds = 0;      ///< augmenting paths, ℓ/2 of them
  double quads_seconds = 0;        ///< quads from K and the perfect matching
  double total_seconds = 0;        ///< everything, setup to quads
  std::uint32_t genus = 0;
  std::uint32_t vertices = 0, edges = 0, faces = 0;  ///< of the input (and of K)
  std::uint32_t irreducible_vertices = 0;  ///< |T′|: 4 at genus 0, at most 26g − 4 otherwise
  std::uint32_t irreducible_faces = 0;
  std::uint64_t contractions = 0;
  std::uint32_t unpaired_after_expansion = 0;  ///< ℓ: T′'s faces, 4 at genus 0, ≤ 56g − 12
  std::uint32_t flipped_edges = 0;             ///< edges of K that are not input edges
  std::uint64_t unflips = 0;                   ///< Algorithm 3.2's unflips
  std::uint64_t expansion_cases[4] = {0, 0, 0, 0};  ///< Alg. 3.1 line 7, Alg. 3.2, 3.3, 3.4
  std::uint64_t augmenting_paths = 0;

  /// The paper's pairing time (e): contraction + expansion + augmentation.
  double matching_seconds() const {
    return contraction_seconds + expansion_seconds + augment_seconds;
  }
  double flipped_percent() const { return edges == 0 ? 0.0 : 100.0 * flipped_edges / edges; }
};

struct LrsResult {
  TriangleMesh flipped_mesh;  ///< K: the input's positions, triangle f = K's face f
  CubicGraph dual;            ///< K's dual: node f = triangle f of flipped_mesh
  Matching matching;          ///< a perfect matching of `dual`
  QuadMesh quads;             ///< one quad per matched pair of K's triangles
  LrsStats stats;
};

/// Converts a closed, connected, orientable manifold triangle mesh into a quad mesh with the same
/// vertex set (see the limitation above). Throws MeshError naming the element (triangle, edge or
/// vertex) when the input is not such a surface: boundary, non-manifold or inconsistently oriented
/// edges, pinched vertices, several components. Contraction and expansion take O(n·d) for maximum
/// input degree d (measured linear, bench/lrs_speed), the augmentation of the ℓ free faces O(ℓ·n)
/// at worst; the surface check O(n log d); O(n) memory; iterative throughout.
LrsResult quadrangulate_lrs(const TriangleMesh& mesh, const LrsOptions& options = {});

}  // namespace petersen
