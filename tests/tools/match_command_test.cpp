// `petersen match` end to end: files written, the tool run, its output read back and checked
// against the input edges (each written line an input edge, no node twice, the right size).

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "peers.hpp"
#include "petersen/generators/graph_generators.hpp"

namespace petersen {
namespace {

namespace fs = std::filesystem;

class MatchCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("petersen-match-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  // Runs the tool; its exit code, with stderr in err_.
  int run(const std::string& arguments) {
    const std::string command = std::string(PETERSEN_BINARY) + " match " + arguments + " >" +
                                path("stdout") + " 2>" + path("stderr");
    const int status = std::system(command.c_str());
    err_ = read(path("stderr"));
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

  static std::string read(const std::string& file) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }
  static void write(const std::string& file, const std::string& text) {
    std::ofstream(file) << text;
  }

  fs::path dir_;
  std::string err_;
};

// The size of the matching in `output` (lines "u v" in ids from first_id), or -1 when a line is
// not an edge of `edges` (counted with multiplicity) or a node is matched twice.
long long read_back(const std::string& output, std::uint32_t node_count,
                    const testing::EdgeList& edges, std::uint32_t first_id) {
  using Pair = std::pair<long long, long long>;
  std::vector<Pair> input, written;
  for (auto [a, b] : edges) input.push_back({std::min(a, b), std::max(a, b)});
  std::vector<char> matched(node_count, 0);
  std::istringstream in(output);
  long long u = 0, v = 0;
  while (in >> u >> v) {
    u -= first_id;
    v -= first_id;
    if (u < 0 || v < 0 || u >= node_count || v >= node_count || matched[u] || matched[v]) {
      return -1;
    }
    matched[u] = matched[v] = 1;
    written.push_back({std::min(u, v), std::max(u, v)});
  }
  if (!in.eof()) return -1;
  // Every written edge is an input edge, as many times as the input has it at most.
  std::sort(input.begin(), input.end());
  std::sort(written.begin(), written.end());
  if (!std::includes(input.begin(), input.end(), written.begin(), written.end())) return -1;
  return static_cast<long long>(written.size());
}

std::string dimacs(std::uint32_t n, const testing::EdgeList& edges) {
  std::string text = "c written by the test\np edge " + std::to_string(n) + " " +
                     std::to_string(edges.size()) + "\n";
  for (auto [a, b] : edges)
    text += "e " + std::to_string(a + 1) + " " + std::to_string(b + 1) + "\n";
  return text;
}

std::string edge_list(std::uint32_t n, const testing::EdgeList& edges) {
  std::string text =
      "# nodes " + std::to_string(n) + " edges " + std::to_string(edges.size()) + "\n";
  for (auto [a, b] : edges) text += std::to_string(a) + " " + std::to_string(b) + "\n";
  return text;
}

TEST_F(MatchCommand, PetersenGraphInDimacsByEveryAlgorithm) {
  const CubicGraph g = petersen_graph();
  const testing::EdgeList edges = testing::edge_list(g);
  write(path("petersen.dimacs"), dimacs(10, edges));
  for (const char* algorithm : {"auto", "sg", "ps", "ds", "gw", "frink"}) {
    SCOPED_TRACE(algorithm);
    ASSERT_EQ(run(path("petersen.dimacs") + " " + path("m.txt") + " --algorithm " + algorithm +
                  " --stats-json " + path("stats.json")),
              0)
        << err_;
    EXPECT_EQ(read_back(read(path("m.txt")), 10, edges, 1), 5);
    const std::string stats = read(path("stats.json"));
    EXPECT_NE(stats.find("\"cubic_bridgeless\": true"), std::string::npos) << stats;
    EXPECT_NE(stats.find("\"matched_edges\": 5"), std::string::npos) << stats;
  }
  EXPECT_EQ(run(path("petersen.dimacs") + " " + path("m.txt") + " --algorithm lrs"), 105) << err_;
}

TEST_F(MatchCommand, AMillionNodeRandomCubicBridgelessGraph) {
  const std::uint32_t n = 1'000'000;
  const testing::EdgeList edges = testing::edge_list(random_cubic_bridgeless(n, 11));
  write(path("big.edges"), edge_list(n, edges));
  ASSERT_EQ(run(path("big.edges") + " " + path("big-matching.txt") + " --require-perfect"), 0)
      << err_;
  EXPECT_EQ(read_back(read(path("big-matching.txt")), n, edges, 0), n / 2);
}

TEST_F(MatchCommand, ANonCubicGraphGetsAMaximumMatchingAndANote) {
  // A path of five nodes and a triangle: 2 + 1 edges at most, two nodes left.
  const testing::EdgeList edges = {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {5, 6}, {6, 7}, {7, 5}};
  write(path("g.txt"), edge_list(8, edges));
  ASSERT_EQ(run(path("g.txt") + " " + path("m.txt")), 0) << err_;
  EXPECT_NE(err_.find("is not cubic and bridgeless (node 0 has degree 1)"), std::string::npos)
      << err_;
  EXPECT_EQ(read_back(read(path("m.txt")), 8, edges, 0), testing::boost_matching_size(8, edges));

  // With --require-perfect: exit 3, and an existing OUT is left as it was.
  write(path("kept.txt"), "untouched\n");
  EXPECT_EQ(run(path("g.txt") + " " + path("kept.txt") + " --require-perfect"), 3);
  EXPECT_EQ(read(path("kept.txt")), "untouched\n");
  // A non-cubic graph that has a perfect matching passes --require-perfect.
  write(path("path.txt"), "0 1\n1 2\n2 3\n");
  ASSERT_EQ(run(path("path.txt") + " " + path("p.txt") + " --require-perfect"), 0) << err_;
  EXPECT_EQ(read_back(read(path("p.txt")), 4, {{0, 1}, {1, 2}, {2, 3}}, 0), 2);
}

// The cost of the matching in `output` ("u v" lines, 0-based): each pair at its cheapest edge
// between them (a cheapest matching takes that one of parallel edges).
long long cost_of(const std::string& output, const testing::EdgeList& edges,
                  const std::vector<std::int64_t>& costs) {
  std::map<std::pair<long long, long long>, std::int64_t> cheapest;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const std::pair<long long, long long> key{std::min(edges[e][0], edges[e][1]),
                                              std::max(edges[e][0], edges[e][1])};
    const auto [at, inserted] = cheapest.emplace(key, costs[e]);
    if (!inserted) at->second = std::min(at->second, costs[e]);
  }
  std::istringstream in(output);
  long long u = 0, v = 0, total = 0;
  while (in >> u >> v) total += cheapest.at({std::min(u, v), std::max(u, v)});
  return total;
}

TEST_F(MatchCommand, CostsGiveTheCheapestPerfectMatchingAsLemonFindsIt) {
  const std::uint32_t n = 2000;
  const testing::EdgeList edges = testing::edge_list(random_cubic_bridgeless(n, 5));
  std::mt19937_64 random(7);
  std::vector<std::int64_t> costs;
  std::string text = "p edge " + std::to_string(n) + " " + std::to_string(edges.size()) + "\n";
  for (auto [a, b] : edges) {
    costs.push_back(static_cast<std::int64_t>(random() % 1000) - 100);
    text += "e " + std::to_string(a + 1) + " " + std::to_string(b + 1) + " " +
            std::to_string(costs.back()) + "\n";
  }
  write(path("w.dimacs"), text);
  ASSERT_EQ(run(path("w.dimacs") + " " + path("m.txt") + " --objective cost --require-perfect" +
                " --stats-json " + path("stats.json")),
            0)
      << err_;
  const std::optional<std::int64_t> lemon = testing::lemon_min_cost_perfect(n, edges, costs);
  ASSERT_TRUE(lemon.has_value());
  const std::string matching = read(path("m.txt"));
  EXPECT_EQ(read_back(matching, n, edges, 1), n / 2);
  std::string zero_based;
  {
    std::istringstream in(matching);
    long long u = 0, v = 0;
    while (in >> u >> v) zero_based += std::to_string(u - 1) + " " + std::to_string(v - 1) + "\n";
  }
  EXPECT_EQ(cost_of(zero_based, edges, costs), *lemon);
  const std::string stats = read(path("stats.json"));
  EXPECT_NE(stats.find("\"total_cost\": " + std::to_string(*lemon) + ","), std::string::npos)
      << stats;
  EXPECT_NE(stats.find("\"optimality_certified\": true"), std::string::npos) << stats;
  EXPECT_NE(read(path("stdout")).find("minimum certified"), std::string::npos);
}

TEST_F(MatchCommand, CostsWithoutAPerfectMatchingGiveTheCheapestMaximumOne) {
  // A path of five nodes and a triangle: two path edges and one triangle edge at most; the
  // cheapest such: 0-1 2-3 or 1-2 3-4 (6), and 5-6 (2).
  // A loop (no matching has one) changes nothing.
  const testing::EdgeList edges = {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {5, 6}, {6, 7}, {7, 5}, {4, 4}};
  const std::vector<std::int64_t> costs = {5, 1, 1, 5, 2, 3, 4, -50};
  std::string text;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    text += std::to_string(edges[e][0]) + " " + std::to_string(edges[e][1]) + " " +
            std::to_string(costs[e]) + "\n";
  }
  write(path("w.txt"), text);
  ASSERT_EQ(run(path("w.txt") + " " + path("m.txt") + " --objective cost --stats-json " +
                path("stats.json")),
            0)
      << err_;
  EXPECT_EQ(err_, "");  // no note on cubic graphs: the objective is the cost
  const std::string matching = read(path("m.txt"));
  EXPECT_EQ(read_back(matching, 8, edges, 0), 3);
  EXPECT_EQ(cost_of(matching, edges, costs), 8);
  // Only the cheapest maximum matching ran (it finds the maximum size itself), and says so.
  const std::string stats = read(path("stats.json"));
  EXPECT_NE(stats.find("\"algorithm\": \"min-cost\""), std::string::npos) << stats;
  EXPECT_NE(stats.find("\"perfect\": false,\n  \"matched_edges\": 3,\n  \"unmatched_nodes\": 2"),
            std::string::npos)
      << stats;
  EXPECT_EQ(stats.find("\"augmenting_paths\""), std::string::npos) << stats;
  // Asked for a perfect one first, it tells there is none and writes nothing.
  EXPECT_EQ(run(path("w.txt") + " " + path("m2.txt") + " --objective cost --require-perfect"), 3);
  EXPECT_FALSE(fs::exists(path("m2.txt")));
  // Without costs the objective cannot be met: refused, naming the file.
  write(path("plain.txt"), "0 1\n1 2\n2 3\n");
  EXPECT_EQ(run(path("plain.txt") + " " + path("p.txt") + " --objective cost"), 1);
  EXPECT_NE(err_.find("plain.txt: --objective cost needs a number on every edge line"),
            std::string::npos)
      << err_;
  EXPECT_FALSE(fs::exists(path("p.txt")));
  EXPECT_EQ(run(path("plain.txt") + " " + path("p.txt") + " --objective beauty"), 105);
}

// The best matching by brute force over all matchings of a tiny graph: the heaviest of any size
// (any_size), the heaviest maximum one, or the cheapest perfect one (nullopt: none).
struct Brute {
  std::optional<double> heaviest, heaviest_maximum, cheapest_perfect;
};
Brute brute_force(std::uint32_t n, const testing::EdgeList& edges, const std::vector<double>& w) {
  Brute best;
  int most = -1;
  const std::size_t m = edges.size();
  for (std::uint64_t subset = 0; subset < (std::uint64_t{1} << m); ++subset) {
    std::vector<char> used(n, 0);
    double weight = 0;
    int size = 0;
    bool ok = true;
    for (std::size_t e = 0; e < m && ok; ++e) {
      if (!(subset >> e & 1)) continue;
      const auto [a, b] = edges[e];
      ok = a != b && !used[a] && !used[b];
      used[a] = used[b] = 1;
      weight += w[e];
      ++size;
    }
    if (!ok) continue;
    best.heaviest = std::max(best.heaviest.value_or(weight), weight);
    if (size > most) best.heaviest_maximum.reset();
    if (size >= most) {
      most = size;
      best.heaviest_maximum = std::max(best.heaviest_maximum.value_or(weight), weight);
    }
    if (2 * size == static_cast<int>(n)) {
      best.cheapest_perfect = std::min(best.cheapest_perfect.value_or(weight), weight);
    }
  }
  return best;
}

// The weight of the written matching ("u v" lines in ids from first_id): each pair at its
// heaviest edge between them, or lightest (`heaviest` false).
double weight_of(const std::string& output, const testing::EdgeList& edges,
                 const std::vector<double>& w, std::uint32_t first_id, bool heaviest) {
  std::istringstream in(output);
  long long u = 0, v = 0;
  double total = 0;
  while (in >> u >> v) {
    std::optional<double> pick;
    for (std::size_t e = 0; e < edges.size(); ++e) {
      const auto [a, b] = edges[e];
      if (std::min(a, b) + first_id != std::min(u, v) ||
          std::max(a, b) + first_id != std::max(u, v))
        continue;
      pick = !pick ? w[e] : heaviest ? std::max(*pick, w[e]) : std::min(*pick, w[e]);
    }
    total += pick.value();
  }
  return total;
}

// The objectives on small random graphs with decimal weights, in both formats: each answer the
// brute force's optimum (exact decimals: equal to the last digit printed), certified.
TEST_F(MatchCommand, WeightAndPerfectCostObjectivesAreTheBruteForceOptima) {
  std::mt19937_64 random(3);
  for (int trial = 0; trial < 40; ++trial) {
    const std::uint32_t n = 2 + random() % 7;
    testing::EdgeList edges;
    std::vector<double> w;
    std::string text = "# nodes " + std::to_string(n) + "\n", dimacs_text;
    const std::size_t m = random() % 11;
    for (std::size_t e = 0; e < m; ++e) {
      const std::uint32_t a = random() % n, b = random() % n;
      const long long hundredths = static_cast<long long>(random() % 2001) - 500;
      edges.push_back({a, b});
      w.push_back(static_cast<double>(hundredths) / 100);
      char number[32];
      std::snprintf(number, sizeof number, "%.2f", w.back());
      text += std::to_string(a) + " " + std::to_string(b) + " " + number + "\n";
      dimacs_text +=
          "e " + std::to_string(a + 1) + " " + std::to_string(b + 1) + " " + number + "\n";
    }
    write(path("w.txt"), text);
    write(path("w.dimacs"),
          "p edge " + std::to_string(n) + " " + std::to_string(m) + "\n" + dimacs_text);
    const Brute best = brute_force(n, edges, w);
    for (const char* file : {"w.txt", "w.dimacs"}) {
      const std::uint32_t first = std::string(file) == "w.txt" ? 0 : 1;
      SCOPED_TRACE(text + file);
      ASSERT_EQ(run(path(file) + " " + path("m.txt") + " --objective weight"), 0) << err_;
      EXPECT_NEAR(weight_of(read(path("m.txt")), edges, w, first, true), *best.heaviest, 1e-9);
      EXPECT_NE(read(path("stdout")).find("maximum certified"), std::string::npos);
      ASSERT_EQ(run(path(file) + " " + path("m.txt") + " --objective weight-maximum"), 0) << err_;
      EXPECT_NEAR(weight_of(read(path("m.txt")), edges, w, first, true), *best.heaviest_maximum,
                  1e-9);
      const int code = run(path(file) + " " + path("p.txt") + " --objective perfect-cost" +
                           " --stats-json " + path("s.json"));
      if (best.cheapest_perfect) {
        ASSERT_EQ(code, 0) << err_;
        EXPECT_NEAR(weight_of(read(path("p.txt")), edges, w, first, false), *best.cheapest_perfect,
                    1e-9);
        EXPECT_NE(read(path("s.json")).find("\"exact\": true"), std::string::npos);
      } else {
        ASSERT_EQ(code, 3) << err_;
        EXPECT_NE(err_.find("Tutte-Berge witness A = {"), std::string::npos) << err_;
        EXPECT_NE(read(path("s.json")).find("\"tutte_set\": ["), std::string::npos);
        EXPECT_FALSE(fs::exists(path("p.txt")));
      }
      fs::remove(path("p.txt"));
    }
  }
}

// Costs no power of ten makes integers within 2^40: rounded at a power of two, the tolerance
// printed and in the JSON, the answer the brute force's.
TEST_F(MatchCommand, BinaryRealCostsStateTheirTolerance) {
  const testing::EdgeList edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  const std::vector<double> w = {3.141592653589793, 2.718281828459045, 1.4142135623730951,
                                 1.7320508075688772};
  std::string text;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    char line[64];
    std::snprintf(line, sizeof line, "%u %u %.17g\n", edges[e][0], edges[e][1], w[e]);
    text += line;
  }
  write(path("r.txt"), text);
  ASSERT_EQ(run(path("r.txt") + " " + path("m.txt") + " --objective weight --stats-json " +
                path("s.json")),
            0)
      << err_;
  EXPECT_NEAR(weight_of(read(path("m.txt")), edges, w, 0, true), w[0] + w[2], 1e-12);
  EXPECT_NE(read(path("stdout")).find("tolerance"), std::string::npos);
  const std::string stats = read(path("s.json"));
  EXPECT_NE(stats.find("\"exact\": false"), std::string::npos) << stats;
  EXPECT_EQ(stats.find("\"gap_bound\": 0,"), std::string::npos) << stats;
}

// Notes name nodes and edges as the file does: DIMACS ids 1-based, an edge by its line.
TEST_F(MatchCommand, NotesUseTheFilesOwnIds) {
  // A K4 on nodes 1-4 and a tail 4-5-6: node 4 (index 3) is the first of another degree.
  write(path("k.dimacs"),
        "c K4 and a tail\np edge 6 8\ne 1 2\ne 1 3\ne 1 4\ne 2 3\ne 2 4\ne 3 4\ne 4 5\ne 5 6\n");
  ASSERT_EQ(run(path("k.dimacs") + " " + path("m.txt")), 0) << err_;
  EXPECT_NE(err_.find("(node 4 has degree 4)"), std::string::npos) << err_;
  // Two K4s with one edge subdivided each, joined at the subdivision nodes: cubic, and the
  // joining edge (on line 13) is a bridge.
  write(path("b.dimacs"),
        "p edge 10 15\ne 1 2\ne 1 3\ne 1 5\ne 2 3\ne 2 4\ne 3 4\ne 4 5\n"
        "e 6 7\ne 6 8\ne 6 10\ne 7 8\ne 5 10\ne 7 9\ne 8 9\ne 9 10\n");
  ASSERT_EQ(run(path("b.dimacs") + " " + path("m.txt")), 0) << err_;
  EXPECT_NE(err_.find("(the edge on line 13 (5, 10) is a bridge)"), std::string::npos) << err_;
}

TEST_F(MatchCommand, BadFilesAreRefusedWithTheirLine) {
  write(path("bad.txt"), "0 1\n1 x\n");
  write(path("out.txt"), "untouched\n");
  EXPECT_EQ(run(path("bad.txt") + " " + path("out.txt")), 1);
  EXPECT_NE(err_.find("bad.txt:2: bad node id 'x'"), std::string::npos) << err_;
  EXPECT_EQ(read(path("out.txt")), "untouched\n");
  write(path("g.graph"), "0 1\n");
  EXPECT_EQ(run(path("g.graph") + " " + path("out.txt")), 1);
  EXPECT_NE(err_.find("unknown graph format"), std::string::npos) << err_;
  EXPECT_EQ(run(path("g.graph") + " " + path("out.txt") + " --format edges"), 0) << err_;
}

}  // namespace
}  // namespace petersen
