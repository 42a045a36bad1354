#include "simplify.hpp"

#include <functional>
#include <queue>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "edge_contraction.hpp"

namespace petersen::bench {

namespace {

using lrs::Halfedge;
using lrs::Triangulation;

double squared_length(const Positions& positions, VertexId a, VertexId b) {
  double sum = 0;
  for (int d = 0; d < 3; ++d)
    sum += (positions[a][d] - positions[b][d]) * (positions[a][d] - positions[b][d]);
  return sum;
}

}  // namespace

PolygonMesh simplify(const PolygonMesh& mesh, std::uint64_t target_triangles) {
  Triangulation tri = Triangulation::from_mesh(mesh);
  Positions positions = mesh.positions;
  lrs::VertexMarks marks(tri.vertex_capacity());
  // Min-heap of (squared length when pushed, edge); an entry whose length is stale is re-pushed.
  using Entry = std::pair<double, EdgeId>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  auto length_of = [&](EdgeId e) {
    return squared_length(positions, tri.origin(2 * e), tri.destination(2 * e));
  };
  for (EdgeId e = 0; e < tri.edge_capacity(); ++e)
    if (tri.edge_alive(e)) queue.push({length_of(e), e});

  while (tri.live_faces() > target_triangles) {
    if (queue.empty()) {
      throw std::runtime_error("simplify: no contractible edge left at " +
                               std::to_string(tri.live_faces()) + " triangles");
    }
    const auto [length, e] = queue.top();
    queue.pop();
    if (!tri.edge_alive(e)) continue;
    if (const double now = length_of(e); now != length) {
      queue.push({now, e});
      continue;
    }
    const Halfedge h = 2 * e;
    if (!lrs::is_contractible(tri, h, marks)) continue;
    const VertexId u = tri.origin(h), v = tri.destination(h);
    for (int d = 0; d < 3; ++d) positions[u][d] = (positions[u][d] + positions[v][d]) / 2;
    lrs::contract(tri, h);
    // u's edges changed length (and their neighbourhoods): queue them again.
    const Halfedge first = tri.out(u);
    Halfedge around = first;
    do {
      queue.push({length_of(Triangulation::edge(around)), Triangulation::edge(around)});
      around = tri.rotate(around);
    } while (around != first);
  }

  // Keep only the referenced vertices, numbered in order of first use.
  const PolygonMesh simplified = tri.to_mesh(positions);
  std::vector<VertexId> renumbered(simplified.positions.size(), kNoNode);
  PolygonMesh compact;
  compact.corners.reserve(simplified.corners.size());
  for (const VertexId corner : simplified.corners) {
    if (renumbered[corner] == kNoNode) {
      renumbered[corner] = static_cast<VertexId>(compact.positions.size());
      compact.positions.push_back(simplified.positions[corner]);
    }
    compact.corners.push_back(renumbered[corner]);
  }
  return compact;
}

}  // namespace petersen::bench
