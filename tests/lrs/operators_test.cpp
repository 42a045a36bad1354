// The topological operators of the mutable triangulation: contraction, vertex split, flip, and
// the link condition on hand-made cases.

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <string>
#include <vector>

#include "edge_contraction.hpp"
#include "edge_flip.hpp"
#include "petersen/generators/polygon_generators.hpp"
#include "petersen/generators/surface_generators.hpp"
#include "petersen/mesh/mesh_report.hpp"
#include "petersen/testing/arbitrary.hpp"
#include "small_meshes.hpp"

namespace petersen::lrs {
namespace {

using testing::identical;
using testing::oriented_faces;

// The halfedge from a to b, or kNoHalfedge.
Halfedge find_halfedge(const Triangulation& tri, VertexId a, VertexId b) {
  Halfedge g = tri.out(a);
  do {
    if (tri.destination(g) == b) return g;
    g = tri.rotate(g);
  } while (g != tri.out(a));
  return kNoHalfedge;
}

TEST(Triangulation, BuildsFromMeshWithMeshIds) {
  const PolygonMesh mesh = testing::octahedron();
  const Triangulation tri = testing::from_triangles(mesh);
  EXPECT_EQ(tri.check(), "");
  EXPECT_EQ(tri.live_vertices(), 6u);
  EXPECT_EQ(tri.live_edges(), 12u);
  EXPECT_EQ(tri.live_faces(), 8u);
  EXPECT_EQ(tri.genus(), 0u);
  for (VertexId v = 0; v < 6; ++v) EXPECT_EQ(tri.degree(v), 4u);
  EXPECT_EQ(tri.to_mesh(mesh.positions).face_count(), 8u);
  EXPECT_EQ(oriented_faces(tri.to_mesh(mesh.positions)), oriented_faces(mesh));
}

// Spatial numbering renumbers vertices and faces inside, and gives the input's ids back: the same
// surface, the same oriented faces, the same genus; an error names the input's elements.
RC_GTEST_PROP(Triangulation, SpatialNumberingKeepsTheSurface, ()) {
  const auto genus = *rc::gen::inRange<std::uint32_t>(0, 6);
  const PolygonMesh mesh = random_closed_surface(genus, *rc::gen::inRange<std::uint32_t>(0, 300),
                                                 *rc::gen::inRange<std::uint32_t>(0, 300),
                                                 *rc::gen::arbitrary<std::uint64_t>());
  const Triangulation tri = testing::from_triangles(mesh, Triangulation::Numbering::spatial);
  RC_ASSERT(tri.check() == "");
  RC_ASSERT(tri.genus() == genus);
  RC_ASSERT(oriented_faces(tri.to_mesh(mesh.positions)) == oriented_faces(mesh));
  std::vector<VertexId> input(mesh.positions.size());
  for (VertexId v = 0; v < input.size(); ++v) input[v] = tri.input_vertex(v);
  std::sort(input.begin(), input.end());
  for (VertexId v = 0; v < input.size(); ++v) RC_ASSERT(input[v] == v);
}

TEST(Triangulation, SpatialNumberingNamesTheInputsElementsInErrors) {
  PolygonMesh open = testing::octahedron();
  open.corners.erase(open.corners.begin() + 9, open.corners.begin() + 12);
  std::string as_given, spatial;
  try {
    testing::from_triangles(open);
  } catch (const MeshError& e) {
    as_given = e.what();
  }
  try {
    testing::from_triangles(open, Triangulation::Numbering::spatial);
  } catch (const MeshError& e) {
    spatial = e.what();
  }
  EXPECT_NE(as_given, "");
  EXPECT_EQ(spatial, as_given);
  PolygonMesh out_of_range = testing::tetrahedron();
  out_of_range.corners[2 * 3 + 1] = 99;
  EXPECT_THROW(testing::from_triangles(out_of_range, Triangulation::Numbering::spatial), MeshError);
}

// From the dual: the same surface as from_mesh, numbered spatially, every vertex once.
RC_GTEST_PROP(Triangulation, FromDualKeepsTheSurface, ()) {
  const auto genus = *rc::gen::inRange<std::uint32_t>(0, 6);
  const PolygonMesh mesh = random_closed_surface(genus, *rc::gen::inRange<std::uint32_t>(0, 300),
                                                 *rc::gen::inRange<std::uint32_t>(0, 300),
                                                 *rc::gen::arbitrary<std::uint64_t>());
  const Triangulation tri = testing::from_dual_of(mesh);
  const Triangulation reference = testing::from_triangles(mesh);
  RC_ASSERT(tri.check() == "");
  RC_ASSERT(tri.genus() == genus);
  RC_ASSERT(tri.live_vertices() == reference.live_vertices());
  RC_ASSERT(tri.live_edges() == reference.live_edges());
  RC_ASSERT(tri.live_faces() == reference.live_faces());
  RC_ASSERT(oriented_faces(tri.to_mesh(mesh.positions)) == oriented_faces(mesh));
  std::vector<VertexId> input(mesh.positions.size());
  for (VertexId v = 0; v < input.size(); ++v) input[v] = tri.input_vertex(v);
  std::sort(input.begin(), input.end());
  for (VertexId v = 0; v < input.size(); ++v) RC_ASSERT(input[v] == v);
}

// A caller that has counted one component skips the count, and gets the same triangulation.
RC_GTEST_PROP(Triangulation, FromDualTrustsTheCallersCount, ()) {
  const PolygonMesh mesh = *petersen::testing::closed_triangulations_up_to(3);
  const CubicGraph dual = build_dual(mesh).graph;
  const auto build = [&](Triangulation::Connectivity connectivity) {
    return Triangulation::from_dual(mesh.positions, testing::flat_corners(mesh),
                                    {dual.node_edges().begin(), dual.node_edges().end()},
                                    {dual.edge_ends().begin(), dual.edge_ends().end()},
                                    connectivity);
  };
  const Triangulation counted = build(Triangulation::Connectivity::unknown);
  const Triangulation trusted = build(Triangulation::Connectivity::connected);
  RC_ASSERT(trusted.check() == "");
  RC_ASSERT(trusted.edge_capacity() == counted.edge_capacity());
  for (Halfedge h = 0; h < 2 * counted.edge_capacity(); ++h) {
    RC_ASSERT(trusted.origin(h) == counted.origin(h));
    RC_ASSERT(trusted.next(h) == counted.next(h));
  }
  for (VertexId v = 0; v < counted.vertex_capacity(); ++v) {
    RC_ASSERT(trusted.out(v) == counted.out(v));
    RC_ASSERT(trusted.input_vertex(v) == counted.input_vertex(v));
  }
}

// The corners are not read after corners_read, which is called once: a caller that overwrites
// (or frees) them there gets the same triangulation.
RC_GTEST_PROP(Triangulation, FromDualReadsNoCornerAfterSayingSo, ()) {
  const PolygonMesh mesh = *petersen::testing::closed_triangulations_up_to(3);
  const CubicGraph dual = build_dual(mesh).graph;
  std::vector<VertexId> corners = testing::flat_corners(mesh);
  int calls = 0;
  const Triangulation spoiled = Triangulation::from_dual(
      mesh.positions, corners, {dual.node_edges().begin(), dual.node_edges().end()},
      {dual.edge_ends().begin(), dual.edge_ends().end()}, Triangulation::Connectivity::unknown,
      [&] {
        ++calls;
        std::fill(corners.begin(), corners.end(), 0xFFFFFFFFu);
      });
  const Triangulation kept = testing::from_dual_of(mesh);
  RC_ASSERT(calls == 1);
  RC_ASSERT(spoiled.check() == "");
  RC_ASSERT(spoiled.edge_capacity() == kept.edge_capacity());
  for (Halfedge h = 0; h < 2 * kept.edge_capacity(); ++h) {
    RC_ASSERT(spoiled.origin(h) == kept.origin(h));
    RC_ASSERT(spoiled.next(h) == kept.next(h));
  }
  for (VertexId v = 0; v < kept.vertex_capacity(); ++v) {
    RC_ASSERT(spoiled.out(v) == kept.out(v));
    RC_ASSERT(spoiled.degree(v) == kept.degree(v));
  }
}

// Closed surfaces with vertices pinched (pinch_vertices merges two vertices' cones): from_dual
// refuses them, on one thread or two, naming a vertex that the surface check (inspect_mesh,
// which counts each vertex's fans its own way) finds pinched, and before corners_read; without a
// pinch it builds.
RC_GTEST_PROP(Triangulation, FromDualRefusesEveryPinchBeforeReadingOn, ()) {
  const PolygonMesh surface = random_closed_surface(
      *rc::gen::inRange<std::uint32_t>(0, 3), *rc::gen::inRange<std::uint32_t>(0, 200),
      *rc::gen::inRange<std::uint32_t>(0, 200), *rc::gen::arbitrary<std::uint64_t>());
  const PolygonMesh mesh = pinch_vertices(surface, *rc::gen::inRange<std::uint32_t>(0, 4),
                                          *rc::gen::arbitrary<std::uint64_t>());
  const MeshReport report = inspect_mesh(mesh);
  const CubicGraph dual = build_dual(mesh).graph;
  const std::vector<VertexId> corners = testing::flat_corners(mesh);
  int reads = 0;
  // The refusal on one thread and on two (the fans' walks split by vertex parity): the same.
  std::array<std::string, 2> refusals;
  for (std::uint32_t threads : {1u, 2u}) {
    try {
      Triangulation::from_dual(
          mesh.positions, corners, {dual.node_edges().begin(), dual.node_edges().end()},
          {dual.edge_ends().begin(), dual.edge_ends().end()}, Triangulation::Connectivity::unknown,
          [&] { ++reads; }, threads);
    } catch (const MeshError& e) {
      refusals[threads - 1] = e.what();
    }
  }
  RC_ASSERT(refusals[0] == refusals[1]);
  const std::string& refusal = refusals[0];
  RC_TAG(report.pinched_vertices.count);
  if (report.pinched_vertices.empty()) {
    RC_ASSERT(refusal == "");
    RC_ASSERT(reads == 2);
    return;
  }
  RC_ASSERT(reads == 0);
  bool named = false;
  for (const VertexId v : report.pinched_vertices.first) {
    named |= refusal ==
             "pinched vertex " + std::to_string(v) + " (its triangles form more than one fan)";
  }
  RC_ASSERT(named || report.pinched_vertices.count > report.pinched_vertices.first.size());
  RC_ASSERT(refusal.rfind("pinched vertex ", 0) == 0);
}

TEST(Triangulation, FromDualRefusesWhatLrsCannotTake) {
  // A refusal comes before corners_read: a caller that frees the corners there and falls back
  // to another method on MeshError reads them again.
  const auto message = [](const PolygonMesh& mesh, std::span<const VertexId> corners,
                          const CubicGraph& dual) -> std::string {
    bool read = false;
    try {
      Triangulation::from_dual(mesh.positions, corners,
                               {dual.node_edges().begin(), dual.node_edges().end()},
                               {dual.edge_ends().begin(), dual.edge_ends().end()},
                               Triangulation::Connectivity::unknown, [&] { read = true; });
    } catch (const MeshError& e) {
      EXPECT_FALSE(read) << e.what();
      return e.what();
    }
    EXPECT_TRUE(read);
    return "";
  };
  // Two tetrahedra apart.
  PolygonMesh two = testing::mesh_of(
      8, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}, {4, 6, 5}, {4, 5, 7}, {5, 6, 7}, {4, 7, 6}});
  EXPECT_EQ(message(two, testing::flat_corners(two), build_dual(two).graph),
            "2 components (triangles joined through edges)");
  // A cylinder of 2 x 4 squares whose end circles are closed by cones with one apex, vertex 12:
  // connected through edges, but 12 has two fans.
  PolygonMesh pinched;
  for (VertexId v = 0; v < 13; ++v) pinched.positions.push_back({double(v), 0, 0});
  for (VertexId row = 0; row < 2; ++row) {
    for (VertexId i = 0; i < 4; ++i) {
      const VertexId a = 4 * row + i, b = 4 * row + (i + 1) % 4, c = a + 4, d = b + 4;
      pinched.add_face(std::array<VertexId, 3>{a, b, d});
      pinched.add_face(std::array<VertexId, 3>{a, d, c});
    }
  }
  for (VertexId i = 0; i < 4; ++i) {
    pinched.add_face(std::array<VertexId, 3>{(i + 1) % 4, i, 12});
    pinched.add_face(std::array<VertexId, 3>{8 + i, 8 + (i + 1) % 4, 12});
  }
  EXPECT_EQ(message(pinched, testing::flat_corners(pinched), build_dual(pinched).graph),
            "pinched vertex 12 (its triangles form more than one fan)");
  // Triangle 0 of the tetrahedron turned over, its slots turned with it: the dual's arrays still
  // fit the triangles, but the two triangles of its edges run along them the same way.
  const PolygonMesh tetrahedron = testing::tetrahedron();
  const CubicGraph dual = build_dual(tetrahedron).graph;
  std::vector<VertexId> corners = testing::flat_corners(tetrahedron);
  std::swap(corners[1], corners[2]);
  std::pmr::vector<EdgeId> slots(dual.node_edges().begin(), dual.node_edges().end());
  std::swap(slots[0], slots[2]);
  bool read = false;
  EXPECT_THROW(Triangulation::from_dual(tetrahedron.positions, corners, std::move(slots),
                                        {dual.edge_ends().begin(), dual.edge_ends().end()},
                                        Triangulation::Connectivity::unknown, [&] { read = true; }),
               MeshError);
  EXPECT_FALSE(read);
  // Arrays of the wrong sizes, and an edge that is no side of its triangle.
  EXPECT_THROW(Triangulation::from_dual(tetrahedron.positions, corners, {}, {}),
               std::invalid_argument);
  std::pmr::vector<NodeId> ends(dual.edge_ends().begin(), dual.edge_ends().end());
  std::swap(ends[0], ends[3]);  // edge 0's first triangle no longer has it
  EXPECT_THROW(Triangulation::from_dual(tetrahedron.positions, testing::flat_corners(tetrahedron),
                                        {dual.node_edges().begin(), dual.node_edges().end()},
                                        std::move(ends)),
               std::invalid_argument);
}

TEST(Triangulation, RefusesPinchedVertexAndOpenSurface) {
  // Two tetrahedra sharing vertex 0: closed, but 0's link is two cycles.
  PolygonMesh pinched = testing::mesh_of(
      7, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}, {0, 5, 4}, {0, 4, 6}, {4, 5, 6}, {0, 6, 5}});
  EXPECT_THROW(testing::from_triangles(pinched), MeshError);
  PolygonMesh open = testing::tetrahedron();
  open.corners.resize(open.corners.size() - 3);
  EXPECT_THROW(testing::from_triangles(open), MeshError);
}

TEST(LinkCondition, TetrahedronHasNoContractibleEdge) {
  const Triangulation tri = testing::from_triangles(testing::tetrahedron());
  VertexMarks marks(tri.vertex_capacity());
  for (Halfedge h = 0; h < 2 * tri.edge_capacity(); ++h) {
    EXPECT_FALSE(is_contractible(tri, h, marks)) << "halfedge " << h;
  }
}

TEST(LinkCondition, OctahedronEdgesAreAllContractible) {
  const Triangulation tri = testing::from_triangles(testing::octahedron());
  VertexMarks marks(tri.vertex_capacity());
  for (Halfedge h = 0; h < 2 * tri.edge_capacity(); ++h) {
    EXPECT_TRUE(is_contractible(tri, h, marks)) << "halfedge " << h;
    Triangulation copy = tri;
    contract(copy, h);
    EXPECT_EQ(copy.check(), "");
    EXPECT_EQ(copy.live_vertices(), 5u);
    EXPECT_EQ(copy.genus(), 0u);
  }
}

TEST(LinkCondition, SeparatingThreeCycleBlocksItsEdges) {
  const Triangulation tri = testing::from_triangles(testing::stacked_tetrahedron());
  VertexMarks marks(tri.vertex_capacity());
  const auto on_cycle = [](VertexId v) { return v == 0 || v == 1 || v == 3; };
  for (Halfedge h = 0; h < 2 * tri.edge_capacity(); ++h) {
    const bool separating = on_cycle(tri.origin(h)) && on_cycle(tri.destination(h));
    EXPECT_EQ(is_contractible(tri, h, marks), !separating)
        << tri.origin(h) << "-" << tri.destination(h);
  }
  // Contracting the degree-3 vertex 4 away leaves the tetrahedron.
  Triangulation copy = tri;
  contract(copy, find_halfedge(copy, 0, 4));
  EXPECT_EQ(copy.check(), "");
  EXPECT_EQ(oriented_faces(copy.to_mesh(testing::tetrahedron().positions)),
            oriented_faces(testing::mesh_of(5, {{0, 2, 1}, {1, 2, 3}, {0, 3, 2}, {0, 1, 3}})));
}

TEST(LinkCondition, FlippabilityOnTheOctahedron) {
  const Triangulation tri = testing::from_triangles(testing::octahedron());
  // Flipping [0, 2] (faces 0-2-4 and 2-0-5) would join 4 and 5: not yet an edge, degrees 4.
  EXPECT_TRUE(is_flippable(tri, find_halfedge(tri, 0, 2)));
  const Triangulation tet = testing::from_triangles(testing::tetrahedron());
  EXPECT_FALSE(is_flippable(tet, 0));  // the apexes are adjacent already
}

RC_GTEST_PROP(Operators, ContractThenSplitRestoresTheExactTriangulation, ()) {
  const auto genus = *rc::gen::inRange<std::uint32_t>(0, 6);
  const auto seed = *rc::gen::arbitrary<std::uint64_t>();
  const Triangulation original =
      testing::from_triangles(random_closed_surface(genus, 60, 60, seed));
  Triangulation tri = original;
  VertexMarks marks(tri.vertex_capacity());
  std::mt19937_64 random(seed);
  // A chain of contractions at random edges, then the splits in reverse order.
  std::vector<ContractionRecord> stack;
  const auto steps = *rc::gen::inRange<std::uint32_t>(1, 40);
  for (std::uint32_t i = 0; i < steps; ++i) {
    const EdgeId e = std::uniform_int_distribution<EdgeId>(0, tri.edge_capacity() - 1)(random);
    if (!tri.edge_alive(e) || !is_contractible(tri, 2 * e + (i & 1), marks)) continue;
    stack.push_back(contract(tri, 2 * e + (i & 1)));
    RC_ASSERT(tri.check() == "");
    RC_ASSERT(tri.genus() == genus);
  }
  while (!stack.empty()) {
    split(tri, stack.back());
    stack.pop_back();
    RC_ASSERT(tri.check() == "");
  }
  RC_ASSERT(identical(tri, original));
}

RC_GTEST_PROP(Operators, FlipTwiceRestoresTheTriangulation, ()) {
  const auto genus = *rc::gen::inRange<std::uint32_t>(0, 6);
  const auto seed = *rc::gen::arbitrary<std::uint64_t>();
  const PolygonMesh mesh = random_closed_surface(genus, 40, 40, seed);
  const Triangulation original = testing::from_triangles(mesh);
  std::uint32_t flipped = 0;
  for (Halfedge h = 0; h < 2 * original.edge_capacity(); h += 7) {
    if (!is_flippable(original, h)) continue;
    Triangulation tri = original;
    const VertexId c = tri.apex(h), d = tri.apex(Triangulation::twin(h));
    flip(tri, h);
    RC_ASSERT(tri.check() == "");
    RC_ASSERT(tri.origin(h) == d && tri.destination(h) == c);
    RC_ASSERT(tri.genus() == genus);
    flip(tri, h);
    RC_ASSERT(tri.check() == "");
    RC_ASSERT(oriented_faces(tri.to_mesh(mesh.positions)) == oriented_faces(mesh));
    ++flipped;
  }
  RC_ASSERT(flipped > 0u);
}

}  // namespace
}  // namespace petersen::lrs
