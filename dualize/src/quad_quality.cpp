#include "petersen/dualize/quad_quality.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "petersen/graph/parallel.hpp"
#include "petersen/mesh/vec3.hpp"

namespace petersen {

namespace {

using vec3::cross, vec3::dot, vec3::sub;
using Vec = vec3::Vec3;

// p without its component along the unit vector n.
Vec project(const Vec& p, const Vec& n) {
  const double along = dot(p, n);
  return {p[0] - along * n[0], p[1] - along * n[1], p[2] - along * n[2]};
}

}  // namespace

double quad_corner_deviation(const Vec& a, const Vec& b, const Vec& c, const Vec& d) {
  const Vec corners[4] = {a, b, c, d};
  for (const Vec& p : corners)
    for (double x : p)
      if (!std::isfinite(x)) return kDegenerateQuadCost;
  Vec n = cross(sub(c, a), sub(d, b));
  const double length = std::sqrt(dot(n, n));
  // Also catches an overflowing cross product (length infinite).
  if (!(length > 0) || !std::isfinite(length)) return kDegenerateQuadCost;
  for (double& x : n) x /= length;
  // Each corner's angle as (cos, sin) times a positive factor: counter-clockwise about n from
  // to_next to to_prev.
  double along[4], across[4];
  for (int k = 0; k < 4; ++k) {
    const Vec& p = corners[k];
    const Vec to_next = project(sub(corners[(k + 1) % 4], p), n);
    const Vec to_prev = project(sub(corners[(k + 3) % 4], p), n);
    if (dot(to_next, to_next) == 0 || dot(to_prev, to_prev) == 0) return kDegenerateQuadCost;
    along[k] = dot(to_next, to_prev);
    across[k] = dot(n, cross(to_next, to_prev));
  }
  // |90° − θ| in degrees, θ in [0°, 360°): the interior angle of a quad whose corners run
  // counter-clockwise about n, as (c − a) × (d − b) makes them.
  auto deviation = [&](int k) {
    double theta = std::atan2(across[k], along[k]) * 180.0 / std::numbers::pi;
    if (theta < 0) theta += 360.0;
    if (theta >= 360.0) theta = 0;  // rounding reached the full turn
    return std::abs(90.0 - theta);
  };
  // The worst corner is found without trigonometry: the diamond angle (x, y) -> [0, 4) rises
  // with θ and is symmetric about 90° like θ itself, so |1 − diamond| orders the corners as
  // |90° − θ| does; only the worst corner's atan2 is taken. Where rounding wraps θ to 0 the
  // order may differ, and all four are measured.
  auto diamond = [](double x, double y) {
    if (x == 0 && y == 0) return 0.0;
    if (y >= 0) return x >= 0 ? y / (x + y) : 1 - x / (y - x);
    return x < 0 ? 2 - y / (-x - y) : 3 + x / (x - y);
  };
  int worst = 0;
  double worst_key = -1;
  for (int k = 0; k < 4; ++k) {
    const double key = std::abs(1 - diamond(along[k], across[k]));
    if (key > worst_key) worst_key = key, worst = k;
  }
  double theta = std::atan2(across[worst], along[worst]) * 180.0 / std::numbers::pi;
  if (theta < 0) theta += 360.0;
  if (theta < 360.0 && worst_key >= 0) return std::abs(90.0 - theta);
  // A wrapped worst corner, or no corner's angle defined (NaN from overflowing products, which
  // std::max skips): all four are measured.
  double deviation_max = 0;
  for (int k = 0; k < 4; ++k) deviation_max = std::max(deviation_max, deviation(k));
  return deviation_max;
}

std::pmr::vector<double> pairable_edge_quality(const PairableGraph& graph, const PolygonMesh& mesh,
                                               std::uint32_t threads,
                                               std::pmr::memory_resource* memory) {
  std::pmr::vector<double> degrees(graph.edge_count(), memory);
  const auto& p = mesh.positions;
  auto other_end = [&](EdgeId e, NodeId v) {
    const std::size_t at = 2 * std::size_t{e};
    return graph.edge_ends[at] == v ? graph.edge_ends[at + 1] : graph.edge_ends[at];
  };
  // Reaching the fourth corner's position, through the neighbour's face, is a chain of random
  // reads that dominates the measure on large meshes: a node's edges' ends are fetched 24 nodes
  // ahead, its neighbours' faces 16 ahead, their corners' positions 8 ahead. Inlined by force:
  // GCC 12 takes a function whose only effect is prefetching for one without effects and deletes
  // the calls.
  enum class Ahead { ends, faces, positions };
  auto prefetch_edge = [&](NodeId v, EdgeId e, Ahead what) __attribute__((always_inline)) {
    if (e == kNoEdge) return;
    if (what == Ahead::ends) {
      __builtin_prefetch(&graph.edge_ends[2 * std::size_t{e}]);
      return;
    }
    const auto face = mesh.face(graph.face_of(other_end(e, v)));  // a triangle: a node
    if (what == Ahead::faces) {
      __builtin_prefetch(face.data());
      return;
    }
    __builtin_prefetch(p[face[0]].data());
    __builtin_prefetch(p[face[1]].data());
    __builtin_prefetch(p[face[2]].data());
  };
  auto prefetch = [&](NodeId v, Ahead what) __attribute__((always_inline)) {
    const EdgeId* edges = &graph.node_edges[3 * std::size_t{v}];
    prefetch_edge(v, edges[0], what);
    prefetch_edge(v, edges[1], what);
    prefetch_edge(v, edges[2], what);
  };
  // Each edge is measured once, by the end whose face is lower, so the blocks of nodes write
  // disjoint entries and can run on the threads.
  constexpr NodeId kBlock = 1 << 16;
  run_parallel(threads, (graph.node_count + kBlock - 1) / kBlock, [&](std::uint32_t block) {
    const NodeId end = std::min(graph.node_count, (block + 1) * kBlock);
    for (NodeId v = block * kBlock; v < end; ++v) {
      if (v + 24 < end) prefetch(v + 24, Ahead::ends);
      if (v + 16 < end) prefetch(v + 16, Ahead::faces);
      if (v + 8 < end) prefetch(v + 8, Ahead::positions);
      for (int k = 0; k < 3; ++k) {
        const EdgeId e = graph.node_edges[3 * std::size_t{v} + k];
        if (e == kNoEdge) continue;
        const NodeId w = other_end(e, v);
        // In the lower face's orientation, as the output quad: the same rounding as measuring it.
        if (graph.face_of(w) < graph.face_of(v)) continue;
        const auto t1 = mesh.face(graph.face_of(v));
        const auto t2 = mesh.face(graph.face_of(w));
        const VertexId a = t1[k], b = t1[(k + 1) % 3], c = t1[(k + 2) % 3];
        const VertexId d = t2[0] != a && t2[0] != b   ? t2[0]
                           : t2[1] != a && t2[1] != b ? t2[1]
                                                      : t2[2];
        degrees[e] = quad_corner_deviation(p[a], p[d], p[b], p[c]);
      }
    }
  });
  return degrees;
}

std::vector<double> quad_costs(const PolygonMesh& mesh) {
  std::vector<double> costs;
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    if (mesh.arity(f) != 4) continue;
    const auto q = mesh.face(f);
    costs.push_back(quad_corner_deviation(mesh.positions[q[0]], mesh.positions[q[1]],
                                          mesh.positions[q[2]], mesh.positions[q[3]]));
  }
  return costs;
}

QualityFigures quality_figures(std::vector<double> costs) {
  return quality_figures_in_place(costs);
}

QualityFigures quality_figures_in_place(std::span<double> costs) {
  QualityFigures figures;
  figures.quads = costs.size();
  if (costs.empty()) return figures;
  for (double c : costs) {
    figures.total += c;
    figures.nonconvex += c > 90;
  }
  // Nearest rank: the smallest cost with at least p of them at most, the k-th smallest. Two
  // selections, O(q), where a sort of a large mesh's costs is a visible part of a whole
  // `petersen quad` run; the p95 selection only looks above the median.
  auto rank_index = [&](double p) {
    const auto k = static_cast<std::size_t>(std::ceil(p * double(costs.size())));
    return std::max<std::size_t>(k, 1) - 1;
  };
  const std::size_t median = rank_index(0.5), p95 = rank_index(0.95);
  std::nth_element(costs.begin(), costs.begin() + median, costs.end());
  figures.median = costs[median];
  std::nth_element(costs.begin() + median, costs.begin() + p95, costs.end());
  figures.p95 = costs[p95];
  return figures;
}

std::string describe(const QualityFigures& f) {
  char line[200];
  std::snprintf(line, sizeof line,
                "%llu quads, worst corner median %.1f\xc2\xb0, p95 %.1f\xc2\xb0, %llu non-convex, "
                "total %.1f\xc2\xb0",
                static_cast<unsigned long long>(f.quads), f.median, f.p95,
                static_cast<unsigned long long>(f.nonconvex), f.total);
  return line;
}

}  // namespace petersen
