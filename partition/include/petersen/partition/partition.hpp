#pragma once
// A triangle mesh too large for one pairing, paired part by part: the three steps a driver runs
// (one process out of core, or a cluster engine such as Dask), see docs/distributed.md.
//
// 1. pair_part: the triangles of one part (a contiguous range of global face ids) are paired by
//    a certified maximum matching of the part's pairable graph; its unpaired triangles are moved
//    by alternating paths to the part's border, and it reports its open edges (edges with one
//    triangle in the part: the cut and the true boundary) and its band (the triangles within a
//    few steps of the open edges).
// 2. pair_open_edges: the open edges of all parts, merged by their vertex pair, give the pairable
//    adjacencies across the cuts and tell whether the whole mesh is closed.
// 3. repair_cuts: the bands of all parts with the cut adjacencies form the band graph; augmenting
//    paths in it (from the current pairing) pair the triangles the cuts left unpaired.
//
// With a cost objective (Objective::quads or quality, as quadrangulate's) the part step pairs
// each part by the same minimum-cost matching, costs and price as quadrangulate, and reports its
// band with the corners' positions and its dual there (SeamFace); step 3 is then pair_seams: the
// bands of all parts and the cut adjacencies are paired again by the same matching, and the
// parts' duals, stitched across the cuts, bound the whole mesh's optimum from below.
//
// Ids are global: FaceId for faces (a part's triangle i is face first_face + i), VertexId for
// vertices. Every triangle is a face; polygons are not taken (a part names its triangles only).

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "petersen/dualize/pairable_graph.hpp"
#include "petersen/matching/min_cost_matching.hpp"
#include "petersen/matching/options.hpp"
#include "petersen/mesh/mesh.hpp"
#include "petersen/quadrangulate/quadrangulate.hpp"

namespace petersen {

/// The triangles of one part: face first_face + i has corners corners[3i], corners[3i + 1],
/// corners[3i + 2] (global vertex ids, any values below 2^32 - 1).
///
/// A sweep over the parts in face order may carry the end of the previous part into the next:
/// then the first `carried` triangles are the previous part's, already paired, carried_partner[i]
/// naming triangle i's partner (global id, kNoFace when unpaired). Their pairs inside the part
/// are the initial matching and may change; a carried triangle paired outside is held fixed.
/// Unpaired triangles of the previous part are so paired by augmenting paths into this one, and
/// this part's own are moved to its other borders: the sweep carries them forward to where they
/// meet a partner. Open edges and the band are those of the part's own triangles (after the
/// carried ones) as if it were alone; partner and unpaired cover all of them.
struct PartTriangles {
  FaceId first_face = 0;
  std::span<const VertexId> corners = {};
  std::uint32_t carried = 0;
  std::span<const FaceId> carried_partner = {};
  /// The position of each corner (one per entry of `corners`): read by the cost objectives and
  /// the sharp-angle cut only, which measure the quads.
  std::span<const std::array<double, 3>> corner_positions = {};
  std::uint32_t triangle_count() const { return static_cast<std::uint32_t>(corners.size() / 3); }
};

/// An edge with exactly one triangle of its part: its ends (low < high), that triangle and the
/// triangle's third corner (which tells two triangles on the same three vertices apart).
struct OpenEdge {
  VertexId low = 0, high = 0;
  FaceId face = kNoFace;
  VertexId apex = 0;
  friend bool operator==(const OpenEdge&, const OpenEdge&) = default;
};

/// What each side of a band triangle is in its own part (BandFace::sides).
enum class SideState : std::uint8_t {
  cut,       ///< no pair may cross it (non-manifold, degenerate, duplicate inside the part)
  pairable,  ///< an edge of the part's pairable graph
  open,      ///< one of the part's open edges: pairable only where pair_open_edges says so
};

/// A triangle near its part's open edges: its corners, its sides' states (side k runs from
/// corner k to corner k + 1) and its distance, in steps across pairable edges of its part, from
/// the nearest triangle with an open side (0 for those).
struct BandFace {
  FaceId face = kNoFace;
  std::array<VertexId, 3> corners{};
  std::array<SideState, 3> sides{};
  std::uint32_t distance = 0;
};

/// What the cost objectives need of the cuts (see pair_seams): an own triangle of a part within
/// the band (PartPairingOptions::band_radius steps of an open side), its corners and their
/// positions, its sides' states and distance (as BandFace's), its partner after the part step,
/// and, for Objective::quads, the part's dual at its two nodes of the doubled graph (v and its
/// copy v', see min_cost_matching), each with the values of the odd sets holding the node: an edge
/// across a cut from here has reduced cost 2·cost − dual[k] − the other end's dual[k] in copy k;
/// its price for staying unpaired in the part's pairing (triangle_prices over the part's graph,
/// which near a cut sees one side only) and the left side of its stay edge v–v''s constraint in
/// the part's certificate (at most 4·price): pair_seams prices the faces beside a cut from both
/// sides and lowers the duals where that price is less.
struct SeamFace {
  FaceId face = kNoFace;
  std::array<VertexId, 3> corners{};
  std::array<std::array<double, 3>, 3> positions{};
  std::array<SideState, 3> sides{};
  std::uint32_t distance = 0;
  FaceId partner = kNoFace;
  std::array<std::int64_t, 2> dual{};
  Cost price = 0;
  std::int64_t stay_dual = 0;
};

/// The costs of quadrangulate's cost objectives, for the parts and the seams alike.
struct PartCosts {
  /// Objective::pairs: the part's maximum matching, moved to the border (the sweep and the band
  /// repair); quads or quality: the minimum-cost matching of quadrangulate, no carried triangles.
  Objective objective = Objective::pairs;
  /// Objective::quads: a triangle left unpaired, in degrees (QuadOptions::triangle_cost).
  double triangle_cost = kDefaultTriangleCost;
  /// Pairs whose quad costs more are refused (QuadOptions::max_corner_deviation).
  std::optional<double> max_corner_deviation = {};
  /// Edges whose triangles fold by more are cut (CutOptions::sharp_angle_degrees).
  std::optional<double> sharp_angle_degrees = {};
};

struct PartPairingOptions {
  PartCosts costs = {};
  Augment augment = Augment::local;
  /// The band holds the triangles at most this many steps from the open edges: repair_cuts can
  /// grow its band graph up to here. O(band_radius · open edges) band faces on a regular surface.
  /// Objective::quads needs 3 or more: pair_seams prices the faces beside a cut from their two
  /// rings, which must lie in the bands (pair_part throws std::invalid_argument otherwise).
  std::uint32_t band_radius = 16;
  /// Labels the searches that move unpaired triangles to the border may give in all, before the
  /// rest give up (their triangles then stay where they are, counted in PartPairing::stranded).
  /// 0: four times the part's triangles, so that any one search may cross the whole part (a
  /// triangle left far from the border, as parity may leave one in a sweep's window, is carried
  /// forward only once it is there) while a part with many unpaired triangles stays O(m).
  std::uint64_t move_budget = 0;
  /// Threads for the pairable graph's construction (build_pairable_graph); 0: every core.
  std::uint32_t threads = 1;
  /// Where the partners, the part's mesh and graph and the matching's arrays are allocated.
  std::pmr::memory_resource* memory = std::pmr::get_default_resource();
};

struct PartPairing {
  FaceId first_face = 0;
  /// Per triangle of the part (carried ones first): its partner's global face id, or kNoFace.
  /// Partners are in the part, but for carried triangles held fixed.
  std::pmr::vector<FaceId> partner;
  std::vector<FaceId> unpaired = {};      ///< global ids, ascending
  std::vector<OpenEdge> open_edges = {};  ///< ascending by (low, high, face)
  std::vector<BandFace> band = {};        ///< ascending by face (Objective::pairs)
  std::vector<SeamFace> seam = {};        ///< the cost objectives' band, ascending by face
  /// The cost objectives: the part's certified optimum in the solver's units (scale_costs):
  /// quads the matched costs plus the price of every triangle left, quality the matched costs.
  Cost objective_units = 0;
  /// The cost objectives: the part's minimum-cost matching passed its certificate check.
  bool optimality_certified = false;
  /// The part's structural cuts that are no open edge (non-manifold, degenerate, duplicate,
  /// polygon): any of them makes the whole mesh not closed.
  std::uint64_t inner_structural_cuts = 0;
  std::uint64_t pairs = 0;
  std::uint64_t moved_to_border = 0;  ///< unpaired triangles moved to the border
  std::uint64_t stranded = 0;         ///< unpaired triangles no alternating path took there
  /// The part's pairing passed verify_maximum_matching with its Tutte–Berge witness (before the
  /// moves, which keep its size and validity: re-checked by verify_matching).
  bool maximum_certified = false;
  double seconds = 0;
};

/// Pairs the triangles of one part (see the top of this file). Throws std::invalid_argument when
/// carried_partner does not have `carried` entries or names a partner that does not name it back
/// (both inside the part), and with a cost objective when triangles are carried or the corner
/// positions are missing (and for a sharp angle without them), and with Objective::quads for a
/// band radius under 3. Throws MeshError naming the
/// global face for a corner equal to 2^32 - 1 or a part past 2^32 - 1 faces; throws
/// std::logic_error if the pairing fails its verifier. O(m log m) for m triangles (the vertex
/// renumbering), plus the pairable graph and the matching (maximum_matching, augment.hpp; with a
/// cost objective min_cost_matching or min_cost_maximum_matching, twice the work of a perfect
/// matching's on the part).
PartPairing pair_part(const PartTriangles& part, const PartPairingOptions& options = {});

/// Two triangles of different parts across a cut edge {low, high} that they alone share, with
/// four distinct corners: first < second.
struct CutAdjacency {
  FaceId first = kNoFace, second = kNoFace;
  VertexId low = 0, high = 0;
  friend bool operator==(const CutAdjacency&, const CutAdjacency&) = default;
};

struct CutPairing {
  std::vector<CutAdjacency> adjacencies;  ///< ascending by (first, second)
  std::uint64_t boundary_edges = 0;       ///< open edges no other part has: the true boundary
  std::uint64_t non_manifold_edges = 0;   ///< vertex pairs with three or more open records
  std::uint64_t duplicate_edges = 0;      ///< two records whose triangles have the same corners
  bool closed() const {
    return boundary_edges == 0 && non_manifold_edges == 0 && duplicate_edges == 0;
  }
};

/// Merges the open edges of all parts (any order, concatenated) by vertex pair: two records of a
/// pair are a cut adjacency unless their triangles have the same three corners. O(r log r) for r
/// records.
CutPairing pair_open_edges(std::vector<OpenEdge> records);

struct RepairOptions {
  Augment augment = Augment::local;
  /// The band graph starts with the band faces at distance at most first_radius and doubles it
  /// while triangles stay unpaired, up to the parts' band_radius.
  std::uint32_t first_radius = 2;
};

/// The bands of all parts (BandFace, any order, each face once), with each band face's current
/// partner (kNoFace when unpaired) at the same index, and the cut adjacencies.
struct RepairInput {
  std::span<const BandFace> band;
  std::span<const FaceId> partner;
  std::span<const CutAdjacency> adjacencies;
};

struct RepairResult {
  /// The new partner of each band face (same order as RepairInput::band); a face outside the
  /// band graph keeps its partner.
  std::vector<FaceId> partner;
  std::uint64_t unpaired_before = 0, unpaired_after = 0;  ///< band faces without a partner
  std::uint64_t augmenting_paths = 0;
  std::uint64_t band_graph_faces = 0;  ///< triangles in the last band graph
  std::uint32_t radius = 0;            ///< the last band graph's radius
  /// The last band graph's matching passed verify_maximum_matching: no augmenting path is left
  /// inside the band graph (the faces outside it, or paired outside it, are held fixed).
  bool maximum_in_band_certified = false;
  double seconds = 0;
};

/// Pairs across the cuts (see the top of this file): the band graph holds the band faces within
/// the radius whose partners are in it too (a face paired outside the band is held fixed); its
/// edges are the pairable sides inside a part and the cut adjacencies. Throws std::logic_error
/// if a matching fails its verifier, std::invalid_argument when partner and band differ in size.
/// O(b log b) for b band faces, plus the augmentation.
RepairResult repair_cuts(const RepairInput& input, const RepairOptions& options = {});

/// The seams of all parts (SeamFace, any order, each face once) and the cut adjacencies.
struct SeamInput {
  std::span<const SeamFace> faces;
  std::span<const CutAdjacency> adjacencies;
  /// The step works in batches: the candidate edges are measured this many at a time (at least
  /// one), and the seam graph's components (the bands of different cuts are apart) are solved in
  /// batches of whole components, each of at least this many faces but the last. The answer is
  /// the same for any batch size; the memory follows the largest batch.
  std::uint32_t batch_faces = std::uint32_t{1} << 20;
};

struct SeamResult {
  /// Each seam face's partner after the seam step (same order as SeamInput::faces).
  std::vector<FaceId> partner;
  /// The seam graph's total after the step (at the whole mesh's prices) minus before it (at the
  /// parts' prices, as their objective_units count it), in the solver's units: added to the
  /// parts' objective_units, the whole pairing's total.
  Cost objective_change = 0;
  /// Objective::quads: what stitching the parts' duals across the cuts lost, in the certificate's
  /// units (twice the doubled graph's costs): Σ parts' objective_units − dual_lowering / 4 is a
  /// lower bound on the whole mesh's optimum (lower_bound_degrees).
  std::int64_t dual_lowering = 0;
  std::uint64_t seam_graph_faces = 0, seam_graph_edges = 0;
  std::uint64_t pairs_across = 0;  ///< pairs of the seam graph across a cut after the step
  /// The seam graph's matching passed its certificate check (of the objective's matching).
  bool certified = false;
  double seconds = 0;
};

/// Pairs across the cuts with a cost objective. The seam graph holds the seam faces within the
/// bands' depth of a cut adjacency (across allowed edges; with their partners) whose partners are
/// seam faces too or none (a face paired outside the seams is held), with their
/// pairable sides inside a part and the cut adjacencies as edges, where the options allow them
/// (the sharp angle, the corner threshold), each costing its quad as quadrangulate measures it
/// (pairable_edge_quality, from the lower face). Its matching is solved again from scratch:
/// Objective::quads by min_cost_matching at the whole mesh's prices (triangle_prices: a face
/// within one step of an open side priced again over the seam faces, whose candidate edges hold
/// its two rings; the others at their part's price), quality by min_cost_maximum_matching; each
/// certificate is checked. The parts' pairs there are one of its matchings, so quads' total never
/// rises above theirs at the whole mesh's prices, and quality's pairs never fall.
/// For Objective::quads it also stitches the parts' duals: every stay edge whose whole-mesh
/// price leaves it violated (SeamFace::stay_dual), then every cut adjacency whose reduced cost
/// (SeamFace::dual) is negative in a copy, lowers a node dual by the violation left, which keeps
/// every other constraint of the whole mesh's doubled graph (a node's dual is free, lowering it
/// only raises the reduced costs at it), so the stitched duals are feasible for the whole mesh.
/// Throws std::invalid_argument naming a face given twice or an adjacency whose face is no seam
/// face, std::logic_error if a certificate fails. O(s log s) for s seam faces plus the matching.
SeamResult pair_seams(const SeamInput& input, const PartCosts& costs, std::uint32_t threads = 1);

/// The lower bound on the whole mesh's Objective::quads optimum, in degrees, from the parts'
/// certified optima (the sum of their objective_units) and the seam step's dual_lowering.
double lower_bound_degrees(Cost parts_units, std::int64_t dual_lowering);

}  // namespace petersen
