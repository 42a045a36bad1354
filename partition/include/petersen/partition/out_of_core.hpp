#pragma once
// The out-of-core conversion: a binary PLY triangle mesh larger than memory, paired part by part
// (partition.hpp) and written as a binary PLY of quads, with a bounded peak of memory.

#include <cstdint>
#include <string>

#include "petersen/matching/options.hpp"
#include "petersen/partition/partition.hpp"

namespace petersen {

struct OutOfCoreOptions {
  /// The objective and its costs. Objective::pairs (the default here: the fastest, to 10^9
  /// triangles) pairs the maximum by the sweep and the band repair; quads and quality pair each
  /// part by quadrangulate's minimum-cost matching and then the seams (pair_seams).
  PartCosts costs = {};
  /// The bytes the run may hold; the parts are sized from it (bytes_per_triangle).
  std::uint64_t memory_limit = std::uint64_t{3} << 30;
  /// Memory one triangle of a part costs at the part step's peak (measured for each objective;
  /// see docs/distributed.md). Zero: the measured default.
  std::uint64_t bytes_per_triangle = 0;
  /// Triangles per part; zero: from memory_limit. Tests set it to force many parts.
  std::uint64_t part_triangles = 0;
  Augment augment = Augment::local;
  /// Every face of the output made a quad (QuadOptions::all_quad), part by part (all_quad.hpp):
  /// the fewest midpoints per part given what the parts before it chose, then the cuts.
  bool all_quad = false;
  /// With all_quad: QuadOptions::keep_polygons. The input holds triangles only, so there is no
  /// polygon to keep: honoured as it is, changing nothing.
  bool keep_polygons = false;
  /// Triangles per part of the all-quad step; zero: part_triangles, or from memory_limit.
  std::uint64_t all_quad_part_triangles = 0;
  std::uint32_t band_radius = 16;
  std::uint32_t threads = 1;
  /// Where each part's arrays are allocated: a resource that keeps what one part frees for the
  /// next (the CLI's huge-page pool, up to memory_limit) spares faulting them in afresh for
  /// every part.
  std::pmr::memory_resource* memory = std::pmr::get_default_resource();
};

struct OutOfCoreStats {
  std::uint64_t vertices = 0, triangles = 0, parts = 0, part_triangles = 0;
  std::uint64_t pairs = 0, triangles_left = 0;
  std::uint64_t unpaired_after_parts = 0, repaired = 0;
  std::uint64_t cut_adjacencies = 0, band_faces = 0, band_graph_faces = 0;
  std::uint32_t repair_radius = 0;
  bool closed = false;
  /// Every pair shares an edge and names its partner back (checked while writing), and on a
  /// closed mesh every triangle is paired: the pairing is perfect, hence maximum.
  bool perfect_certified = false;
  /// Each part's pairing was maximum for the part (its Tutte–Berge witness), and the repair's
  /// was maximum in its band graph; whole-mesh maximality is proved only by perfect_certified.
  bool parts_certified = false;
  /// The cost objectives: the pairing's total in degrees (its quads' costs, plus for quads the
  /// price of every triangle left), the parts' and the seams' matchings having passed their
  /// certificates (costs_certified).
  double objective_total = 0;
  bool costs_certified = false;
  /// Objective::quads: a lower bound on the whole mesh's optimum, from the parts' duals stitched
  /// across the cuts (pair_seams), and optimality_certified when it meets objective_total.
  double lower_bound = 0;
  bool lower_bound_valid = false;
  bool optimality_certified = false;
  /// The cost objectives: pairs made across the cuts, and the seam graph they were chosen in.
  std::uint64_t seam_pairs = 0, seam_graph_faces = 0;
  /// all_quad: the vertices added (split_edges midpoints and centre_vertices centres), the
  /// faces kept as they are (they repeat a vertex), the pieces the cuts made and their
  /// worst-corner median and 95th percentile, the output's faces, the all-quad step's parts.
  /// all_quad_parts_certified: every part's T-join passed its certificate (each is minimal for
  /// its own T; whole-mesh minimality is not proved).
  std::uint64_t added_vertices = 0, split_edges = 0, centre_vertices = 0, degenerate_faces = 0;
  std::uint64_t split_quads = 0, faces_out = 0, all_quad_parts = 0, seam_cut_edges = 0;
  double split_quality_median = 0, split_quality_p95 = 0;
  bool all_quad_parts_certified = false;
  double all_quad_seconds = 0;
  /// The written quads' worst corners (quad_quality.hpp), as quadrangulate's figures: the count
  /// of non-convex ones exact, the median and 95th percentile those of the costs rounded down to
  /// 1/1024° (within 0.001° below the exact figures), the quads being too many to hold. With
  /// all_quad, the pairs' quads before the splits, as in memory.
  double quality_median = 0, quality_p95 = 0;
  std::uint64_t nonconvex_quads = 0;
  std::uint64_t temp_bytes = 0;  ///< the temporary files' size at their largest
  double read_pair_seconds = 0, cut_seconds = 0, repair_seconds = 0, write_seconds = 0;
  double total_seconds = 0;
};

/// Converts `input` (binary little-endian PLY: a vertex element of fixed-size properties, then a
/// face element of triangles, a list of uint8 count and int32/uint32 indices, and no other
/// element) to `output` (binary PLY: the vertex records copied byte for byte, then the quads and
/// the triangles left; with all_quad, the input's vertex records, then the midpoints' and the
/// centres' records blended from their ends' or corners' (PlyTriangleStream::
/// append_blended_record), then quads). Temporary files sit beside the output and are removed on
/// success and on failure; the output is written to a temporary file renamed only on success.
/// Throws FileError naming the file, MeshError naming the face for bad input. O(n log n) for n
/// triangles, two passes over the faces, one over the vertices.
OutOfCoreStats quad_out_of_core(const std::string& input, const std::string& output,
                                const OutOfCoreOptions& options = {});

}  // namespace petersen
