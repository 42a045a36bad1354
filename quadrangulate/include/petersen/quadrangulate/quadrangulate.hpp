#pragma once
// The front door for meshes: any polygon mesh in, its triangles paired into quads, the rest kept.
//
// Two triangles may be paired when they share an edge that belongs to exactly these two faces and
// their union has four distinct vertices (petersen/dualize/pairable_graph.hpp); every other edge
// is a cut no pair crosses. By default (Objective::quads) the pairing is the matching of that graph
// of least total cost, each quad costing its shape and each triangle left a price, found exactly
// and proved optimal by its dual certificate. Objective::pairs and quality pair the maximum:
// - components of the graph in which every triangle has three pairable sides (closed surfaces)
//   are matched perfectly by the chosen algorithm (Petersen's theorem: their graph is cubic and
//   bridgeless, since a bridge would be a one-edge boundary), and checked by the O(n) verifier;
// - every other component by a greedy pass and Tarjan's augmenting paths, whose final Edmonds
//   forest gives a Tutte–Berge witness that verify_maximum_matching checks;
// quality takes, among the maximum pairings, the one of least total shape cost.
// Faces that are not triangles are kept exactly as they are; triangles left unpaired stay
// triangles, or with all_quad are turned into quads by splitting edges (see QuadOptions).

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "petersen/dualize/pairable_graph.hpp"
#include "petersen/matching/perfect_matching.hpp"
#include "petersen/mesh/mesh.hpp"

namespace petersen {

/// A triangle is flat shaded when each of its corner normals n makes with its geometric normal m
/// an angle whose cosine is at least this (n·m ≥ 0.9999 |n| |m|: within about 0.8°, wide enough
/// for normals written with four decimals).
inline constexpr double kFlatShadingCosine = 0.9999;

/// What the pairing optimises.
enum class Objective {
  /// The quads people keep (the default): the least total of every quad's cost, its shape
  /// (quad_corner_deviation) plus QuadOptions::flow_weight times its edge flow (how far its sides
  /// lie from a smooth cross field, petersen/dualize/cross_field.hpp), plus
  /// QuadOptions::triangle_cost for every triangle left unpaired. Not the maximum pairing: a
  /// triangle stays where every quad it could join costs more than leaving it, so a model's own
  /// triangles stay where pairing them would break good quads. Exact, its dual certificate checked.
  quads,
  pairs,    ///< the maximum pairing by the algorithm, nothing else weighed: fastest
  quality,  ///< the maximum pairing of least total quad_corner_deviation, exact and certified
};
std::string_view to_string(Objective objective);
std::optional<Objective> parse_objective(std::string_view name);

/// lrs, contraction and expansion with flips (paper §3.3, petersen/lrs/lrs.hpp): it works on the
/// mesh's triangulation, not on a graph, so it is chosen here rather than among Algorithm's.
struct Lrs {
  bool operator==(const Lrs&) const = default;
};
inline constexpr Lrs kLrs{};
/// Objective::pairs' algorithm for the closed components: one that perfect_matching runs, or lrs.
using PairingAlgorithm = std::variant<Algorithm, Lrs>;
/// "lrs", or to_string of the Algorithm.
std::string_view to_string(const PairingAlgorithm& algorithm);
/// "lrs", or what parse_algorithm accepts; std::nullopt for any other name.
std::optional<PairingAlgorithm> parse_pairing_algorithm(std::string_view name);

/// Objective::quads' defaults, chosen on the recovery bench (bench/quad_recovery.py: quad models
/// exported triangulated and converted back) and the scans of ../shared/meshes. Leaving a triangle
/// costs as much as a quad whose worst corner is 90° off a right angle, so a pair of cost c saves
/// 180 − c over its two triangles: scans keep all but a fraction of a percent of their triangles
/// paired, while a model's own triangles stay where pairing them would turn its quads. The edge
/// flow is off by default: a cross field made from the triangles' own sides points the wrong way
/// often enough on the bench's models (whose quads meet at many irregular vertices) that every
/// weight tried brought fewer quads back than shape alone.
inline constexpr double kDefaultTriangleCost = 90.0;
inline constexpr double kDefaultFlowWeight = 0.0;
/// Their largest values: far above what any quad costs, inside the solver's range once scaled.
inline constexpr double kMaxTriangleCost = 10000.0;
inline constexpr double kMaxFlowWeight = 100.0;

/// The most threads QuadOptions::threads may ask for: more than any machine has cores, few enough
/// that a mistyped count cannot start a thread per block of a large mesh.
inline constexpr std::uint32_t kMaxQuadThreads = 1024;

struct QuadOptions {
  /// Objective::quads pairs by the exact minimum-cost matching of any size with a price per left
  /// triangle (min_cost_matching in min_cost_matching.hpp) over the whole pairable graph (with
  /// all_quad, which splits every triangle left, the cheapest maximum pairing, as quality);
  /// Objective::quality by the minimum-cost matching of the quads' worst-corner deviation,
  /// perfect on closed components and the cheapest maximum one elsewhere. Each is proved optimal
  /// by its dual certificate. Objective::pairs runs `algorithm`, `augment` and `seed`, which the
  /// other two do not use: an algorithm other than automatic with them is refused.
  Objective objective = Objective::quads;
  /// Objective::quads: what a triangle left unpaired costs, in the quads' cost units (degrees). A
  /// pair is made where its quad costs less than the two triangles it takes (twice this) and the
  /// pairs it displaces allow; 0 would pair nothing that costs. Finite and at least 0.
  double triangle_cost = kDefaultTriangleCost;
  /// Objective::quads: degrees of shape cost per degree of edge flow (pairable_edge_flow in
  /// petersen/dualize/cross_field.hpp: how closely the edge a pair removes runs along the cross
  /// field, in [0, 90]). Finite and at least 0; 0 (the default) weighs shape alone and computes no
  /// field.
  double flow_weight = kDefaultFlowWeight;
  /// Objective::pairs: the algorithm for the closed components: auto, sg, ps, ds, gw, frink or
  /// lrs. lrs works on each closed, connected, orientable manifold component (it flips edges,
  /// see LrsResult); a closed component it cannot take (pinched vertex, non-orientable) is matched
  /// by auto instead and counted in QuadStats::lrs_fallback_components.
  PairingAlgorithm algorithm = Algorithm::automatic;
  Augment augment = Augment::local;
  std::uint64_t seed = 1;
  /// Make every face of the output a quad, adding the fewest vertices this pairing allows. A
  /// polygon can be cut into quads iff its side count is even, and a midpoint on an edge adds a
  /// side to every face on it; so the edges to split are a minimum T-join (T: the faces of odd
  /// side count) of the faces' dual, where every edge of exactly two faces is a dual edge
  /// whatever its cut cause and boundary edges meet a sink. It is solved exactly by a
  /// minimum-cost perfect matching whose certificate is checked (all_quad_certified). Then every
  /// face is cut into quads: a triangle with one midpoint is a quad; a face of 6 or more sides is
  /// cut by the fan of quads, from one of its corners, whose worst corner is least (no new
  /// vertex: added_vertices = added_vertices_minimum); with Objective::quality a crossed quad
  /// becomes three quads around a new centre vertex where that is better (centre_vertices); a
  /// quad crossed straight through becomes two quads. A face whose every fan would draw a
  /// diagonal that is already an edge (which would then lie on three faces) gets a centre too.
  /// Parity on a component enclosed by non-manifold edges (or by the polygons keep_polygons keeps)
  /// may force splits of non-manifold edges, each adding a midpoint to all of its faces: they are
  /// chosen first, by elimination over GF(2), and the minimum is then the T-join's given them
  /// (all_quad_certified is false, as it is wherever a non-manifold edge borders faces that
  /// need splits: splitting it flips all of its faces at once, which the T-join does not weigh).
  /// A face repeating a vertex (a degenerate triangle such as {a, a, b}) has no cut into quads
  /// that repeats none: it is kept as it is, its sides never split, and counted in
  /// QuadStats::degenerate_faces, while every other face becomes quads.
  /// Input vertices never move and the surface's topology is
  /// unchanged. Throws MeshError only with a proof that no all-quad mesh exists (faces whose total
  /// side count stays odd whatever is split, naming an input face), the kept faces as they are.
  bool all_quad = false;
  /// With all_quad: the input's faces that are not triangles are kept exactly as they are (never
  /// in T, their edges never split); where that leaves a region of odd total side count, the
  /// MeshError says that --keep-polygons is what makes it impossible.
  bool keep_polygons = false;
  /// The threshold mode (Blender's Tris to Quads, made exact): only triangles whose quad costs at
  /// most this many degrees (quad_corner_deviation) may be paired; every other pairable edge is a
  /// cut of cause CutCause::shape. The pairing is then a certified maximum matching of what is
  /// left, the cheapest of those with Objective::quality; triangles no such pair takes stay
  /// triangles. With all_quad those are still split into quads, which the threshold does not
  /// judge (it says which pairs are allowed, not what the splits look like). Under a threshold
  /// the closed components are matched by auto instead of lrs, whose flips would make quads the
  /// threshold never saw.
  /// Degrees in [0, 270], the measure's range.
  std::optional<double> max_corner_deviation = {};
  /// Edges no pair may cross besides the mesh's own cuts: sharp folds, the caller's edges, seams
  /// and borders of the mesh's attributes (petersen/dualize/pairable_graph.hpp).
  CutOptions cuts = {};
  /// The mesh's own attributes cut too, on by default (mesh.attributes, where the mesh has them):
  /// no pair crosses a texture-coordinate or normal seam (its two triangles give an end of the
  /// edge different values; compared by value, so two `vt` entries with equal coordinates make
  /// no seam; and flat shading is no seam: where both triangles are flat shaded, each corner's
  /// normal along its own triangle's normal within kFlatShadingCosine, their edge is not cut,
  /// while a hard edge between smooth-shaded triangles is), nor a border between different
  /// materials, groups, objects, smoothing groups or face property values (all of a face's property
  /// columns together; names compared as strings). Each applies where `cuts` leaves its span empty;
  /// name its cause here (CutCause::uv_seam, normal_seam, material, group, object, smoothing,
  /// face_property) to let pairs cross it. Any other cause throws std::invalid_argument: the mesh's
  /// structure and the caller's own cuts are never crossed.
  std::vector<CutCause> cross = {};
  /// Threads for the phases that split into independent parts (grouping the halfedges and
  /// classifying the edges, the quads' measure, the minimum-cost matching's short searches); 0:
  /// every core; at most kMaxQuadThreads. Threads are started for the call and joined before it
  /// returns. The result does not depend on it.
  std::uint32_t threads = 1;
  /// Whether QuadResult::sources is filled. A caller that does not read them (the command-line
  /// tool) turns this off: lrs then need not find each quad's triangles among the input's, and the
  /// consuming front door frees the input's corners early, which lowers lrs's peak (see
  /// quadrangulate(PolygonMesh&&)).
  bool sources = true;
  /// Where the result's arrays and the conversion's large scratch arrays are allocated (see
  /// petersen/graph/memory.hpp); it must outlive the result. Two conversions on two threads may
  /// each have their own.
  std::pmr::memory_resource* memory = std::pmr::get_default_resource();
};

struct QuadStats {
  std::uint64_t faces_in = 0;       ///< faces of the input
  std::uint64_t vertices = 0;       ///< vertices of the input (referenced or not)
  std::uint64_t triangles = 0;      ///< triangles of the input
  std::uint64_t polygons_kept = 0;  ///< faces that are not triangles, kept as they are
  /// Faces with the same corners as an earlier face (duplicate_faces, petersen/mesh/
  /// duplicate_faces.hpp): their edges are edges of three or more faces (or of a face and its
  /// copy), so no pair crosses them; drop_duplicate_faces removes them before a run. Looked for
  /// only where some edge is cut as non-manifold or duplicate, among the polygons and the
  /// triangles cut on every side: a copy of a triangle can be nowhere else, a copy of a polygon
  /// nowhere else that matters to the pairing.
  std::uint64_t duplicate_faces = 0;
  std::uint64_t pairs = 0;  ///< quads made of two input triangles
  /// Triangles left unpaired (before all_quad): none that a maximum pairing can pair, except with
  /// Objective::quads, which leaves those that cost less as triangles.
  std::uint64_t triangles_left = 0;
  /// all_quad: every new vertex, split_edges + centre_vertices.
  std::uint64_t added_vertices = 0;
  std::uint64_t split_edges = 0;  ///< all_quad: edges given a midpoint
  /// all_quad: faces (not pairs) repeating a vertex, which no cut into quads can fix, kept as they
  /// are; their sides are never split.
  std::uint64_t degenerate_faces = 0;
  std::uint64_t centre_vertices = 0;  ///< all_quad: centres of faces cut around one
  /// all_quad: the fewest midpoints that make every face even for this pairing (the minimum
  /// T-join's size, plus the non-manifold splits when parity forced some).
  std::uint64_t added_vertices_minimum = 0;
  /// all_quad: the T-join's certificate passed the independent check and no non-manifold edge
  /// borders a component that needed splits, so split_edges = added_vertices_minimum is proved
  /// the fewest.
  bool all_quad_certified = false;
  std::uint64_t split_quads = 0;  ///< faces of the output made by all_quad's cuts
  /// The faces all_quad's cuts made, by quad_corner_deviation in degrees: median and 95th
  /// percentile.
  double split_quality_median = 0, split_quality_p95 = 0;
  std::uint64_t mesh_edges = 0;
  std::int64_t euler_characteristic = 0;  ///< referenced vertices − edges + faces, of the input
  /// Of a closed, consistently oriented triangle mesh: the sum of its components' genera (the
  /// surface's components, joined across chosen cuts such as seams and material borders).
  std::optional<std::int64_t> genus;
  CutCounts cuts;                        ///< mesh edges no pair may cross, by cause
  std::uint64_t inconsistent_edges = 0;  ///< pairable edges whose triangles run the same way
  std::uint64_t components = 0;          ///< components of the pairable graph
  std::uint64_t closed_components = 0;   ///< of them, those matched by `algorithm`
  /// The pairing passed the verifier and the witness check: no pairing leaves fewer triangles.
  /// Objective::quads does not seek the maximum: there it is true only when the optimum happens
  /// to leave no triangle a maximum pairing would pair (every triangle paired, or proved so).
  bool maximum_certified = false;
  /// Objective::quads and quality: the certificates proved the total cost minimal.
  bool optimality_certified = false;
  /// The quads made of two input triangles, by quad_corner_deviation in degrees (quality_figures
  /// of petersen/dualize/quad_quality.hpp): median, 95th percentile, how many are non-convex
  /// (cost above 90), and the sum (for Objective::quality and quads the certified optimum, in the
  /// solver's integer units over kDefaultCostScale: for quads, shape, flow and left triangles).
  double quality_median = 0, quality_p95 = 0, objective_total = 0;
  std::uint64_t nonconvex_quads = 0;
  /// Of `algorithm` on the closed components (the paper's columns), plus the augmentation of the
  /// other components in augmenting_paths, blossoms and nodes_labelled.
  PerfectMatchingStats matching;
  std::uint64_t flipped_edges = 0;         ///< lrs: edges of K that are not input edges
  std::uint64_t irreducible_vertices = 0;  ///< lrs: |T′|, summed over components
  std::uint64_t lrs_fallback_components = 0;
  std::string lrs_fallback_reason;  ///< the first component's refusal, when there was one

  double check_seconds = 0;            ///< the input check and the pairable graph (and the field)
  double field_seconds = 0;            ///< Objective::quads: the cross field and the flow costs
  std::uint32_t field_iterations = 0;  ///< Objective::quads: the field solve's iterations
  double dual_seconds = 0;             ///< the graphs the algorithms run on
  double verify_seconds = 0;           ///< the verifier and the maximality witness (on a closed
                                       ///< mesh, the components are counted beside the verifier)
  double quads_seconds = 0;            ///< the output faces
  double all_quad_seconds = 0;         ///< the splits
  double total_seconds = 0;            ///< everything above plus the matching
};

struct QuadResult {
  /// The output: the input's positions (then all_quad's new vertices) and faces in input order:
  /// each pair's quad where its first triangle was, kept polygons and left triangles as they
  /// were (or, with all_quad, the quads they were split into).
  /// With the input's attributes: a quad's corners have the corner attributes (texture
  /// coordinate, normal) of the triangle corners they came from (the shared edge's ends those of
  /// its first triangle, where a crossed seam lets them differ), and its face attributes
  /// (material, group, object, smoothing group, face properties) are its first triangle's; kept
  /// and left faces keep theirs; vertex properties are copied. all_quad's new vertices get
  /// interpolated values: vertex properties averaged over the edge's ends or the quad's corners
  /// (integer types rounded, float32 ones held as floats, and the position too when
  /// attributes.position_type is float32: the result holds what a writer writes), and each face
  /// around a new vertex its own corner values averaged likewise (normals renormalised), so a
  /// seam stays a seam; the new texture coordinates and normals are appended, one entry per
  /// distinct value. lrs flips edges, and a flipped triangle has no corners or face of the input
  /// to take attributes from: on a mesh with corner or face attributes its closed components are
  /// paired by ps (lrs_fallback_components says so).
  PolygonMesh mesh;
  /// For each output face, the input faces it came from: {t1, t2} for a pair's quad (the quad
  /// follows t1's orientation), {f, kNoFace} for a face kept or left. With lrs, a triangle its
  /// flips made new has no input face (kNoFace). A face split by all_quad names the faces of the
  /// quad or triangle it was split from. Empty without QuadOptions::sources.
  std::pmr::vector<std::array<FaceId, 2>> sources;
  /// The proof that no pairing leaves fewer triangles: a set A of triangles (input face ids)
  /// such that removing A from the pairable graph leaves triangles_left + |A| components with an
  /// odd number of triangles (verify_maximum_matching). Empty when every triangle is paired.
  std::vector<FaceId> tutte_set = {};
  QuadStats stats = {};
};

/// Pairs the triangles of any polygon mesh (see the top of this file). Throws MeshError naming the
/// vertex for a coordinate that is not finite (NaN or infinite, referenced or not), MeshError
/// naming the face for a corner out of range or a face of fewer than three corners, MeshError when
/// all_quad proves that no all-quad mesh exists (see QuadOptions::all_quad); std::invalid_argument
/// naming the option and its value for max_corner_deviation outside [0, 270]
/// (quad_corner_deviation's range), cuts.sharp_angle_degrees outside [0, 180], either not finite,
/// threads above kMaxQuadThreads, or a cause in `cross` that cannot be crossed, all before any
/// work. A mesh with no faces is no error here: its result is empty (no pairs, no triangles left,
/// maximum_certified), and the callers that need a mesh (`petersen quad`, the Python module) refuse
/// it themselves. O(n log d) plus the algorithm's cost.
QuadResult quadrangulate(const PolygonMesh& mesh, const QuadOptions& options = {});
/// The same, consuming the mesh: its positions (when on QuadOptions::memory) move into the output
/// mesh instead of being copied
/// (24 bytes per vertex of fresh memory, 1.2 GB at 10^8 triangles), and without
/// QuadOptions::sources lrs on a whole closed mesh frees its corners once its triangulation is
/// built (12 bytes per triangle less at lrs's peak). Whether it returns or throws, `mesh` is left
/// valid with unspecified contents.
QuadResult quadrangulate(PolygonMesh&& mesh, const QuadOptions& options = {});

}  // namespace petersen
