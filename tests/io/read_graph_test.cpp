// Graph files: both formats parse to the same graph, the edge list's header rule, and every bad
// file gets an error naming its line.

#include "petersen/io/read_graph.hpp"

#include <gtest/gtest.h>

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

TEST(ReadGraph, EdgeListWithAndWithoutHeader) {
  // "3 2" is followed by two edge lines: a header, so node 2 is isolated... and counted.
  const GraphFile with = parse_graph("3 2\n0 1 # an edge\n1 0\n", GraphFormat::edges, "g");
  EXPECT_EQ(with.node_count, 3u);
  EXPECT_EQ(with.edges, (Edges{{0, 1}, {1, 0}}));
  // "3 5" is not followed by five lines: an edge, and the node count is the largest id + 1.
  const GraphFile without = parse_graph("3 5\n0 1\n", GraphFormat::edges, "g");
  EXPECT_EQ(without.node_count, 6u);
  EXPECT_EQ(without.edges, (Edges{{3, 5}, {0, 1}}));
  EXPECT_EQ(parse_graph("", GraphFormat::edges, "g").node_count, 0u);
}

TEST(ReadGraph, CostsAreAThirdNumberOnEveryEdgeLine) {
  const GraphFile dimacs = parse_graph("p edge 3 3\ne 1 2 5\ne 2 3 -7\nc a comment\ne 1 3 +0\n",
                                       GraphFormat::dimacs, "g");
  EXPECT_EQ(dimacs.edges, (Edges{{0, 1}, {1, 2}, {0, 2}}));
  EXPECT_EQ(dimacs.costs, (std::vector<std::int64_t>{5, -7, 0}));
  // A header has no cost; the edge lines after it have one each.
  const GraphFile header = parse_graph("4 2\n0 1 4\n1 2 1099511627776\n", GraphFormat::edges, "g");
  EXPECT_EQ(header.node_count, 4u);
  EXPECT_EQ(header.edges, (Edges{{0, 1}, {1, 2}}));
  EXPECT_EQ(header.costs, (std::vector<std::int64_t>{4, kMaxFileCost}));
  const GraphFile no_header = parse_graph("0 1 4\n1 2 -9\n", GraphFormat::edges, "g");
  EXPECT_EQ(no_header.node_count, 3u);
  EXPECT_EQ(no_header.costs, (std::vector<std::int64_t>{4, -9}));
  EXPECT_EQ(parse_graph("3 2 1\n", GraphFormat::edges, "g").costs, (std::vector<std::int64_t>{1}));
  EXPECT_TRUE(parse_graph("3 2\n0 1\n1 2\n", GraphFormat::edges, "g").costs.empty());
  EXPECT_TRUE(parse_graph("p edge 2 1\ne 1 2\n", GraphFormat::dimacs, "g").costs.empty());
}

TEST(ReadGraph, BadCostsNameTheLine) {
  EXPECT_EQ(error_of("p edge 2 2\ne 1 2 5\ne 2 1\n", GraphFormat::dimacs),
            "g:3: no cost on this edge line, one on line 2 (a cost on every edge line or on none)");
  EXPECT_EQ(error_of("p edge 2 2\ne 1 2\nc\ne 2 1 5\n", GraphFormat::dimacs),
            "g:4: a cost on this edge line, none on line 2 (a cost on every edge line or on none)");
  // "0 1" does not declare the two lines after it: not a header, an edge without a cost.
  EXPECT_EQ(error_of("0 1\n1 2 5\n2 0 6\n", GraphFormat::edges),
            "g:1: no cost on this edge line, one on line 2 (a cost on every edge line or on none)");
  EXPECT_EQ(error_of("0 1 5\n1 2\n", GraphFormat::edges),
            "g:1: a cost on this edge line, none on line 2 (a cost on every edge line or on none)");
  EXPECT_EQ(error_of("0 1 5\n1 2 6\n2 0\n", GraphFormat::edges),
            "g:3: no cost on this edge line, one on line 2 (a cost on every edge line or on none)");
  EXPECT_EQ(error_of("0 1 1.5\n", GraphFormat::edges), "g:1: bad cost '1.5' (an integer)");
  EXPECT_EQ(error_of("p edge 2 1\ne 1 2 x\n", GraphFormat::dimacs),
            "g:2: bad cost 'x' (an integer)");
  EXPECT_EQ(error_of("0 1 -1099511627777\n", GraphFormat::edges),
            "g:1: cost -1099511627777 out of range (at most 2^40 in absolute value)");
  EXPECT_EQ(error_of("0 1 99999999999999999999\n", GraphFormat::edges),
            "g:1: bad cost '99999999999999999999' (an integer)");
  EXPECT_EQ(error_of("0 1 5 6\n", GraphFormat::edges), "g:1: unexpected '6'");
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
  EXPECT_EQ(error_of("c nothing\n", GraphFormat::dimacs), "g:1: no 'p edge N M' line");
  EXPECT_EQ(error_of("p edge 2 1\ne 1 2 3 4\n", GraphFormat::dimacs), "g:2: unexpected '4'");
  EXPECT_EQ(error_of("0 1\n1 -2\n", GraphFormat::edges), "g:2: bad node id '-2'");
  EXPECT_EQ(error_of("0 1\n\n7\n", GraphFormat::edges), "g:3: expected two node ids 'U V'");
  EXPECT_EQ(error_of("2 1\n0 5\n", GraphFormat::edges),
            "g:2: node 5 out of range (the header on line 1 declares 2 nodes)");
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
