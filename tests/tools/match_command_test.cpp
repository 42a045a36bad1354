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
  std::string text = std::to_string(n) + " " + std::to_string(edges.size()) + "\n";
  for (auto [a, b] : edges) text += std::to_string(a) + " " + std::to_string(b) + "\n";
  return text;
}

TEST_F(MatchCommand, PetersenGraphInDimacsByEveryAlgorithm) {
  const CubicGraph g = petersen_graph();
  const testing::EdgeList edges = testing::edge_list(g);
  write(path("petersen.dimacs"), dimacs(10, edges));
  for (const char* algorithm : {"auto", "sg", "ps", "ds", "gw", "frink", "lemon"}) {
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
  EXPECT_NE(err_.find("plain.txt: --objective cost needs a cost on every edge line"),
            std::string::npos)
      << err_;
  EXPECT_FALSE(fs::exists(path("p.txt")));
  EXPECT_EQ(run(path("plain.txt") + " " + path("p.txt") + " --objective beauty"), 105);
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
