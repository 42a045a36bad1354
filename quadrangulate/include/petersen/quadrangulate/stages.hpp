#pragma once
// The stages of quadrangulate() (quadrangulate.hpp), each a function from values to values that an
// expert can run alone, as LEMON's phases; the front door is their composition, in this order:
//   pairable_mesh    the pairable graph with every cut, and each pair's cost where one is wanted
//   pair_triangles   the pairing, checked: maximum (Tutte–Berge witness) or least cost (its dual)
//   output_faces     the pairs' quads and the faces kept or left, in input order
//   measure_quads    the quads' worst-corner figures
//   attributes_of_pairs  the input's attributes carried to the quads
//   split_leftovers  with all_quad: every face made a quad by the fewest midpoints
// and, for a mesh converted piece by piece (partition/: out of core, Dask), stage 6 in three
// calls on one piece at a time: piece_parity, plan_piece_splits, cut_piece_into_quads.
// Every stage takes the
// QuadOptions the front door was given (each reads only its own fields) and fills its own fields of
// the one QuadStats; no stage reads what another left anywhere but in its arguments.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "petersen/dualize/pairable_graph.hpp"
#include "petersen/dualize/quad_quality.hpp"
#include "petersen/lrs/lrs.hpp"
#include "petersen/quadrangulate/quadrangulate.hpp"

namespace petersen {

/// What the pairing runs on: a mesh's pairable graph with every cut (structural, attribute,
/// sharp, kept-edge and shape), and each pairable edge's cost when one is wanted.
struct PairableMesh {
  PairableGraph graph;
  /// Per pairable edge: its quad's quad_corner_deviation, plus QuadOptions::flow_weight times
  /// its edge flow with Objective::quads; empty with Objective::pairs and no
  /// max_corner_deviation, which need none.
  std::pmr::vector<double> costs;
};

/// Stage 1: the pairable graph of `mesh` (build_pairable_graph) with the attribute cuts the
/// options do not cross, the pairs' costs, the cross field when a flow weight is given, and the
/// shape cuts of max_corner_deviation. Fills the mesh's figures in `stats` (faces_in, vertices,
/// triangles, polygons_kept, mesh_edges, cuts, duplicate_faces, inconsistent_edges,
/// euler_characteristic, field_iterations, field_seconds, and genus where chosen cuts join the
/// surface). Throws MeshError naming the face for bad input. O(C) for C corners on the threads,
/// plus the field's solve when asked.
PairableMesh pairable_mesh(const PolygonMesh& mesh, const QuadOptions& options, QuadStats& stats);

/// A quad lrs made, with the input triangles behind it (kNoFace where its flips made a new one).
using LrsQuad = petersen::LrsQuad;

/// What pair_triangles found.
struct TrianglePairing {
  /// Per node: its partner node, kNoNode when unpaired, kLrsNode when lrs paired it (lrs_quads).
  std::pmr::vector<NodeId> partner;
  std::pmr::vector<LrsQuad> lrs_quads;  ///< on QuadOptions::memory, as the partners
  std::vector<NodeId> tutte_set = {};   ///< nodes; see QuadResult::tutte_set
  std::int64_t objective_units = 0;     ///< a cost objective's certified total, in scaled costs
};
inline constexpr NodeId kLrsNode = kNoNode - 1;

/// Stage 2: pairs the nodes of `graph` (the pairable graph of `mesh`; its edge arrays may be taken
/// over, its node_face stays) by the options' objective and checks the answer; the cost
/// objectives need `degrees`, each edge's cost (PairableMesh::costs). `releasable_corners`, when
/// not null, is mesh.corners, which lrs on a whole closed mesh frees without options.sources; the
/// mesh then has no corners when this returns, and output_faces still reads it rightly (its
/// faces are then all lrs quads). Throws std::logic_error if a matching fails the verifier, its
/// witness or its certificate. Fills the matching, lrs, component and time fields of `stats`,
/// maximum_certified and optimality_certified.
TrianglePairing pair_triangles(PairableGraph& graph, const PolygonMesh& mesh,
                               std::pmr::vector<VertexId>* releasable_corners,
                               std::span<const double> degrees, const QuadOptions& options,
                               QuadStats& stats);

/// What each output face is: a face kept as it was (not a triangle), a triangle left, a pair's
/// quad.
enum class FaceKind : std::uint8_t { kept, left, pair };

/// What output_faces makes: the result (its mesh, the sources when asked, the Tutte–Berge set in
/// input faces; its stats left to the caller) and what each of its faces is.
struct OutputFaces {
  QuadResult result;
  std::vector<FaceKind> kinds = {};
};

/// Stage 3: the output mesh on `positions` (the input's, moved or copied in by the caller): in
/// input order each pair's quad where its first triangle was and every other face as it is, then
/// lrs's quads, all on the positions' memory resource. `with_sources`: fill result.sources (what
/// attributes and all_quad read).
/// `pairing` is taken, and freed before this returns. Counts pairs and triangles_left into
/// `stats`. O(F).
OutputFaces output_faces(const PolygonMesh& mesh, const PairableGraph& graph,
                         TrianglePairing pairing, Positions positions, bool with_sources,
                         QuadStats& stats);

/// Stage 4: the worst-corner figures of the faces `kinds` marks as pairs' quads, measured on
/// `threads` and gathered in face order (the figures do not depend on the threads). O(F).
QualityFigures measure_quads(const PolygonMesh& out, std::span<const FaceKind> kinds,
                             std::uint32_t threads);

/// Stage 5: the attributes of `out`, made by output_faces from `input` with sources: face o came
/// from input faces sources[o] ({f, kNoFace}: face f as it was; {t1, t2}: their quad, whose
/// corners take the values of the triangle corners at the same vertex, t1's first), its face
/// attributes those of its first face; vertex properties copied. Throws std::logic_error for a
/// face with no input face (lrs's flips, which never run on a mesh with corner or face
/// attributes). O(C + F).
MeshAttributes attributes_of_pairs(const PolygonMesh& input, const PolygonMesh& out,
                                   std::span<const std::array<FaceId, 2>> sources);

/// Stage 6 (all_quad): makes every face of `result` a quad (but those QuadOptions::keep_polygons
/// keeps): the fewest edges get a midpoint so that every face has an even side count (a minimum
/// T-join, certified, after the non-manifold edges parity forces), then every face is cut into
/// quads. Updates the mesh, the sources, the attributes and the stats (added_vertices,
/// split_edges, centre_vertices, added_vertices_minimum, all_quad_certified, split_quads,
/// split_quality_*; triangles_left stays the pairing's). Throws MeshError naming an input face
/// when a face that must change repeats a vertex, or when parity proves that no all-quad mesh
/// exists. O(H) plus the T-join's matching.
void split_leftovers(QuadResult& result, const std::vector<FaceKind>& kinds,
                     const QuadOptions& options);

/// Stage 6 on a piece of a mesh (a part out of core or on a cluster: partition/all_quad.hpp),
/// step 1: what the piece's parity is. An edge of exactly one face of the piece.
struct PieceOpenEdge {
  VertexId low = 0, high = 0;  ///< its ends, low < high
  FaceId face = kNoFace;       ///< the piece's face on it
  bool kept = false;           ///< that face is kept as it is (it repeats a vertex)
  friend bool operator==(const PieceOpenEdge&, const PieceOpenEdge&) = default;
};

/// The piece's faces joined across its edges of exactly two faces (neither kept): as
/// plan_splits' dual, without the sink.
struct PieceParity {
  std::vector<std::uint32_t> component;     ///< per face: its component, kNoNode when kept
  std::vector<std::uint8_t> component_odd;  ///< per component: an odd number of odd faces
  std::vector<PieceOpenEdge> open;          ///< ascending by (low, high)
  std::uint64_t kept_faces = 0;             ///< faces that repeat a vertex
};

/// The parity of `piece` (faces over its own vertex ids; positions unread): a face is odd when
/// its side count is odd and it is not kept (it repeats a vertex: kept as it is, as in
/// split_leftovers). O(C) for C corners.
PieceParity piece_parity(const PolygonMesh& piece);

/// What an open edge of a piece leads to (PieceBorder::node): an edge never split, an edge whose
/// midpoint is decided already (it flips the piece's face), or one of the outside nodes; outside
/// node 0 is the sink (any parity), the others have the parity PieceSplitInput::outside_odd
/// gives.
inline constexpr std::uint32_t kKeepWhole = 0xFFFFFFFFu, kSplitAlready = 0xFFFFFFFEu;

struct PieceBorder {
  VertexId low = 0, high = 0;  ///< an open edge of the piece, low < high
  std::uint32_t node = 0;      ///< kKeepWhole, kSplitAlready or an outside node
};

struct PieceSplitInput {
  /// Open edges of the piece, ascending by (low, high); an open edge not listed joins the sink.
  std::span<const PieceBorder> border = {};
  /// Per outside node (node 0, the sink, is read as free): whether it is in T.
  std::span<const std::uint8_t> outside_odd = {};
  std::uint32_t threads = 1;  ///< the T-join's matching (0: every core)
};

/// The edges of a piece that plan_piece_splits gives a midpoint.
struct PieceSplits {
  /// Ascending, in the piece's ids: edges inside the piece and the open edges chosen (not those
  /// split already).
  std::vector<std::array<VertexId, 2>> edges;
  bool certified = false;  ///< the T-join's certificate passed its check (it is minimal)
};

/// Step 2: the fewest edges of `piece` whose midpoints, with those split already, make every
/// face even: a minimum T-join (minimum_t_join, certified by its dual) of the piece's dual
/// with the outside nodes, where T is the odd faces (flipped by the edges split already) and the
/// outside nodes in T, the sink taking whatever parity makes its component even. Non-manifold
/// edges of the piece and the edges of kept faces are never split (unlike plan_splits, which may
/// split a non-manifold edge). Throws MeshError naming a face of the piece when a component
/// without the sink has odd parity (no midpoints inside it can make it even). O(C) plus the
/// T-join's matching.
PieceSplits plan_piece_splits(const PolygonMesh& piece, const PieceSplitInput& input);

/// What cut_piece_into_quads makes of a piece.
struct PieceQuads {
  /// The faces (no positions), in the order of the faces they come from, over the piece's
  /// vertices, then the midpoints (vertex V + i on split_edges[i], for V the piece's vertices),
  /// then the centres (V + split_edges.size() + j).
  PolygonMesh mesh;
  /// Per centre: the corners of the face it is the average of (up to four; kNoNode after).
  std::vector<std::array<VertexId, 4>> centre_corners;
  /// The worst-corner figure (quad_corner_deviation) of each face the cuts made.
  std::vector<double> split_quality;
};

/// Step 3: every face of `piece` (with positions) cut into quads once `split_edges` (ascending
/// (low, high) pairs, each an edge of the piece) have their midpoints: split_leftovers' cut
/// (a kept face stays as it is; centres where options.objective is not pairs and they are
/// better), except that a fan's diagonal is tested against the piece's edges only. O(C log M)
/// for M split edges.
PieceQuads cut_piece_into_quads(const PolygonMesh& piece,
                                std::span<const std::array<VertexId, 2>> split_edges,
                                const QuadOptions& options);

}  // namespace petersen
