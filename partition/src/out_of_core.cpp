// The out-of-core conversion (out_of_core.hpp): the part, cut and repair steps of partition.hpp
// over a mapped binary PLY, the pairing in a temporary file, the output streamed.

#include "petersen/partition/out_of_core.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>

#include "petersen/dualize/quad_of.hpp"
#include "petersen/dualize/quad_quality.hpp"
#include "petersen/graph/parallel.hpp"
#include "petersen/graph/stopwatch.hpp"
#include "petersen/io/file_error.hpp"
#include "petersen/io/ply_stream.hpp"
#include "petersen/partition/all_quad.hpp"
#include "petersen/partition/partition.hpp"
#include "quality_histogram.hpp"
#include "temp_files.hpp"

namespace petersen {

namespace {

using partition_detail::QualityHistogram;
using partition_detail::TempFaceArray;
using partition_detail::TempRecords;

// What a part costs per triangle at the part step's peak, its corners read from the file
// included: 125 bytes per triangle of the largest part, measured on the closed 10^8 plate
// (docs/distributed.md); parts are sized for 1.5 times their size (next_carry), which covers it.
constexpr std::uint64_t kBytesPerTriangle = 120;
// The same for the cost objectives (docs/distributed.md), whose part step holds the corners'
// positions (72 bytes per triangle), the part as a mesh, the edge costs and the minimum-cost
// matching's doubled graph and search state; quality's also the maximum matching that sizes its
// price, and a search that leaves more trees open on a part's open border.
constexpr std::uint64_t kQuadsBytesPerTriangle = 600;
constexpr std::uint64_t kQualityBytesPerTriangle = 700;
// Kept back from the limit for what does not scale with the part: the bands and open edges of all
// parts, the buffers and the program itself.
constexpr std::uint64_t kFixedBytes = std::uint64_t{256} << 20;

// The cost objectives' parts paired at once (run_parts_at_cost), one per thread: the automatic
// part size leaves each this share of the limit, on any number of threads, so that the parts, and
// so the answer, do not depend on the threads.
constexpr std::uint32_t kCostPartsInFlight = 2;

// The smallest part: below it the open edges outweigh the triangles.
constexpr std::uint64_t kMinPartTriangles = 64;

std::uint64_t part_size(const OutOfCoreOptions& options, std::uint64_t triangles) {
  std::uint64_t part = options.part_triangles;
  if (part == 0) {
    const Objective objective = options.costs.objective;
    const std::uint64_t per = options.bytes_per_triangle > 0  ? options.bytes_per_triangle
                              : objective == Objective::pairs ? kBytesPerTriangle
                              : objective == Objective::quads ? kQuadsBytesPerTriangle
                                                              : kQualityBytesPerTriangle;
    const std::uint64_t fixed = std::min(kFixedBytes, options.memory_limit / 2);
    // A part with the end of the previous one it carries holds at most 1.5 parts (next_carry);
    // the cost objectives' parts are paired kCostPartsInFlight at once.
    const std::uint64_t share = objective == Objective::pairs ? 1 : kCostPartsInFlight;
    part = std::max(kMinPartTriangles, (options.memory_limit - fixed) / per * 2 / 3 / share);
  }
  const std::uint64_t parts = std::max<std::uint64_t>(1, (triangles + part - 1) / part);
  // Parts of equal, even size: a part of odd size leaves a triangle unpaired for the repair.
  const std::uint64_t size = std::max<std::uint64_t>(2, (triangles + parts - 1) / parts);
  return size + size % 2;
}

// What the part steps leave for the cut and repair steps.
struct PartsOutcome {
  std::vector<OpenEdge> open_edges;
  std::vector<BandFace> band;  // ascending by face: the parts' bands in part order
  std::uint64_t inner_structural_cuts = 0;
  bool certified = true;
};

// Where the next part's carried range starts: the end of this part, from a little before the
// first triangle left unpaired (the sweep carries it forward) but at most half a part. Some of the
// end is carried even when all are paired, so that the cut to the next part lies inside the next
// window: its unpaired triangles then move only to borders toward later parts, and those at the
// cut find their partners across it.
std::uint64_t next_carry(const PartPairing& part, std::uint64_t own_end, std::uint64_t size) {
  const std::uint64_t margin = std::max<std::uint64_t>(1024, size / 16);
  const std::uint64_t first = part.unpaired.empty() ? own_end : part.unpaired.front();
  return std::max({own_end - std::min(own_end, size / 2), first - std::min(first, margin),
                   std::uint64_t{part.first_face}});
}

// The part step over every part in face order, each carrying the previous one's end.
PartsOutcome run_parts(const PlyTriangleStream& in, TempFaceArray& partner, std::uint64_t size,
                       const OutOfCoreOptions& options, OutOfCoreStats& stats) {
  PartsOutcome out;
  const std::uint64_t n = in.face_count();
  std::pmr::vector<VertexId> corners(options.memory);
  std::vector<FaceId> carried_partner;
  std::uint64_t carry_first = 0;
  for (std::uint64_t own_first = 0; own_first < n; own_first += size) {
    const std::uint64_t own_count = std::min(size, n - own_first);
    const std::uint64_t first = std::min(carry_first, own_first),
                        count = own_first + own_count - first;
    corners.resize(3 * count);
    in.read_faces(first, count, corners);
    in.release_faces(first, count);
    carried_partner.assign(&partner[first], &partner[first] + (own_first - first));
    const PartPairing part =
        pair_part({static_cast<FaceId>(first), corners,
                   static_cast<std::uint32_t>(own_first - first), carried_partner},
                  {.augment = options.augment,
                   .band_radius = options.band_radius,
                   .threads = options.threads,
                   .memory = options.memory});
    std::copy(part.partner.begin(), part.partner.end(), &partner[first]);
    partner.release(first, count);
    out.open_edges.insert(out.open_edges.end(), part.open_edges.begin(), part.open_edges.end());
    out.band.insert(out.band.end(), part.band.begin(), part.band.end());
    out.inner_structural_cuts += part.inner_structural_cuts;
    out.certified = out.certified && part.maximum_certified;
    carry_first = next_carry(part, own_first + own_count, size);
    ++stats.parts;
  }
  return out;
}

// What the cost objectives' part steps leave for the cut and seam steps. The seam faces of all
// parts (a band along every cut, 120 bytes a face: at 10^9 triangles, gigabytes) wait for the
// seam step in a temporary file, so that the parts have the whole limit.
struct CostPartsOutcome {
  explicit CostPartsOutcome(const std::string& beside) : seam(beside) {}
  std::vector<OpenEdge> open_edges;
  TempRecords<SeamFace> seam;
  Cost units = 0;  // the sum of the parts' certified optima
  std::uint64_t inner_structural_cuts = 0;
  bool certified = true;
};

// One part of a cost objective paired alone, with its corners' positions read from the vertex
// block. Reads the file only, so parts can be paired on several threads (ply_stream.hpp).
PartPairing pair_cost_part(const PlyTriangleStream& in, std::uint64_t first, std::uint64_t count,
                           const OutOfCoreOptions& options, std::uint32_t threads) {
  std::pmr::vector<VertexId> corners(3 * count, options.memory);
  std::pmr::vector<std::array<double, 3>> positions(3 * count, options.memory);
  in.read_faces(first, count, corners);
  in.release_faces(first, count);
  in.read_positions(corners, positions);
  in.release_vertices(0, in.vertex_count());
  return pair_part(
      {.first_face = static_cast<FaceId>(first), .corners = corners, .corner_positions = positions},
      {.costs = options.costs,
       .augment = options.augment,
       .threads = threads,
       .memory = options.memory});
}

// The part step over every part alone. The parts are independent: up to kCostPartsInFlight of
// them are paired at once, one per thread, and merged in part order, so that the result is the
// same on any number of threads (part_size leaves each its share of the memory limit).
CostPartsOutcome run_parts_at_cost(const PlyTriangleStream& in, TempFaceArray& partner,
                                   std::uint64_t size, const std::string& output,
                                   const OutOfCoreOptions& options, OutOfCoreStats& stats) {
  CostPartsOutcome out(output);
  const std::uint64_t n = in.face_count();
  const std::uint32_t threads = resolve_threads(options.threads);
  const std::uint32_t in_flight = std::min(threads, kCostPartsInFlight);
  std::vector<std::optional<PartPairing>> batch(in_flight);
  for (std::uint64_t start = 0; start < n; start += in_flight * size) {
    run_parallel(in_flight, in_flight, [&](std::uint32_t slot) {
      const std::uint64_t first = start + slot * size;
      if (first >= n) return;
      batch[slot].emplace(pair_cost_part(in, first, std::min(size, n - first), options,
                                         std::max<std::uint32_t>(1, threads / in_flight)));
    });
    for (std::optional<PartPairing>& part : batch) {
      if (!part) continue;
      const std::uint64_t first = part->first_face;
      std::copy(part->partner.begin(), part->partner.end(), &partner[first]);
      partner.release(first, part->partner.size());
      out.open_edges.insert(out.open_edges.end(), part->open_edges.begin(), part->open_edges.end());
      out.seam.append(part->seam);
      out.units += part->objective_units;
      out.inner_structural_cuts += part->inner_structural_cuts;
      out.certified = out.certified && part->optimality_certified;
      ++stats.parts;
      part.reset();
    }
  }
  return out;
}

// Pairs and unpaired triangles of the pairing, by one pass over it. O(n).
std::pair<std::uint64_t, std::uint64_t> count_pairing(TempFaceArray& partner, std::uint64_t n) {
  constexpr std::uint64_t kChunk = std::uint64_t{1} << 24;
  std::uint64_t pairs = 0, unpaired = 0;
  for (std::uint64_t first = 0; first < n; first += kChunk) {
    const std::uint64_t count = std::min(kChunk, n - first);
    for (std::uint64_t f = first; f < first + count; ++f) {
      const FaceId p = partner[f];
      unpaired += p == kNoFace;
      pairs += p != kNoFace && p > f;
    }
    partner.release(first, count);
  }
  return {pairs, unpaired};
}

// The repair step over the bands of all parts, with their partners as the sweep left them;
// its new partners written into the pairing.
RepairResult repair(const PartsOutcome& parts, const CutPairing& cut, TempFaceArray& partner) {
  std::vector<FaceId> band_partner(parts.band.size());
  for (std::size_t i = 0; i < parts.band.size(); ++i) band_partner[i] = partner[parts.band[i].face];
  RepairResult result = repair_cuts({parts.band, band_partner, cut.adjacencies});
  for (std::size_t i = 0; i < parts.band.size(); ++i)
    partner[parts.band[i].face] = result.partner[i];
  return result;
}

// Checks the pair {f, p} from f's side: p names f back and the two share an edge; its quad.
// O(1).
std::array<VertexId, 4> checked_quad(const TempFaceArray& partner, FaceId f, FaceId p,
                                     std::span<const VertexId> tf, std::span<const VertexId> tp,
                                     std::uint64_t n) {
  if (p >= n || partner[p] != f) {
    throw std::logic_error("internal error: face " + std::to_string(f) + " names partner " +
                           std::to_string(p) + ", which does not name it back");
  }
  std::array<VertexId, 4> quad;
  try {
    quad = quad_of(tf, tp);
  } catch (const std::logic_error&) {
    throw std::logic_error("internal error: faces " + std::to_string(f) + " and " +
                           std::to_string(p) + " are paired but share no edge");
  }
  return quad;
}

// Visits the output faces of faces first..first+count-1 in face order: each triangle left
// (visit(corners of 3)), and the quad of each pair whose first triangle is among them
// (visit(corners of 4)); every pair is checked from both of its sides (checked_quad), the one
// whose first triangle lies in an earlier part from its second. `corners` is the part's buffer.
// O(count), plus one face read for each partner outside the part.
template <class Visit>
void for_each_output_face(const PlyTriangleStream& in, TempFaceArray& partner, std::uint64_t first,
                          std::uint64_t count, std::pmr::vector<VertexId>& corners, Visit visit) {
  corners.resize(3 * count);
  in.read_faces(first, count, corners);
  in.release_faces(first, count);
  const std::uint64_t n = in.face_count();
  for (std::uint64_t i = 0; i < count; ++i) {
    const FaceId f = static_cast<FaceId>(first + i), p = partner[f];
    const std::span<const VertexId> tf(corners.data() + 3 * i, 3);
    if (p == kNoFace) {
      visit(tf);
      continue;
    }
    const bool inside = p >= first && p < first + count;
    VertexId outside[3];
    if (!inside && p < n) in.read_faces(p, 1, outside);
    const std::span<const VertexId> tp =
        inside ? std::span<const VertexId>(corners.data() + 3 * (p - first), 3) : outside;
    const std::array<VertexId, 4> quad = checked_quad(partner, f, p, tf, tp, n);
    if (f < p) visit(std::span<const VertexId>(quad));
  }
  partner.release(first, count);
}

// The worst corner of each of these quads (4 corners each) into `histogram`, their positions read
// from the file in chunks of kQuadChunk, so that the buffers stay small beside a part.
void measure_quads(const PlyTriangleStream& in, std::span<const VertexId> quad_corners,
                   std::pmr::vector<std::array<double, 3>>& positions,
                   QualityHistogram& histogram) {
  constexpr std::size_t kQuadChunk = std::size_t{1} << 18;
  for (std::size_t first = 0; first < quad_corners.size(); first += 4 * kQuadChunk) {
    const std::span<const VertexId> chunk =
        quad_corners.subspan(first, std::min(4 * kQuadChunk, quad_corners.size() - first));
    positions.resize(chunk.size());
    in.read_positions(chunk, positions);
    for (std::size_t q = 0; q < chunk.size(); q += 4) {
      histogram.add(quad_corner_deviation(positions[q], positions[q + 1], positions[q + 2],
                                          positions[q + 3]));
    }
  }
  in.release_vertices(0, in.vertex_count());
}

// The faces of one part, written and checked: every pair from both of its sides; its quads
// measured into `histogram`.
void write_part(const PlyTriangleStream& in, TempFaceArray& partner, std::uint64_t first,
                std::uint64_t count, std::pmr::vector<VertexId>& corners, PlyStreamWriter& out,
                QualityHistogram& histogram, OutOfCoreStats& stats) {
  std::pmr::vector<VertexId> quad_corners(corners.get_allocator());
  for_each_output_face(in, partner, first, count, corners, [&](std::span<const VertexId> face) {
    if (face.size() == 3) {
      out.write_triangle(face[0], face[1], face[2]);
      ++stats.triangles_left;
    } else {
      out.write_quad(face[0], face[1], face[2], face[3]);
      quad_corners.insert(quad_corners.end(), face.begin(), face.end());
    }
  });
  std::pmr::vector<std::array<double, 3>> positions(corners.get_allocator());
  measure_quads(in, quad_corners, positions, histogram);
}

void set_quality(const QualityHistogram& histogram, OutOfCoreStats& stats) {
  const QualityFigures figures = histogram.figures();
  stats.quality_median = figures.median;
  stats.quality_p95 = figures.p95;
  stats.nonconvex_quads = figures.nonconvex;
}

void write_output(const PlyTriangleStream& in, TempFaceArray& partner, const std::string& output,
                  std::uint64_t size, OutOfCoreStats& stats) {
  PlyStreamWriter out(output, in.vertex_declaration(), in.face_count() - stats.pairs);
  constexpr std::uint64_t kVertexChunk = std::uint64_t{1} << 22;
  for (std::uint64_t first = 0; first < in.vertex_count(); first += kVertexChunk) {
    const std::uint64_t count = std::min(kVertexChunk, in.vertex_count() - first);
    out.write_vertex_records(in.vertex_records(first, count));
    in.release_vertices(first, count);
  }
  std::pmr::vector<VertexId> corners;
  QualityHistogram histogram;
  for (std::uint64_t first = 0; first < in.face_count(); first += size) {
    write_part(in, partner, first, std::min(size, in.face_count() - first), corners, out, histogram,
               stats);
  }
  out.commit();
  set_quality(histogram, stats);
  stats.temp_bytes += out.bytes_written();
}

// The all-quad step's parts: the pairing's, or smaller where the T-join's matching needs it.
constexpr std::uint64_t kAllQuadBytesPerTriangle = 600;

std::uint64_t all_quad_part_size(const OutOfCoreOptions& options, std::uint64_t size) {
  if (options.all_quad_part_triangles > 0) return options.all_quad_part_triangles;
  if (options.part_triangles > 0) return size;
  const std::uint64_t fixed = std::min(kFixedBytes, options.memory_limit / 2);
  return std::max<std::uint64_t>(
      kMinPartTriangles,
      std::min(size, (options.memory_limit - fixed) / kAllQuadBytesPerTriangle * 2 / 3));
}

// The output faces of faces first..first+count-1 (all_quad.hpp's PartFaces), as the output
// writes them (for_each_output_face), with the corners' positions when asked. Counts the
// triangles left into `left`.
PartFaces part_faces(const PlyTriangleStream& in, TempFaceArray& partner, std::uint64_t first,
                     std::uint64_t count, std::pmr::vector<VertexId>& corners, bool positions,
                     std::uint64_t& left) {
  PartFaces faces;
  faces.corners.reserve(2 * count + count / 2);
  for_each_output_face(in, partner, first, count, corners, [&](std::span<const VertexId> face) {
    faces.corners.insert(faces.corners.end(), face.begin(), face.end());
    faces.arity.push_back(static_cast<std::uint8_t>(face.size()));
    left += face.size() == 3;
  });
  if (positions) {
    faces.corner_positions.resize(faces.corners.size());
    in.read_positions(faces.corners, faces.corner_positions);
    in.release_vertices(0, in.vertex_count());
  }
  return faces;
}

// The worst corner of the pairs' quads of a part's faces (read with their positions) into
// `histogram`, as in memory, where the figures are the pairing's before the all-quad splits.
void add_pair_quads(const PartFaces& faces, QualityHistogram& histogram) {
  std::size_t corner = 0;
  for (const std::uint8_t arity : faces.arity) {
    if (arity == 4) {
      const auto* p = faces.corner_positions.data() + corner;
      histogram.add(quad_corner_deviation(p[0], p[1], p[2], p[3]));
    }
    corner += arity;
  }
}

// --all-quad (all_quad.hpp): the parities, the seams, the plan part by part in face order, and
// the output: the input's vertex records, the midpoints' and centres' records, the quads.
void write_all_quad(const PlyTriangleStream& in, TempFaceArray& partner, const std::string& output,
                    std::uint64_t size, const OutOfCoreOptions& options, OutOfCoreStats& stats) {
  const std::uint64_t n = in.face_count();
  const std::uint64_t part = all_quad_part_size(options, size);
  const QuadOptions quad_options{.objective = options.costs.objective,
                                 .all_quad = true,
                                 .keep_polygons = options.keep_polygons,
                                 .threads = options.threads,
                                 .memory = options.memory};
  std::pmr::vector<VertexId> corners(options.memory);
  std::vector<PartParity> parities;
  std::uint64_t left = 0;
  for (std::uint64_t first = 0; first < n; first += part) {
    const PartFaces faces =
        part_faces(in, partner, first, std::min(part, n - first), corners, false, left);
    parities.push_back(part_parity(faces));
    stats.degenerate_faces += parities.back().kept_faces;
  }
  stats.triangles_left = left;
  stats.all_quad_parts = parities.size();
  const SplitSeams seams = split_seams(parities);
  parities = {};
  stats.seam_cut_edges = seams.cut_edges;
  std::vector<std::array<VertexId, 2>> midpoints, cut_midpoints;
  std::vector<std::array<VertexId, 4>> centres;
  std::vector<double> quality;
  std::vector<std::uint64_t> first_centre;
  QualityHistogram histogram;
  stats.all_quad_parts_certified = true;
  std::uint64_t index = 0;
  for (std::uint64_t first = 0; first < n; first += part, ++index) {
    const PartFaces faces =
        part_faces(in, partner, first, std::min(part, n - first), corners, true, left);
    add_pair_quads(faces, histogram);
    PartSplitPlan plan = plan_part_all_quad(faces, static_cast<std::uint32_t>(index), seams,
                                            cut_midpoints, quad_options);
    midpoints.insert(midpoints.end(), plan.midpoints.begin(), plan.midpoints.end());
    const std::size_t middle = cut_midpoints.size();
    cut_midpoints.insert(cut_midpoints.end(), plan.cut_midpoints.begin(), plan.cut_midpoints.end());
    std::inplace_merge(cut_midpoints.begin(), cut_midpoints.begin() + middle, cut_midpoints.end());
    first_centre.push_back(centres.size());
    centres.insert(centres.end(), plan.centre_corners.begin(), plan.centre_corners.end());
    quality.insert(quality.end(), plan.split_quality.begin(), plan.split_quality.end());
    stats.faces_out += plan.faces;
    stats.all_quad_parts_certified = stats.all_quad_parts_certified && plan.certified;
  }
  std::sort(midpoints.begin(), midpoints.end());
  midpoints.erase(std::unique(midpoints.begin(), midpoints.end()), midpoints.end());
  stats.split_edges = midpoints.size();
  stats.centre_vertices = centres.size();
  stats.added_vertices = stats.split_edges + stats.centre_vertices;
  set_quality(histogram, stats);
  stats.split_quads = quality.size();
  const QualityFigures figures = quality_figures_in_place(quality);
  stats.split_quality_median = figures.median;
  stats.split_quality_p95 = figures.p95;
  quality = {};
  const std::uint64_t vertices = in.vertex_count() + stats.added_vertices;
  if (vertices >= kNoFace) {
    throw std::invalid_argument("--all-quad: " + std::to_string(vertices) +
                                " vertices; vertex ids are 32-bit");
  }
  PlyStreamWriter out(output, in.vertex_declaration(vertices), stats.faces_out);
  constexpr std::uint64_t kVertexChunk = std::uint64_t{1} << 22;
  for (std::uint64_t first = 0; first < in.vertex_count(); first += kVertexChunk) {
    const std::uint64_t count = std::min(kVertexChunk, in.vertex_count() - first);
    out.write_vertex_records(in.vertex_records(first, count));
    in.release_vertices(first, count);
  }
  std::string records;
  auto flush = [&](bool last) {
    if (records.size() >= (std::size_t{1} << 22) || last) {
      out.write_vertex_records(records);
      records.clear();
    }
  };
  for (const auto& edge : midpoints) {
    in.append_blended_record(edge, records);
    flush(false);
  }
  for (const auto& corners4 : centres) {
    const std::size_t count =
        std::find(corners4.begin(), corners4.end(), kNoNode) - corners4.begin();
    in.append_blended_record(std::span<const VertexId>(corners4.data(), count), records);
    flush(false);
  }
  flush(true);
  in.release_vertices(0, in.vertex_count());
  centres = {};
  index = 0;
  std::uint64_t ignored = 0;
  for (std::uint64_t first = 0; first < n; first += part, ++index) {
    const PartFaces faces =
        part_faces(in, partner, first, std::min(part, n - first), corners, true, ignored);
    const PolygonMesh quads = part_all_quads(
        faces, midpoints, static_cast<VertexId>(in.vertex_count()),
        static_cast<VertexId>(in.vertex_count() + midpoints.size() + first_centre[index]),
        quad_options);
    for (FaceId f = 0; f < quads.face_count(); ++f) {
      const auto c = quads.face(f);
      if (c.size() == 4) {
        out.write_quad(c[0], c[1], c[2], c[3]);
      } else if (c.size() == 3) {
        out.write_triangle(c[0], c[1], c[2]);
      } else {
        throw std::logic_error("internal error: --all-quad made a face of " +
                               std::to_string(c.size()) + " corners");
      }
    }
  }
  out.commit();
  stats.temp_bytes += out.bytes_written();
}

// Objective::pairs: the sweep over the parts, the cut and the band repair.
void pair_maximum(const PlyTriangleStream& in, TempFaceArray& partner, std::uint64_t size,
                  const OutOfCoreOptions& options, OutOfCoreStats& stats, Stopwatch& clock) {
  PartsOutcome parts = run_parts(in, partner, size, options, stats);
  stats.unpaired_after_parts = count_pairing(partner, stats.triangles).second;
  stats.read_pair_seconds = clock.lap();
  const CutPairing cut = pair_open_edges(std::move(parts.open_edges));
  stats.cut_adjacencies = cut.adjacencies.size();
  stats.closed = cut.closed() && parts.inner_structural_cuts == 0;
  stats.cut_seconds = clock.lap();
  const RepairResult repaired = repair(parts, cut, partner);
  stats.pairs = count_pairing(partner, stats.triangles).first;
  stats.repaired = (repaired.unpaired_before - repaired.unpaired_after) / 2;
  stats.band_faces = parts.band.size();
  stats.band_graph_faces = repaired.band_graph_faces;
  stats.repair_radius = repaired.radius;
  stats.parts_certified =
      parts.certified && (repaired.unpaired_before == 0 || repaired.maximum_in_band_certified);
  stats.repair_seconds = clock.lap();
}

// The cost objectives' parts, cut and seams: the pairing in `partner`, the figures in `stats`.
void pair_at_cost(const PlyTriangleStream& in, TempFaceArray& partner, std::uint64_t size,
                  const std::string& output, const OutOfCoreOptions& options, OutOfCoreStats& stats,
                  Stopwatch& clock) {
  // The seam file is gone before the output is written and is smaller than it, so temp_bytes (the
  // largest the temporary files get together) stays the pairing's and the output's.
  CostPartsOutcome parts = run_parts_at_cost(in, partner, size, output, options, stats);
  stats.unpaired_after_parts = count_pairing(partner, stats.triangles).second;
  stats.read_pair_seconds = clock.lap();
  const CutPairing cut = pair_open_edges(std::move(parts.open_edges));
  stats.cut_adjacencies = cut.adjacencies.size();
  stats.closed = cut.closed() && parts.inner_structural_cuts == 0;
  stats.cut_seconds = clock.lap();
  std::pmr::vector<SeamFace> seam;  // on the default resource, which a program's pool serves
  parts.seam.read_all(seam);
  // A batch of the seam graph no larger than a part (whose pairing fits the limit beside another)
  // nor than the default batch: the seam step holds every seam face beside its batch's solve.
  const std::uint32_t batch =
      static_cast<std::uint32_t>(std::min<std::uint64_t>(size, SeamInput{}.batch_faces));
  const SeamResult seams =
      pair_seams({.faces = seam, .adjacencies = cut.adjacencies, .batch_faces = batch},
                 options.costs, options.threads);
  for (std::size_t i = 0; i < seam.size(); ++i) partner[seam[i].face] = seams.partner[i];
  stats.pairs = count_pairing(partner, stats.triangles).first;
  stats.seam_pairs = seams.pairs_across;
  stats.band_faces = seam.size();
  stats.seam_graph_faces = seams.seam_graph_faces;
  const Cost total = parts.units + seams.objective_change;
  stats.objective_total = double(total) / kDefaultCostScale;
  stats.costs_certified = parts.certified && seams.certified;
  if (options.costs.objective == Objective::quads) {
    stats.lower_bound = lower_bound_degrees(parts.units, seams.dual_lowering);
    stats.lower_bound_valid = stats.costs_certified;
    stats.optimality_certified =
        stats.costs_certified && 4 * total == 4 * parts.units - seams.dual_lowering;
  }
  stats.repair_seconds = clock.lap();
}

}  // namespace

OutOfCoreStats quad_out_of_core(const std::string& input, const std::string& output,
                                const OutOfCoreOptions& given) {
  // With all_quad every triangle left is split into quads anyway: quads then pairs the cheapest
  // maximum, as quality does (as quadrangulate does in memory).
  OutOfCoreOptions options = given;
  if (options.all_quad && options.costs.objective == Objective::quads) {
    options.costs.objective = Objective::quality;
  }
  Stopwatch clock;
  OutOfCoreStats stats;
  const PlyTriangleStream in(input);
  if (in.face_count() >= kNoFace) {
    throw FileError(
        input, 0,
        std::to_string(in.face_count()) + " faces: face ids are 32-bit, at most 4294967294 faces");
  }
  stats.vertices = in.vertex_count();
  stats.triangles = in.face_count();
  const std::uint64_t size = part_size(options, stats.triangles);
  stats.part_triangles = size;
  TempFaceArray partner(output, stats.triangles);
  stats.temp_bytes = partner.bytes();
  if (options.costs.objective != Objective::pairs) {
    pair_at_cost(in, partner, size, output, options, stats, clock);
  } else {
    pair_maximum(in, partner, size, options, stats, clock);
  }
  if (options.all_quad) {
    write_all_quad(in, partner, output, size, options, stats);
    stats.all_quad_seconds = clock.lap();
  } else {
    write_output(in, partner, output, size, stats);
    stats.write_seconds = clock.lap();
  }
  stats.perfect_certified = stats.closed && stats.triangles_left == 0;
  stats.total_seconds = clock.seconds();
  return stats;
}

}  // namespace petersen
