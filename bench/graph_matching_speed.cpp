// Matching of general graphs against LEMON, on the inputs graph users bring: minimum-cost perfect
// matching (min_cost_perfect_matching, one thread, its certificate verified) against LEMON's
// MaxWeightedPerfectMatching on k-nearest-neighbour graphs of random points, jittered
// triangulated grids (Euclidean lengths, rounded by integer_costs at the same power of two for
// both) and random graphs with a planted perfect matching (integer costs); maximum cardinality
// (maximum_matching, its Tutte–Berge witness verified) against LEMON's MaxMatching on grids and
// random graphs. Both solvers' times include building their own graph from the edge list; the
// optima (costs, sizes) are checked equal. One run each.
// Usage: petersen_graph_matching_speed [--small]   (--small: 2.5·10^5 nodes only)

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "petersen/graph/csr_graph.hpp"
#include "petersen/lemon_peer/lemon_peer.hpp"
#include "petersen/matching/augment.hpp"
#include "petersen/matching/min_cost_matching.hpp"
#include "petersen/matching/real_costs.hpp"
#include "petersen/matching/tutte_berge.hpp"
#include "petersen/matching/verify_min_cost.hpp"

namespace {

using namespace petersen;
using Edges = std::vector<std::array<NodeId, 2>>;

double seconds_of(const std::function<void()>& run) {
  const auto start = std::chrono::steady_clock::now();
  run();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Point {
  double x, y;
};

double length(const std::vector<Point>& p, std::array<NodeId, 2> e) {
  return std::hypot(p[e[0]].x - p[e[1]].x, p[e[0]].y - p[e[1]].y);
}

// Each point joined to its k nearest others (by a bucket grid of about k points per cell and
// rings around the point's cell until the k-th nearest is closer than the ring), duplicates
// removed. O(n k) expected.
Edges knn_edges(const std::vector<Point>& p, std::uint32_t k) {
  const auto n = static_cast<std::uint32_t>(p.size());
  const auto side = static_cast<std::uint32_t>(std::max(1.0, std::sqrt(n / double(k))));
  std::vector<std::vector<NodeId>> cells(std::size_t{side} * side);
  auto cell_of = [&](double c) { return std::min(side - 1, static_cast<std::uint32_t>(c * side)); };
  for (NodeId v = 0; v < n; ++v) cells[cell_of(p[v].y) * side + cell_of(p[v].x)].push_back(v);
  Edges edges;
  std::vector<std::pair<double, NodeId>> near;
  for (NodeId v = 0; v < n; ++v) {
    const int cx = static_cast<int>(cell_of(p[v].x)), cy = static_cast<int>(cell_of(p[v].y));
    for (int ring = 1;; ++ring) {
      near.clear();
      for (int y = std::max(0, cy - ring); y <= std::min<int>(side - 1, cy + ring); ++y)
        for (int x = std::max(0, cx - ring); x <= std::min<int>(side - 1, cx + ring); ++x)
          for (NodeId w : cells[y * side + x])
            if (w != v) near.push_back({length(p, {v, w}), w});
      if (near.size() < k && ring < static_cast<int>(side)) continue;
      std::partial_sort(near.begin(), near.begin() + std::min<std::size_t>(k, near.size()),
                        near.end());
      // The ring covers every point within `ring` cells' width: enough once the k-th is inside.
      if (near.size() >= k && near[k - 1].first > double(ring) / side && ring < int(side)) continue;
      for (std::size_t i = 0; i < std::min<std::size_t>(k, near.size()); ++i)
        edges.push_back({std::min(v, near[i].second), std::max(v, near[i].second)});
      break;
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

std::vector<Point> random_points(std::uint32_t n, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<Point> p(n);
  for (Point& q : p) q = {unit(random), unit(random)};
  return p;
}

// A side × side grid, each point moved by up to 0.3 of the spacing, each square split along a
// diagonal: a planar triangulation with 6 edges per inner node.
Edges triangulated_grid(std::uint32_t side, std::vector<Point>& p, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  p.resize(std::size_t{side} * side);
  Edges edges;
  for (std::uint32_t i = 0; i < side; ++i) {
    for (std::uint32_t j = 0; j < side; ++j) {
      const NodeId v = i * side + j;
      p[v] = {(j + jitter(random)) / side, (i + jitter(random)) / side};
      if (j + 1 < side) edges.push_back({v, v + 1});
      if (i + 1 < side) edges.push_back({v, v + side});
      if (i + 1 < side && j + 1 < side) edges.push_back({v, v + side + 1});
    }
  }
  return edges;
}

Edges grid(std::uint32_t rows, std::uint32_t columns) {
  Edges edges;
  for (std::uint32_t i = 0; i < rows; ++i) {
    for (std::uint32_t j = 0; j < columns; ++j) {
      const NodeId v = i * columns + j;
      if (j + 1 < columns) edges.push_back({v, v + 1});
      if (i + 1 < rows) edges.push_back({v, v + columns});
    }
  }
  return edges;
}

// m random edges (no loops) and, when `planted`, a random perfect matching besides.
Edges random_graph(std::uint32_t n, std::uint64_t m, bool planted, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  Edges edges;
  while (edges.size() < m) {
    const NodeId a = random() % n, b = random() % n;
    if (a != b) edges.push_back({a, b});
  }
  if (planted) {
    std::vector<NodeId> order(n);
    for (NodeId v = 0; v < n; ++v) order[v] = v;
    std::shuffle(order.begin(), order.end(), random);
    for (NodeId i = 0; i + 1 < n; i += 2) edges.push_back({order[i], order[i + 1]});
  }
  return edges;
}

std::vector<std::uint32_t> flat(const Edges& edges) {
  std::vector<std::uint32_t> ends;
  ends.reserve(2 * edges.size());
  for (auto [a, b] : edges) {
    ends.push_back(a);
    ends.push_back(b);
  }
  return ends;
}

void min_cost_row(const char* name, std::uint32_t n, const Edges& edges,
                  const std::vector<Cost>& costs) {
  MinCostResult ours;
  const double ours_s = seconds_of([&] {
    ours = min_cost_perfect_matching(CsrGraph::from_edges(n, edges), costs, {.threads = 1});
  });
  const CsrGraph g = CsrGraph::from_edges(n, edges);
  const CertificateCheck check = verify_min_cost_perfect_matching(
      n, g.edge_ends(), costs, ours.matching, ours.total_cost, ours.certificate);
  const std::vector<std::uint32_t> ends = flat(edges);
  std::vector<std::uint32_t> mate(n);
  std::int64_t lemon_total = 0;
  bool lemon_ok = false;
  const double lemon_s = seconds_of([&] {
    lemon_ok = lemon_peer::min_cost_perfect_matching(n, ends.data(),
                                                     static_cast<std::uint32_t>(edges.size()),
                                                     costs.data(), mate.data(), lemon_total);
  });
  const MinCostStats& s = ours.stats;
  std::printf(
      "| %s | %u | %zu | %.3f | %.3f | %.1f | %s | %.2f / %.2f | %.3f %% | %.2f |\n", name, n,
      edges.size(), ours_s, lemon_s, lemon_s / ours_s,
      check.ok() && lemon_ok && lemon_total == ours.total_cost ? "equal, certified" : "MISMATCH",
      s.init_seconds, s.search_seconds, 100.0 * s.free_after_init / n,
      double(s.nodes_labelled) / n);
  std::fflush(stdout);
}

void euclidean_row(const char* name, const std::vector<Point>& p, const Edges& edges) {
  std::vector<double> lengths(edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e) lengths[e] = length(p, edges[e]);
  const IntegerCosts costs = integer_costs(lengths);
  min_cost_row(name, static_cast<std::uint32_t>(p.size()), edges,
               std::vector<Cost>(costs.costs.begin(), costs.costs.end()));
}

void maximum_row(const char* name, std::uint32_t n, const Edges& edges) {
  MaximumMatchingResult ours;
  const double ours_s =
      seconds_of([&] { ours = maximum_matching(CsrGraph::from_edges(n, edges)); });
  const CsrGraph g = CsrGraph::from_edges(n, edges);
  const bool verified = verify_maximum_matching(g, ours.matching, ours.tutte_set).ok();
  const std::vector<std::uint32_t> ends = flat(edges);
  std::vector<std::uint32_t> mate(n);
  const double lemon_s = seconds_of([&] {
    lemon_peer::maximum_matching(n, ends.data(), static_cast<std::uint32_t>(edges.size()),
                                 mate.data());
  });
  std::uint32_t lemon_size = 0;
  for (NodeId v = 0; v < n; ++v) lemon_size += mate[v] != 0xFFFFFFFFu && ends[2 * mate[v]] == v;
  std::printf("| %s | %u | %zu | %.3f | %.3f | %.1f | %s |\n", name, n, edges.size(), ours_s,
              lemon_s, lemon_s / ours_s,
              verified && lemon_size == ours.size ? "equal, certified" : "MISMATCH");
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const bool small = argc > 1 && std::strcmp(argv[1], "--small") == 0;
  std::vector<std::uint32_t> sizes = {250'000};
  if (!small) sizes.push_back(1'000'000);
  std::printf("minimum-cost perfect matching (ours on 1 thread)\n\n");
  std::printf(
      "| graph | nodes | edges | ours s | LEMON s | LEMON ÷ ours | optimum | ours: start "
      "/ forest s | free after the start | forest labels per node |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---|---:|---:|---:|\n");
  for (std::uint32_t n : sizes) {
    // A k-nearest-neighbour graph may have an odd component (a few points close together, far
    // from the rest): the first seed from 17 on whose graph has a perfect matching.
    for (std::uint64_t seed = 17;; ++seed) {
      const std::vector<Point> points = random_points(n, seed);
      const Edges knn = knn_edges(points, 5);
      if (2 * maximum_matching(CsrGraph::from_edges(n, knn)).size != n) continue;
      euclidean_row("5-nearest neighbours", points, knn);
      break;
    }
    std::vector<Point> jittered;
    const auto side = static_cast<std::uint32_t>(std::sqrt(double(n)));
    const Edges triangulated = triangulated_grid(side, jittered, 19);
    euclidean_row("jittered triangulated grid", jittered, triangulated);
    const Edges random = random_graph(n, 3ull * n, true, 23);
    std::mt19937_64 draw(29);
    std::vector<Cost> costs(random.size());
    for (Cost& c : costs) c = static_cast<Cost>(draw() % 1'000'000);
    min_cost_row("random, 3n edges + a planted perfect matching", n, random, costs);
  }
  std::printf("\nmaximum cardinality\n\n");
  std::printf("| graph | nodes | edges | ours s | LEMON s | LEMON ÷ ours | size |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---|\n");
  for (std::uint32_t n : sizes) {
    const auto side = static_cast<std::uint32_t>(std::sqrt(double(n)));
    maximum_row("grid", side * side, grid(side, side));
    maximum_row("grid, odd sides", (side - 1) * (side + 1), grid(side - 1, side + 1));
    maximum_row("random, 3n edges", n, random_graph(n, 3ull * n, false, 31));
  }
  return 0;
}
