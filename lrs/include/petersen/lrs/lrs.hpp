#pragma once
// LRS, the paper's new algorithm (§3.3–3.4): the triangles of one closed surface paired into quads
// on the same vertices, by contraction to an irreducible triangulation, expansion with edge flips
// and pairing (Algorithms 3.1–3.4), then augmenting paths.
//
// Limitation (the paper's first, §5): the expansion flips edges, so the quads pair the triangles
// of K — the input with some edges flipped — not of the input itself. The quads cover the input's
// surface on its vertices, but some of their edges (the flipped ones) are not input edges, and a
// quad need not be the union of two input triangles. Use sg/ps/ds when the pairing must be of the
// input's own triangles.

#include <array>
#include <cstdint>
#include <functional>
#include <span>

#include "petersen/graph/cubic_graph.hpp"
#include "petersen/graph/memory.hpp"
#include "petersen/matching/options.hpp"
#include "petersen/mesh/mesh.hpp"

namespace petersen {

struct LrsOptions {
  /// How the ℓ faces left unpaired by the expansion are paired (Tarjan's augmenting paths).
  Augment augment = Augment::local;
  /// Whether each quad names the input triangles behind it (LrsQuad::sources): a lookup of K's
  /// triangles among the input's by their vertices, after K is freed. Without, every source is
  /// kNoFace and the input's corners are not read once the triangulation is built.
  bool sources = true;
  /// Threads for the fan check of the dual input (two at most; 0: as many as the machine has).
  std::uint32_t threads = 1;
  /// Where the quads are allocated (the triangulation's scratch is on the default resource).
  std::pmr::memory_resource* memory = std::pmr::get_default_resource();
};

/// A closed triangle surface given by its dual's arrays rather than as a mesh: triangle t has
/// corners corners[3t], corners[3t + 1], corners[3t + 2] over `positions`; node_edges[3t + k] is
/// the edge across its corners k and k + 1, and edge e joins triangles edge_ends[2e] and
/// edge_ends[2e + 1] (a cubic PairableGraph with no inconsistent edge, or build_dual's graph). The
/// two arrays are taken over, so that the triangulation is made from them without a copy of the
/// mesh.
struct LrsDualInput {
  const Positions& positions;
  std::span<const VertexId> corners;
  std::pmr::vector<EdgeId> node_edges;
  std::pmr::vector<NodeId> edge_ends;
  /// Whether the caller has found the triangles connected (then not counted again).
  bool connected = false;
  /// Called, when given, as soon as `corners` is read no more, so that a caller done with them
  /// frees them there: once the triangulation's links are made without options.sources, once the
  /// sources are found with it. Once it is called, nothing is refused.
  std::function<void()> corners_read = {};
};

/// Statistics of one run, in the paper's terms (Table 4.3 columns and §5's flip count).
struct LrsStats {
  double setup_seconds = 0;        ///< surface check and the halfedge triangulation
  double contraction_seconds = 0;  ///< contraction step, down to T′
  double expansion_seconds = 0;    ///< expansion step, plus K's dual rows and M on them
  double augment_seconds = 0;      ///< augmenting paths, ℓ/2 of them
  double verify_seconds = 0;       ///< the perfect matching of K's dual verified
  double quads_seconds = 0;        ///< quads from K and the matching, then their sources
  double total_seconds = 0;        ///< everything, setup to sources
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
  std::uint64_t blossoms = 0;        ///< shrunk by the augmentation
  std::uint64_t nodes_labelled = 0;  ///< by the augmentation's searches

  /// The paper's pairing time (e): contraction + expansion + augmentation.
  double matching_seconds() const {
    return contraction_seconds + expansion_seconds + augment_seconds;
  }
  double flipped_percent() const { return edges == 0 ? 0.0 : 100.0 * flipped_edges / edges; }
};

/// A quad of two triangles of K, as quad_of (petersen/dualize/quad_of.hpp) makes it: the first
/// triangle's orientation, the second's corner off the shared side second.
struct LrsQuad {
  std::array<VertexId, 4> corners;
  /// The input triangles (face ids) behind the quad's two triangles, kNoFace for one the
  /// flips made (or every one without LrsOptions::sources). When both are set, the quad is exactly
  /// those two input triangles: they are partners.
  std::array<FaceId, 2> sources;
};

struct LrsPairing {
  /// One quad per pair of K's triangles, F/2 of them, in order of the pair's first triangle.
  std::pmr::vector<LrsQuad> quads;
  LrsStats stats = {};
};

/// Pairs the triangles of one closed, connected, orientable manifold surface (every face of
/// `component` a triangle; the quads use its vertex ids, the sources its face ids). The matching
/// of K's dual is verified perfect (std::logic_error otherwise). Throws MeshError naming the
/// element when the input is not such a surface: a face that is not a triangle, boundary,
/// non-manifold or inconsistently oriented edges, pinched vertices, several components.
/// Contraction and expansion take O(n·d) for maximum input degree d (measured linear,
/// bench/lrs_speed), the augmentation of the ℓ free faces O(ℓ·n) at worst; the surface check
/// O(n log d); O(n) memory; iterative throughout.
LrsPairing pair_closed_component_by_lrs(const PolygonMesh& component,
                                        const LrsOptions& options = {});

/// The same from the surface's dual arrays (see LrsDualInput), numbered spatially from them: at
/// most 64 bytes per triangle beside the positions and, until corners_read, the corners. Throws
/// MeshError naming the input vertex when a vertex is pinched or orientation is inconsistent
/// around it, or when the triangles form several components (unless `connected`), and
/// std::invalid_argument when the arrays are not a dual of the triangles, all of it before
/// corners_read; the caller's corners are intact then, its arrays gone. O(V + F) to build, then
/// as above.
LrsPairing pair_closed_component_by_lrs(LrsDualInput input, const LrsOptions& options = {});

}  // namespace petersen
