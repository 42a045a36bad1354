// The part, cut and repair steps on generated meshes cut into parts at awkward places, driven as
// a cluster would (every part alone, then the cut and the repair) and as the out-of-core sweep
// does (each part carrying the previous one's end); every pairing checked on its own and compared
// in size with the in-memory maximum.

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <set>
#include <stdexcept>

#include "petersen/generators/polygon_generators.hpp"
#include "petersen/generators/streamed_plate.hpp"
#include "petersen/generators/surface_generators.hpp"
#include "petersen/partition/partition.hpp"
#include "petersen/quadrangulate/quadrangulate.hpp"

namespace petersen {
namespace {

std::vector<VertexId> corners_of(const PolygonMesh& mesh) {
  return std::vector<VertexId>(mesh.corners.begin(), mesh.corners.end());
}

std::vector<VertexId> streamed_plate_corners(std::uint64_t triangles) {
  std::vector<VertexId> corners;
  for_each_plate_triangle(streamed_plate_of_size(triangles),
                          [&](VertexId a, VertexId b, VertexId c) {
                            corners.insert(corners.end(), {a, b, c});
                          });
  return corners;
}

// An open grid with holes, an isolated triangle and a strip of three: components of odd size.
std::vector<VertexId> open_mesh_with_odd_components() {
  std::vector<VertexId> corners = corners_of(punch_holes(open_grid(40, 30), 12, 7));
  const VertexId v = 100000;
  corners.insert(corners.end(), {v, v + 1, v + 2});
  corners.insert(corners.end(), {v + 3, v + 4, v + 5, v + 5, v + 4, v + 6, v + 5, v + 6, v + 7});
  return corners;
}

// The largest pairing, in memory: the front door's certified maximum.
std::uint64_t maximum_pairs(const std::vector<VertexId>& corners) {
  PolygonMesh mesh;
  const VertexId top = *std::max_element(corners.begin(), corners.end());
  mesh.positions.assign(top + 1, {0.0, 0.0, 0.0});
  mesh.corners.assign(corners.begin(), corners.end());
  QuadOptions options;
  options.objective = Objective::pairs;  // the maximum, which the parts are compared with
  options.sources = false;
  return quadrangulate(mesh, options).stats.pairs;
}

// Checks the pairing on its own: partners name each other, differ, and share an edge (two
// corners). Returns the pairs.
std::uint64_t checked_pairs(const std::vector<VertexId>& corners,
                            const std::vector<FaceId>& partner) {
  std::uint64_t pairs = 0;
  for (FaceId f = 0; f < partner.size(); ++f) {
    const FaceId p = partner[f];
    if (p == kNoFace) continue;
    EXPECT_LT(p, partner.size()) << "face " << f;
    if (p >= partner.size()) continue;
    EXPECT_EQ(partner[p], f) << "face " << f;
    EXPECT_NE(p, f);
    std::set<VertexId> a(corners.begin() + 3 * f, corners.begin() + 3 * f + 3);
    int shared = 0;
    for (int k = 0; k < 3; ++k) shared += a.count(corners[3 * std::size_t{p} + k]);
    EXPECT_EQ(shared, 2) << "faces " << f << " and " << p << " share no edge";
    pairs += f < p;
  }
  return pairs;
}

std::vector<std::uint64_t> part_starts(std::uint64_t n, std::vector<std::uint64_t> cuts) {
  cuts.insert(cuts.begin(), 0);
  cuts.push_back(n);
  return cuts;
}

struct Driven {
  std::vector<FaceId> partner;
  std::uint64_t unpaired_after_parts = 0;
  bool certified = true;
  CutPairing cut;
};

// Cut and repair over the parts' open edges and bands, as the drivers end.
void cut_and_repair(std::vector<OpenEdge> open, const std::vector<BandFace>& band, Driven& d) {
  d.cut = pair_open_edges(std::move(open));
  std::vector<FaceId> band_partner;
  for (const BandFace& face : band) band_partner.push_back(d.partner[face.face]);
  const RepairResult repair = repair_cuts({band, band_partner, d.cut.adjacencies});
  d.certified = d.certified && (repair.unpaired_before == 0 || repair.maximum_in_band_certified);
  for (std::size_t i = 0; i < band.size(); ++i) d.partner[band[i].face] = repair.partner[i];
}

// Every part alone, then the cut and the repair over all bands: what a cluster runs.
Driven parts_then_repair(const std::vector<VertexId>& corners,
                         const std::vector<std::uint64_t>& starts) {
  Driven d;
  d.partner.assign(corners.size() / 3, kNoFace);
  std::vector<OpenEdge> open;
  std::vector<BandFace> band;
  for (std::size_t i = 0; i + 1 < starts.size(); ++i) {
    const PartPairing part = pair_part({.first_face = static_cast<FaceId>(starts[i]),
                                        .corners = std::span<const VertexId>(corners).subspan(
                                            3 * starts[i], 3 * (starts[i + 1] - starts[i]))});
    d.certified = d.certified && part.maximum_certified;
    std::copy(part.partner.begin(), part.partner.end(), d.partner.begin() + starts[i]);
    d.unpaired_after_parts += part.unpaired.size();
    open.insert(open.end(), part.open_edges.begin(), part.open_edges.end());
    band.insert(band.end(), part.band.begin(), part.band.end());
  }
  cut_and_repair(std::move(open), band, d);
  return d;
}

// The parts in order, each carrying the previous part's last `carry` triangles, then the cut and
// the repair: what the out-of-core driver runs.
Driven sweep(const std::vector<VertexId>& corners, const std::vector<std::uint64_t>& starts,
             std::uint64_t carry) {
  Driven d;
  d.partner.assign(corners.size() / 3, kNoFace);
  std::vector<OpenEdge> open;
  std::vector<BandFace> band;
  for (std::size_t i = 0; i + 1 < starts.size(); ++i) {
    const std::uint64_t first = starts[i] - std::min(carry, starts[i] - (i ? starts[i - 1] : 0));
    const std::vector<FaceId> carried(d.partner.begin() + first, d.partner.begin() + starts[i]);
    const PartPairing part = pair_part(
        {static_cast<FaceId>(first),
         std::span<const VertexId>(corners).subspan(3 * first, 3 * (starts[i + 1] - first)),
         static_cast<std::uint32_t>(starts[i] - first), carried});
    d.certified = d.certified && part.maximum_certified;
    std::copy(part.partner.begin(), part.partner.end(), d.partner.begin() + first);
    open.insert(open.end(), part.open_edges.begin(), part.open_edges.end());
    band.insert(band.end(), part.band.begin(), part.band.end());
  }
  cut_and_repair(std::move(open), band, d);
  return d;
}

TEST(PartitionSteps, ClosedPlateInParallelPartsIsValidAndRepairGains) {
  const std::vector<VertexId> corners = streamed_plate_corners(20000);
  const std::uint64_t n = corners.size() / 3;
  const Driven d = parts_then_repair(corners, part_starts(n, {777, 5001, 5002, 9999, 14000}));
  EXPECT_TRUE(d.certified);
  EXPECT_TRUE(d.cut.closed());
  EXPECT_GT(d.cut.adjacencies.size(), 0u);
  const std::uint64_t pairs = checked_pairs(corners, d.partner);
  EXPECT_LE(pairs, maximum_pairs(corners));
  EXPECT_GE(2 * pairs, n - d.unpaired_after_parts);  // the repair never loses a pair
}

TEST(PartitionSteps, ClosedPlateSweepIsPerfect) {
  const std::vector<VertexId> corners = streamed_plate_corners(30000);
  const std::uint64_t n = corners.size() / 3;
  for (std::uint64_t carry : {64ull, 1000ull}) {
    const Driven d = sweep(corners, part_starts(n, {1, 2, 4095, 4097, 12345, 20001, 29000}), carry);
    EXPECT_TRUE(d.certified);
    const std::uint64_t pairs = checked_pairs(corners, d.partner);
    EXPECT_EQ(pairs, maximum_pairs(corners)) << "carry " << carry;
    EXPECT_EQ(2 * pairs, n) << "carry " << carry;
  }
}

TEST(PartitionSteps, OpenMeshWithOddComponentsReachesTheMaximum) {
  const std::vector<VertexId> corners = open_mesh_with_odd_components();
  const std::uint64_t n = corners.size() / 3;
  const std::uint64_t maximum = maximum_pairs(corners);
  const Driven whole = parts_then_repair(corners, part_starts(n, {}));
  EXPECT_EQ(checked_pairs(corners, whole.partner), maximum);
  EXPECT_FALSE(whole.cut.closed());
  const Driven swept = sweep(corners, part_starts(n, {333, 334, 1000, n - 3}), 400);
  EXPECT_EQ(checked_pairs(corners, swept.partner), maximum);
  const Driven parallel = parts_then_repair(corners, part_starts(n, {333, 334, 1000, n - 3}));
  EXPECT_LE(checked_pairs(corners, parallel.partner), maximum);
  EXPECT_GT(parallel.cut.boundary_edges, 0u);
}

TEST(PartitionSteps, OpenEdgesOfTwoPartsMeetInTheCut) {
  // Two triangles sharing edge {1, 2}, in different parts.
  const std::vector<VertexId> corners = {0, 1, 2, 2, 1, 3};
  const PartPairing a =
      pair_part({.first_face = 0, .corners = std::span<const VertexId>(corners).first(3)});
  const PartPairing b =
      pair_part({.first_face = 1, .corners = std::span<const VertexId>(corners).last(3)});
  EXPECT_EQ(a.open_edges.size(), 3u);
  EXPECT_EQ(a.unpaired, std::vector<FaceId>{0});
  std::vector<OpenEdge> open = a.open_edges;
  open.insert(open.end(), b.open_edges.begin(), b.open_edges.end());
  const CutPairing cut = pair_open_edges(open);
  ASSERT_EQ(cut.adjacencies.size(), 1u);
  EXPECT_EQ(cut.adjacencies[0], (CutAdjacency{0, 1, 1, 2}));
  EXPECT_EQ(cut.boundary_edges, 4u);
  std::vector<BandFace> band = a.band;
  band.insert(band.end(), b.band.begin(), b.band.end());
  const std::vector<FaceId> partner = {kNoFace, kNoFace};
  const RepairResult repair = repair_cuts({band, partner, cut.adjacencies});
  EXPECT_EQ(repair.partner, (std::vector<FaceId>{1, 0}));
  EXPECT_EQ(repair.augmenting_paths, 1u);
  EXPECT_TRUE(repair.maximum_in_band_certified);
}

TEST(PartitionSteps, DuplicateAndDegenerateRecordsAreNotPaired) {
  // The same triangle twice, in two parts: their edges are no adjacency.
  const std::vector<VertexId> corners = {0, 1, 2, 2, 1, 0};
  const PartPairing a =
      pair_part({.first_face = 0, .corners = std::span<const VertexId>(corners).first(3)});
  const PartPairing b =
      pair_part({.first_face = 1, .corners = std::span<const VertexId>(corners).last(3)});
  std::vector<OpenEdge> open = a.open_edges;
  open.insert(open.end(), b.open_edges.begin(), b.open_edges.end());
  const CutPairing cut = pair_open_edges(open);
  EXPECT_TRUE(cut.adjacencies.empty());
  EXPECT_EQ(cut.duplicate_edges, 3u);
  EXPECT_FALSE(cut.closed());
}

TEST(PartitionSteps, BadInputIsRefusedWithWhatAndWhere) {
  const std::vector<VertexId> bad = {0, 1, 0xFFFFFFFFu};
  try {
    pair_part({.first_face = 7, .corners = bad});
    FAIL() << "no error";
  } catch (const MeshError& e) {
    EXPECT_NE(std::string(e.what()).find("face 7"), std::string::npos) << e.what();
  }
  const std::vector<VertexId> ragged = {0, 1};
  EXPECT_THROW(pair_part({.corners = ragged}), std::invalid_argument);
  const std::vector<VertexId> two = {0, 1, 2, 2, 1, 3};
  const std::vector<FaceId> one_sided = {1};  // carried face 0 names 1, which is no carried face
  EXPECT_THROW(pair_part({0, two, 1, one_sided}), std::invalid_argument);
  const std::vector<BandFace> band(2);
  const std::vector<FaceId> partner(1, kNoFace);
  EXPECT_THROW(repair_cuts({band, partner, {}}), std::invalid_argument);
}

}  // namespace
}  // namespace petersen
