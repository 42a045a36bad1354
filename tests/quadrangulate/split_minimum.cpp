#include "split_minimum.hpp"

#include <algorithm>
#include <limits>
#include <map>
#include <queue>
#include <set>
#include <utility>
#include <vector>

namespace petersen::testing {

namespace {

constexpr std::uint64_t kInfinite = std::numeric_limits<std::uint64_t>::max() / 4;

// The faces of the pairing, as vertex cycles, and which are kept as they are: polygons under
// keep_polygons, and faces repeating a vertex (no cut into quads of those repeats none).
struct PreSplitFaces {
  std::vector<std::vector<VertexId>> cycles;
  std::vector<bool> kept;
};

PreSplitFaces pre_split_faces(const PolygonMesh& input, const QuadResult& result,
                              bool keep_polygons, bool flips_allowed) {
  PreSplitFaces faces;
  std::set<std::pair<FaceId, FaceId>> seen;
  for (FaceId o = 0; o < result.sources.size(); ++o) {
    const auto [f, g] = result.sources[o];
    if (f == kNoFace || !seen.insert({f, g}).second) continue;
    if (flips_allowed && g == kNoFace && input.arity(f) == 3 && o < result.mesh.face_count()) {
      const auto out = result.mesh.face(o);
      auto input_vertex = [&](VertexId v) { return v < input.positions.size(); };
      if (out.size() == 4 && std::all_of(out.begin(), out.end(), input_vertex)) continue;
    }
    const auto t = input.face(f);
    std::vector<VertexId> cycle(t.begin(), t.end());
    if (g != kNoFace) {
      // The pair's quad: the four distinct vertices; only their count and edges matter here.
      const auto u = input.face(g);
      for (VertexId v : u)
        if (std::find(cycle.begin(), cycle.end(), v) == cycle.end()) {
          // Insert g's third vertex between the shared edge's ends, in t's cycle.
          for (std::size_t k = 0; k < 3; ++k) {
            const VertexId a = t[k], b = t[(k + 1) % 3];
            if (std::find(u.begin(), u.end(), a) != u.end() &&
                std::find(u.begin(), u.end(), b) != u.end()) {
              cycle = {a, v, b, t[(k + 2) % 3]};
              break;
            }
          }
        }
    }
    const bool repeats = std::set<VertexId>(cycle.begin(), cycle.end()).size() != cycle.size();
    faces.kept.push_back((keep_polygons && g == kNoFace && input.arity(f) != 3) || repeats);
    faces.cycles.push_back(std::move(cycle));
  }
  return faces;
}

// The split choices: graph edges (two faces change; the sink is node F), and hyperedges (the
// faces changed by an edge of three or more faces).
struct Choices {
  std::vector<std::vector<std::uint32_t>> neighbours;  // F + 1 nodes
  std::vector<std::vector<std::uint32_t>> hyperedges;
};

Choices split_choices(const PreSplitFaces& faces) {
  const std::uint32_t sink = static_cast<std::uint32_t>(faces.cycles.size());
  std::map<std::pair<VertexId, VertexId>, std::vector<std::uint32_t>> on_edge;
  for (std::uint32_t f = 0; f < sink; ++f) {
    const auto& c = faces.cycles[f];
    for (std::size_t k = 0; k < c.size(); ++k) {
      const VertexId a = c[k], b = c[(k + 1) % c.size()];
      on_edge[{std::min(a, b), std::max(a, b)}].push_back(f);
    }
  }
  Choices choices;
  choices.neighbours.resize(sink + 1);
  for (auto& [edge, along] : on_edge) {
    if (std::any_of(along.begin(), along.end(), [&](std::uint32_t f) { return faces.kept[f]; }))
      continue;
    // The faces on it an odd number of times are the ones a split changes.
    std::sort(along.begin(), along.end());
    std::vector<std::uint32_t> changed;
    for (std::size_t i = 0, j = 0; i < along.size(); i = j) {
      while (j < along.size() && along[j] == along[i]) ++j;
      if ((j - i) % 2 == 1) changed.push_back(along[i]);
    }
    if (changed.empty()) continue;
    if (along.size() >= 3) {
      choices.hyperedges.push_back(std::move(changed));
    } else if (changed.size() == 1) {
      choices.neighbours[changed[0]].push_back(sink);
      choices.neighbours[sink].push_back(changed[0]);
    } else {
      choices.neighbours[changed[0]].push_back(changed[1]);
      choices.neighbours[changed[1]].push_back(changed[0]);
    }
  }
  return choices;
}

std::vector<std::uint64_t> distances_from(const Choices& choices, std::uint32_t source) {
  std::vector<std::uint64_t> distance(choices.neighbours.size(), kInfinite);
  std::queue<std::uint32_t> queue;
  distance[source] = 0;
  queue.push(source);
  while (!queue.empty()) {
    const std::uint32_t v = queue.front();
    queue.pop();
    for (std::uint32_t w : choices.neighbours[v]) {
      if (distance[w] != kInfinite) continue;
      distance[w] = distance[v] + 1;
      queue.push(w);
    }
  }
  return distance;
}

// The least total distance of a pairing of all of `odd` (an even number of nodes), by a dynamic
// program over the subsets still to pair.
std::uint64_t least_pairing(const std::vector<std::uint32_t>& odd,
                            std::map<std::uint32_t, std::vector<std::uint64_t>>& distance_cache,
                            const Choices& choices) {
  const std::size_t t = odd.size();
  std::vector<std::vector<std::uint64_t>> d(t, std::vector<std::uint64_t>(t));
  for (std::size_t i = 0; i < t; ++i) {
    auto it = distance_cache.find(odd[i]);
    if (it == distance_cache.end())
      it = distance_cache.emplace(odd[i], distances_from(choices, odd[i])).first;
    for (std::size_t j = 0; j < t; ++j) d[i][j] = it->second[odd[j]];
  }
  const std::size_t full = (std::size_t{1} << t) - 1;
  std::vector<std::uint64_t> best(full + 1, kInfinite);  // best[m]: pairing the nodes not in m
  best[full] = 0;
  for (std::size_t m = full; m-- > 0;) {
    std::size_t i = 0;
    while (m >> i & 1) ++i;
    for (std::size_t j = i + 1; j < t; ++j) {
      if (m >> j & 1 || d[i][j] >= kInfinite) continue;
      const std::size_t next = m | std::size_t{1} << i | std::size_t{1} << j;
      best[m] = std::min(best[m], d[i][j] + best[next]);
    }
  }
  return best[0];
}

}  // namespace

SplitMinimum fewest_splits(const PolygonMesh& input, const QuadResult& result, bool keep_polygons,
                           bool flips_allowed, std::uint32_t most_odd_faces,
                           std::uint32_t most_hyperedges) {
  const PreSplitFaces faces = pre_split_faces(input, result, keep_polygons, flips_allowed);
  const Choices choices = split_choices(faces);
  const std::uint32_t sink = static_cast<std::uint32_t>(faces.cycles.size());
  if (choices.hyperedges.size() > most_hyperedges) return {};  // too_large
  // Components of the graph (the sink joins every face with a boundary edge).
  std::vector<std::uint32_t> component(sink + 1, sink + 1);
  for (std::uint32_t start = 0; start <= sink; ++start) {
    if (component[start] != sink + 1) continue;
    std::queue<std::uint32_t> queue;
    component[start] = start;
    queue.push(start);
    while (!queue.empty()) {
      const std::uint32_t v = queue.front();
      queue.pop();
      for (std::uint32_t w : choices.neighbours[v])
        if (component[w] == sink + 1) component[w] = start, queue.push(w);
    }
  }
  // Each subset of the hyperedges: feasible when every component without the sink has an even
  // number of odd faces; its least splits then by the pairings of each component's odd faces.
  std::map<std::uint32_t, std::vector<std::uint64_t>> distance_cache;
  SplitMinimum answer{SplitMinimum::Status::infeasible, kInfinite, kInfinite};
  bool past_limits = false;
  const std::size_t subsets = std::size_t{1} << choices.hyperedges.size();
  for (std::size_t s = 0; s < subsets; ++s) {
    std::vector<bool> odd(sink, false);
    for (std::uint32_t f = 0; f < sink; ++f)
      odd[f] = !faces.kept[f] && faces.cycles[f].size() % 2 == 1;
    std::uint64_t splits = 0;
    for (std::size_t h = 0; h < choices.hyperedges.size(); ++h) {
      if (!(s >> h & 1)) continue;
      ++splits;
      for (std::uint32_t f : choices.hyperedges[h]) odd[f] = !odd[f];
    }
    std::map<std::uint32_t, std::vector<std::uint32_t>> odd_by_component;
    for (std::uint32_t f = 0; f < sink; ++f)
      if (odd[f]) odd_by_component[component[f]].push_back(f);
    bool feasible = true, within_limits = true;
    for (auto& [root, members] : odd_by_component) {
      if (members.size() % 2 == 1) {
        if (component[sink] != root) feasible = false;
        members.push_back(sink);
      }
      within_limits = within_limits && members.size() <= most_odd_faces;
    }
    if (!feasible) continue;
    if (!within_limits) {
      past_limits = true;
      continue;
    }
    for (const auto& [root, members] : odd_by_component)
      splits += least_pairing(members, distance_cache, choices);
    if (s == 0) answer.splits_without_non_manifold = splits;
    if (splits < answer.splits) answer.status = SplitMinimum::Status::found, answer.splits = splits;
  }
  // A feasible subset not searched may hold a smaller minimum: then nothing is known but that.
  if (past_limits) return {SplitMinimum::Status::too_large, 0, 0};
  if (answer.status == SplitMinimum::Status::infeasible) answer.splits = 0;
  return answer;
}

}  // namespace petersen::testing
