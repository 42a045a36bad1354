// Graph files: both formats parse to the same graph, the edge list's header only when declared,
// exact decimal costs, byte-order marks and line ends, and every bad file gets an error naming
// its line.

#include "petersen/io/read_graph.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace petersen {
namespace {

using Edges = std::vector<std::array<NodeId, 2>>;

// The message of the FileError that parsing `text` raises, or "" when it parses.
std::string error_of(const std::string& text, GraphFormat format) {
  try {
    parse_graph(text, format, "g");
  } catch (const FileError& e) {
    return e.what();
  }
  return "";
}

TEST(ReadGraph, DimacsIsOneBased) {
  const GraphFile g =
      parse_graph("c a theta graph\np edge 2 3\ne 1 2\ne 2 1\n\ne 1 2\n", GraphFormat::dimacs, "g");
  EXPECT_EQ(g.node_count, 2u);
  EXPECT_EQ(g.first_id, 1u);
  EXPECT_EQ(g.edges, (Edges{{0, 1}, {1, 0}, {0, 1}}));
}

TEST(ReadGraph, EdgeListHeaderOnlyWhenTheFileSaysSo) {
  // "# nodes N" declares the node count (node 2 isolated), "edges M" checks the edges'.
  const GraphFile with = parse_graph("# nodes 3\n0 1 # an edge\n1 0\n", GraphFormat::edges, "g");
  EXPECT_EQ(with.node_count, 3u);
  EXPECT_EQ(with.edges, (Edges{{0, 1}, {1, 0}}));
  EXPECT_EQ(parse_graph("# nodes 4 edges 1\n0 1\n", GraphFormat::edges, "g").node_count, 4u);
  EXPECT_EQ(parse_graph("# nodes 0\n", GraphFormat::edges, "g").node_count, 0u);
  // A first line "N M" is an edge like any other, whatever M is.
  const GraphFile one = parse_graph("1 0\n", GraphFormat::edges, "g");
  EXPECT_EQ(one.node_count, 2u);
  EXPECT_EQ(one.edges, (Edges{{1, 0}}));
  const GraphFile three = parse_graph("5 2\n0 1\n3 4\n", GraphFormat::edges, "g");
  EXPECT_EQ(three.node_count, 6u);
  EXPECT_EQ(three.edges, (Edges{{5, 2}, {0, 1}, {3, 4}}));
  EXPECT_EQ(three.edge_lines, (std::vector<std::uint32_t>{1, 2, 3}));
  // Comments that do not read "nodes" and an integer are comments; one after an edge too.
  const GraphFile comments =
      parse_graph("# nodes of a path\n0 1\n# nodes 9\n", GraphFormat::edges, "g");
  EXPECT_EQ(comments.node_count, 2u);
}

// Any headerless edge list, whatever its first line: every line is an edge, and the node count
// is the largest id + 1.
TEST(ReadGraph, AHeaderlessFirstLineIsAlwaysAnEdge) {
  std::uint32_t state = 12345;
  auto next = [&](std::uint32_t bound) {
    state = state * 1664525u + 1013904223u;
    return (state >> 8) % bound;
  };
  for (int trial = 0; trial < 2000; ++trial) {
    const std::uint32_t m = 1 + next(8);
    Edges edges;
    std::string text;
    for (std::uint32_t i = 0; i < m; ++i) {
      // The first line is often "U V" with V = the number of lines after it, the old trap.
      const NodeId a = next(10), b = i == 0 && next(2) == 0 ? m - 1 : next(10);
      edges.push_back({a, b});
      text += std::to_string(a) + " " + std::to_string(b) + "\n";
    }
    const GraphFile g = parse_graph(text, GraphFormat::edges, "g");
    ASSERT_EQ(g.edges, edges) << text;
    NodeId largest = 0;
    for (auto [a, b] : edges) largest = std::max({largest, a, b});
    ASSERT_EQ(g.node_count, largest + 1) << text;
  }
}

TEST(ReadGraph, CostsAreAThirdNumberOnEveryEdgeLine) {
  const GraphFile dimacs = parse_graph("p edge 3 3\ne 1 2 5\ne 2 3 -7\nc a comment\ne 1 3 +0\n",
                                       GraphFormat::dimacs, "g");
  EXPECT_EQ(dimacs.edges, (Edges{{0, 1}, {1, 2}, {0, 2}}));
  EXPECT_EQ(dimacs.costs, (std::vector<std::int64_t>{5, -7, 0}));
  EXPECT_EQ(dimacs.edge_lines, (std::vector<std::uint32_t>{2, 3, 5}));
  const GraphFile header =
      parse_graph("# nodes 4\n0 1 4\n1 2 1099511627776\n", GraphFormat::edges, "g");
  EXPECT_EQ(header.node_count, 4u);
  EXPECT_EQ(header.costs, (std::vector<std::int64_t>{4, kMaxFileCost}));
  EXPECT_EQ(parse_graph("3 2 1\n", GraphFormat::edges, "g").costs, (std::vector<std::int64_t>{1}));
  EXPECT_FALSE(parse_graph("3 2\n0 1\n1 2\n", GraphFormat::edges, "g").has_costs());
  EXPECT_FALSE(parse_graph("p edge 2 1\ne 1 2\n", GraphFormat::dimacs, "g").has_costs());
}

// Decimals (with exponents) are exact integers at the power of ten of the most digits after the
// point, when that fits 2^40; otherwise the doubles are kept, for the solver to round.
TEST(ReadGraph, RealCostsExactWhereThePowerOfTenFits) {
  const GraphFile g =
      parse_graph("0 1 1.5\n1 2 -0.25\n2 3 3\n3 0 2e-2\n4 5 1.10E+1\n", GraphFormat::edges, "g");
  EXPECT_EQ(g.cost_decimals, 2u);
  EXPECT_EQ(g.costs, (std::vector<std::int64_t>{150, -25, 300, 2, 1100}));
  EXPECT_TRUE(g.real_costs.empty());
  const GraphFile pi =
      parse_graph("p edge 2 1\ne 1 2 3.141592653589793\n", GraphFormat::dimacs, "g");
  EXPECT_TRUE(pi.costs.empty());
  EXPECT_EQ(pi.real_costs, (std::vector<double>{3.141592653589793}));
  // Past 2^40 as integers: the doubles.
  const GraphFile big = parse_graph("0 1 1e15\n1 2 1\n", GraphFormat::edges, "g");
  EXPECT_EQ(big.real_costs, (std::vector<double>{1e15, 1}));
  const GraphFile many = parse_graph("0 1 99999999999999999999\n", GraphFormat::edges, "g");
  EXPECT_EQ(many.real_costs, (std::vector<double>{1e20}));
}

TEST(ReadGraph, BadCostsNameTheLine) {
  EXPECT_EQ(error_of("p edge 2 2\ne 1 2 5\ne 2 1\n", GraphFormat::dimacs),
            "g:3: no cost on this edge line, one on line 2 (a cost on every edge line or on none)");
  EXPECT_EQ(error_of("p edge 2 2\ne 1 2\nc\ne 2 1 5\n", GraphFormat::dimacs),
            "g:4: a cost on this edge line, none on line 2 (a cost on every edge line or on none)");
  EXPECT_EQ(error_of("0 1\n1 2 5\n2 0 6\n", GraphFormat::edges),
            "g:2: a cost on this edge line, none on line 1 (a cost on every edge line or on none)");
  EXPECT_EQ(error_of("0 1 5\n1 2\n", GraphFormat::edges),
            "g:2: no cost on this edge line, one on line 1 (a cost on every edge line or on none)");
  EXPECT_EQ(error_of("p edge 2 1\ne 1 2 x\n", GraphFormat::dimacs), "g:2: bad cost 'x' (a number)");
  for (const char* bad : {"inf", "nan", "1e999", "0x10", "1.2.3", "e5", "--1", "1e"}) {
    EXPECT_EQ(error_of(std::string("0 1 ") + bad + "\n", GraphFormat::edges),
              std::string("g:1: bad cost '") + bad + "' (a number)");
  }
  EXPECT_EQ(error_of("0 1 5 6\n", GraphFormat::edges), "g:1: unexpected '6'");
}

// A UTF-8 byte-order mark is skipped; "\r" alone ends a line as "\n" and "\r\n" do; an empty
// file (or one of comments only) is refused alike in both formats.
TEST(ReadGraph, ByteOrderMarksLineEndsAndEmptyFiles) {
  for (GraphFormat format : {GraphFormat::edges, GraphFormat::dimacs}) {
    const std::string body =
        format == GraphFormat::edges ? "0 1|1 2 # x|2 0|" : "c x|p edge 3 3|e 1 2|e 2 3|e 3 1|";
    for (const char* end : {"\n", "\r\n", "\r"}) {
      std::string text = "\xEF\xBB\xBF";
      for (char c : body) text += c == '|' ? std::string(end) : std::string(1, c);
      SCOPED_TRACE(text);
      const GraphFile g = parse_graph(text, format, "g");
      EXPECT_EQ(g.node_count, 3u);
      EXPECT_EQ(g.edges, (Edges{{0, 1}, {1, 2}, {2, 0}}));
      EXPECT_EQ(g.edge_lines.back(), format == GraphFormat::edges ? 3u : 5u);
    }
    for (const char* empty :
         {"", "\xEF\xBB\xBF", "\n\n", "\r", format == GraphFormat::edges ? "# x\n" : "c x\n"}) {
      EXPECT_EQ(error_of(empty, format), "g:1: empty graph file (no edge and no header)");
    }
  }
  EXPECT_EQ(error_of("0 1\r1 x\r", GraphFormat::edges), "g:2: bad node id 'x'");
}

TEST(ReadGraph, BadFilesNameTheLine) {
  EXPECT_EQ(error_of("p edge 2 1\ne 1 3\n", GraphFormat::dimacs),
            "g:2: node 3 out of range (1 to 2)");
  EXPECT_EQ(error_of("p edge 2 1\ne 0 1\n", GraphFormat::dimacs),
            "g:2: node 0 out of range (1 to 2)");
  EXPECT_EQ(error_of("e 1 2\n", GraphFormat::dimacs), "g:1: an edge before the 'p edge N M' line");
  EXPECT_EQ(error_of("p edge 2 2\ne 1 2\n", GraphFormat::dimacs),
            "g:1: header declares 2 edges, the file has 1");
  EXPECT_EQ(error_of("p edge 2 1\np edge 2 1\n", GraphFormat::dimacs),
            "g:2: a second 'p' line (the first is line 1)");
  EXPECT_EQ(error_of("p edge 2 1\nx 1 2\n", GraphFormat::dimacs),
            "g:2: unknown line type 'x' (expected c, p or e)");
  EXPECT_EQ(error_of("c nothing\ne 1 2\n", GraphFormat::dimacs),
            "g:2: an edge before the 'p edge N M' line");
  EXPECT_EQ(error_of("p edge 2 1\ne 1 2 3 4\n", GraphFormat::dimacs), "g:2: unexpected '4'");
  EXPECT_EQ(error_of("0 1\n1 -2\n", GraphFormat::edges), "g:2: bad node id '-2'");
  EXPECT_EQ(error_of("0 1\n\n7\n", GraphFormat::edges), "g:3: expected two node ids 'U V'");
  EXPECT_EQ(error_of("# nodes 2\n0 5\n", GraphFormat::edges),
            "g:2: node 5 out of range (the header on line 1 declares 2 nodes)");
  EXPECT_EQ(error_of("# nodes 2 edges 2\n0 1\n", GraphFormat::edges),
            "g:1: header declares 2 edges, the file has 1");
  EXPECT_EQ(error_of("# nodes 2\n# nodes 3\n0 1\n", GraphFormat::edges),
            "g:2: a second '# nodes' header (the first is line 1)");
  EXPECT_EQ(error_of("# nodes 2 edge 1\n0 1\n", GraphFormat::edges),
            "g:1: expected '# nodes N' or '# nodes N edges M'");
  EXPECT_EQ(error_of("# nodes -2\n0 1\n", GraphFormat::edges), "g:1: bad node count '-2'");
}

TEST(ReadGraph, AbsurdCountsAllocateNothing) {
  EXPECT_EQ(error_of("p edge 4000000000 0\n", GraphFormat::dimacs),
            "g:1: 4000000000 nodes for 0 edges: more than 2^24 of them would be isolated");
  EXPECT_EQ(error_of("p edge 3 4000000000\n", GraphFormat::dimacs),
            "g:1: header declares 4000000000 edges, more than the remaining 0 bytes can hold");
  EXPECT_EQ(error_of("0 4000000000\n", GraphFormat::edges),
            "g:1: 4000000001 nodes for 1 edges: more than 2^24 of them would be isolated");
}

TEST(ReadGraph, FormatFromTheExtension) {
  EXPECT_EQ(graph_format_of("a.dimacs"), GraphFormat::dimacs);
  EXPECT_EQ(graph_format_of("a.COL.gz"), GraphFormat::dimacs);
  EXPECT_EQ(graph_format_of("a.edges"), GraphFormat::edges);
  EXPECT_EQ(graph_format_of("a.txt"), GraphFormat::edges);
  EXPECT_THROW(graph_format_of("a.graph"), FileError);
  EXPECT_THROW(read_graph("/nonexistent/a.txt"), FileError);
}

TEST(ReadGraph, ErrorsCarryTheFileAndTheLine) {
  try {
    parse_graph("p edge 2 1\ne 1 2 3 4\n", GraphFormat::dimacs, "g.dimacs");
    FAIL() << "parsed";
  } catch (const FileError& e) {
    EXPECT_EQ(e.file(), "g.dimacs");
    EXPECT_EQ(e.line(), 2u);
  }
  try {
    read_graph("/nonexistent/a.txt");
    FAIL() << "read";
  } catch (const FileError& e) {
    EXPECT_EQ(e.file(), "/nonexistent/a.txt");
    EXPECT_EQ(e.line(), 0u);
    EXPECT_EQ(std::string(e.what()).rfind("/nonexistent/a.txt: cannot open for reading: ", 0), 0u);
  }
}

}  // namespace
}  // namespace petersen
