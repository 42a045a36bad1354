// The mesh front door on every kind of mesh: closed, open, polygons, non-manifold edges, flipped
// faces, several components; every answer checked by result_check (independent of the code).

#include "petersen/quadrangulate/quadrangulate.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <random>

#include "petersen/dualize/surface_generators.hpp"
#include "petersen/lemon_peer/lemon_peer.hpp"
#include "result_check.hpp"

namespace petersen {
namespace {

using testing::check_quad_result;

constexpr PeerMatcher kLemon = &lemon_peer::maximum_matching;

constexpr Algorithm kAlgorithms[] = {Algorithm::sg, Algorithm::ps,    Algorithm::ds,
                                     Algorithm::gw, Algorithm::frink, Algorithm::lemon,
                                     Algorithm::lrs};

PolygonMesh mesh_of(std::vector<std::array<double, 3>> positions,
                    std::vector<std::vector<VertexId>> faces) {
  PolygonMesh mesh;
  for (const auto& p : positions) mesh.positions.push_back(p);
  for (const auto& f : faces) mesh.add_face(f);
  return mesh;
}

void expect_correct(const PolygonMesh& mesh, bool all_quad = false) {
  for (Algorithm algorithm : kAlgorithms) {
    SCOPED_TRACE(std::string(to_string(algorithm)));
    const QuadResult result =
        quadrangulate(mesh, {.algorithm = algorithm, .all_quad = all_quad, .peer = kLemon});
    EXPECT_TRUE(result.stats.maximum_certified);
    EXPECT_EQ(check_quad_result(mesh, result, all_quad, algorithm == Algorithm::lrs), "");
  }
}

// A square of two triangles, a lone triangle beside it, and a quad: one pair, one left, one kept.
TEST(Quadrangulate, PairsWhatItCanAndKeepsTheRest) {
  const PolygonMesh mesh = mesh_of({{0, 0, 0},
                                    {1, 0, 0},
                                    {1, 1, 0},
                                    {0, 1, 0},
                                    {2, 0, 0},
                                    {3, 0, 0},
                                    {3, 1, 0},
                                    {2, 1, 0},
                                    {5, 0, 0}},
                                   {{0, 1, 2}, {0, 2, 3}, {4, 5, 6, 7}, {5, 8, 6}});
  const QuadResult result = quadrangulate(mesh);
  EXPECT_EQ(result.stats.pairs, 1u);
  EXPECT_EQ(result.stats.triangles_left, 1u);
  EXPECT_EQ(result.stats.polygons_kept, 1u);
  EXPECT_EQ(result.stats.cuts.by_cause[int(CutCause::polygon)], 1u);
  ASSERT_EQ(result.mesh.face_count(), 3u);
  const std::vector<VertexId> quad(result.mesh.face(0).begin(), result.mesh.face(0).end());
  // Triangle 0 = (0, 1, 2) meets triangle 1 across 2 -> 0; the quad starts there, in 0's order.
  EXPECT_EQ(quad, (std::vector<VertexId>{2, 3, 0, 1}));
  expect_correct(mesh);
}

// Three triangles on one edge: no pair crosses it.
TEST(Quadrangulate, NeverPairsAcrossANonManifoldEdge) {
  const PolygonMesh mesh = mesh_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}},
                                   {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
  const QuadResult result = quadrangulate(mesh);
  EXPECT_EQ(result.stats.pairs, 0u);
  EXPECT_EQ(result.stats.cuts.by_cause[int(CutCause::non_manifold)], 1u);
  expect_correct(mesh);
}

// A star of triangles whose maximum matching leaves some unpaired: the witness proves it.
TEST(Quadrangulate, CertifiesAMaximumThatIsNotPerfect) {
  // Triangle 0 in the middle, three triangles on its sides: only one of them can pair with it.
  const PolygonMesh mesh =
      mesh_of({{0, 0, 0}, {2, 0, 0}, {1, 2, 0}, {1, -1, 0}, {2.5, 1.5, 0}, {-0.5, 1.5, 0}},
              {{0, 1, 2}, {1, 0, 3}, {2, 1, 4}, {0, 2, 5}});
  const QuadResult result = quadrangulate(mesh);
  EXPECT_EQ(result.stats.pairs, 1u);
  EXPECT_EQ(result.stats.triangles_left, 2u);
  EXPECT_EQ(result.tutte_set.size(), 1u);  // the middle triangle
  expect_correct(mesh);
  expect_correct(mesh, /*all_quad=*/true);
}

TEST(Quadrangulate, RefusesCornersOutOfRangeAndShortFaces) {
  PolygonMesh bad = mesh_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 7}});
  EXPECT_THROW(quadrangulate(bad), MeshError);
  bad = mesh_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1}});
  EXPECT_THROW(quadrangulate(bad), MeshError);
}

// A closed mesh takes the fast path: every triangle paired by every algorithm.
TEST(Quadrangulate, ClosedMeshesArePerfect) {
  const PolygonMesh mesh = to_polygon_mesh(random_closed_surface(2, 40, 200, 5));
  for (Algorithm algorithm : kAlgorithms) {
    const QuadResult result = quadrangulate(mesh, {.algorithm = algorithm, .peer = kLemon});
    EXPECT_EQ(result.stats.triangles_left, 0u) << to_string(algorithm);
    EXPECT_EQ(result.stats.pairs, mesh.face_count() / 2);
  }
  expect_correct(mesh);
}

// Random damage to a closed surface: holes, polygons, fins, flipped faces, a second component.
PolygonMesh damaged_surface(std::uint32_t genus, std::uint64_t seed, bool second_component) {
  const TriangleMesh closed = random_closed_surface(genus, 10 + seed % 30, 100, seed);
  std::mt19937_64 random(seed);
  PolygonMesh mesh;
  mesh.positions = closed.positions;
  std::vector<std::uint8_t> taken(closed.triangles.size(), 0);
  for (FaceId t = 0; t < closed.triangles.size(); ++t) {
    if (taken[t]) continue;
    auto tri = closed.triangles[t];
    const std::uint64_t roll = random() % 100;
    if (roll < 8) continue;                    // a hole
    if (roll < 12) std::swap(tri[0], tri[1]);  // flipped
    if (roll < 20 && t + 1 < closed.triangles.size() && !taken[t + 1]) {
      // A quad, when the next triangle shares an edge with this one.
      const auto& u = closed.triangles[t + 1];
      for (int k = 0; k < 3; ++k) {
        const VertexId a = tri[k], b = tri[(k + 1) % 3];
        for (int j = 0; j < 3; ++j) {
          if (u[j] == b && u[(j + 1) % 3] == a && !taken[t + 1]) {
            const std::array<VertexId, 4> quad{a, u[(j + 2) % 3], b, tri[(k + 2) % 3]};
            mesh.add_face(quad);
            taken[t + 1] = 1;
          }
        }
      }
      if (taken[t + 1]) continue;
    }
    mesh.add_face(tri);
    if (roll >= 97) {
      // A fin: a third triangle on the edge (tri[0], tri[1]).
      const VertexId apex = static_cast<VertexId>(mesh.positions.size());
      mesh.positions.push_back({0.5, 0.5, 9.0 + double(t)});
      const std::array<VertexId, 3> fin{tri[0], tri[1], apex};
      mesh.add_face(fin);
    }
  }
  if (second_component) {
    const TriangleMesh other = random_closed_surface(0, 5, 20, seed + 1);
    const VertexId offset = static_cast<VertexId>(mesh.positions.size());
    for (const auto& p : other.positions) mesh.positions.push_back({p[0] + 50, p[1], p[2]});
    for (auto tri : other.triangles) {
      for (VertexId& v : tri) v += offset;
      mesh.add_face(tri);
    }
  }
  return mesh;
}

RC_GTEST_PROP(Quadrangulate, MaximumAndCertifiedOnDamagedSurfaces, ()) {
  const auto genus = *rc::gen::inRange<std::uint32_t>(0, 3);
  const auto seed = *rc::gen::inRange<std::uint64_t>(0, 1u << 30);
  const bool second = *rc::gen::arbitrary<bool>();
  const bool all_quad = *rc::gen::arbitrary<bool>();
  const PolygonMesh mesh = damaged_surface(genus, seed, second);
  const Algorithm algorithm =
      *rc::gen::elementOf(std::vector<Algorithm>(std::begin(kAlgorithms), std::end(kAlgorithms)));
  QuadResult result;
  try {
    result = quadrangulate(
        mesh, {.algorithm = algorithm, .seed = seed, .all_quad = all_quad, .peer = kLemon});
  } catch (const MeshError& e) {
    // all_quad may find a left triangle with nothing to reach; nothing else may fail.
    RC_ASSERT(all_quad);
    RC_ASSERT(std::string(e.what()).find("--all-quad") != std::string::npos);
    result = quadrangulate(mesh, {.algorithm = algorithm, .seed = seed, .peer = kLemon});
    RC_ASSERT(result.stats.triangles_left > 0);
    RC_TAG("all-quad refused");
    return;
  }
  RC_ASSERT(result.stats.maximum_certified);
  RC_CLASSIFY(result.stats.triangles_left > 0, "some left");
  RC_CLASSIFY(result.stats.added_vertices > 0, "split");
  const std::string problem =
      check_quad_result(mesh, result, all_quad, algorithm == Algorithm::lrs);
  RC_LOG() << problem;
  RC_ASSERT(problem.empty());
}

}  // namespace
}  // namespace petersen
