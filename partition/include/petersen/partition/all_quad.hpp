#pragma once
// --all-quad part by part (docs/distributed.md, "All quads"): once the pairing is final, every
// face of the output made a quad by midpoints and cuts, one part at a time, in three steps a
// driver runs (out_of_core.cpp; the Dask driver through the bindings):
//
// 1. part_parity (any order): a part's output faces, their components across the part's edges
//    of two faces and each one's parity, and their open edges (the cut and the true boundary).
// 2. split_seams (once): the open edges of all parts merged by vertex pair into the seam graph:
//    the parts' components as nodes, the cut edges between them, the true boundary as a sink.
// 3. plan_part_all_quad (in part order, each given the cut midpoints the parts before it chose):
//    a minimum T-join of the part's dual (quadrangulate's plan_piece_splits) where a cut edge to
//    an earlier part is decided, and a cut edge to a later part leads to that part's group (its
//    component of the seam graph over the later parts), which is in T when its parity is odd,
//    or the sink when it reaches the true boundary. Each group is so left even, which keeps the
//    later parts solvable (a closed component's parity is even). Then the part's faces cut into
//    quads (cut_piece_into_quads), to count its faces and centres before the output is written.
// 4. part_all_quads (any order, once every part is planned): the part's quads in the output's
//    vertex ids (input vertices, then every midpoint in ascending edge order, then the centres
//    part by part).
//
// Every part's T-join is minimal for its own T (certified by its dual); whole-mesh minimality is
// not proved. Non-manifold edges are never split.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "petersen/mesh/mesh.hpp"
#include "petersen/quadrangulate/quadrangulate.hpp"

namespace petersen {

/// A part's output faces: its triangles left and the quads of the pairs whose lower triangle is
/// in the part (as the output writes them), in global vertex ids, with each corner's position
/// (read by steps 3 and 4 only).
struct PartFaces {
  std::vector<VertexId> corners;                        ///< the faces one after another
  std::vector<std::uint8_t> arity;                      ///< 3 or 4 per face
  std::vector<std::array<double, 3>> corner_positions;  ///< one per corner, or empty
};

/// An open edge of a part's output (an edge of exactly one of its faces), global ids.
struct SplitBorderEdge {
  VertexId low = 0, high = 0;
  std::uint32_t component = 0;  ///< the face's component in the part (PartParity)
  bool kept = false;            ///< the face repeats a vertex: the edge is never split
};

struct PartParity {
  std::vector<SplitBorderEdge> border;      ///< ascending by (low, high)
  std::vector<std::uint8_t> component_odd;  ///< per component: odd parity
  std::uint64_t faces = 0, kept_faces = 0;
};

/// Step 1. O(C log C) for C corners.
PartParity part_parity(const PartFaces& faces);

/// The seam graph of step 2.
struct SplitSeams {
  /// An open edge of some part: a cut edge between two parts' components (nodes a < b), a
  /// boundary edge (b == kSeamSink) or an edge never split (a non-manifold edge, or one beside
  /// a kept face: a == b == kSeamWhole).
  struct Edge {
    VertexId low = 0, high = 0;
    std::uint32_t a = 0, b = 0;
  };
  static constexpr std::uint32_t kSeamSink = 0xFFFFFFFFu, kSeamWhole = 0xFFFFFFFEu;
  std::vector<Edge> edges;                ///< ascending by (low, high)
  std::vector<std::uint32_t> node_start;  ///< per part: its first node; one past the last
  std::vector<std::uint8_t> node_odd;     ///< per node: its component's parity
  std::uint64_t cut_edges = 0, boundary_edges = 0, whole_edges = 0;
};

/// Step 2, from every part's parity in part order. O(r log r) for r open edges.
SplitSeams split_seams(std::span<const PartParity> parts);

/// What step 3 decided for a part.
struct PartSplitPlan {
  std::vector<std::array<VertexId, 2>> midpoints;       ///< edges it split, ascending (global)
  std::vector<std::array<VertexId, 2>> cut_midpoints;   ///< of them, those on cut edges
  std::vector<std::array<VertexId, 4>> centre_corners;  ///< per centre (kNoNode after the last)
  std::vector<double> split_quality;                    ///< the cut pieces' worst corners
  std::uint64_t faces = 0;                              ///< the part's output faces after the cuts
  bool certified = false;                               ///< its T-join's certificate passed
};

/// Step 3 for part `part` (faces with positions), given the cut midpoints every earlier part
/// chose (ascending). Throws MeshError when parity leaves some faces without a way to be made
/// even (see plan_piece_splits). O(C log C + s) for s seam edges, plus the T-join.
PartSplitPlan plan_part_all_quad(const PartFaces& faces, std::uint32_t part,
                                 const SplitSeams& seams,
                                 std::span<const std::array<VertexId, 2>> earlier_cut_midpoints,
                                 const QuadOptions& options);

/// Step 4: the part's faces cut into quads over the output's vertex ids: input vertex v is v,
/// the midpoint of midpoints[i] (every part's, ascending) is vertex_count + i, the part's j-th
/// centre first_centre + j. Faces with their corners one after another (4 each, but a face kept
/// as it is: 3 for a triangle that repeats a vertex) in `mesh`. O(C log M).
PolygonMesh part_all_quads(const PartFaces& faces,
                           std::span<const std::array<VertexId, 2>> midpoints,
                           VertexId vertex_count, VertexId first_centre,
                           const QuadOptions& options);

}  // namespace petersen
