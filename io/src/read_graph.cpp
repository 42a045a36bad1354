#include "petersen/io/read_graph.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <utility>

#include "petersen/io/file_bytes.hpp"
#include "text_scan.hpp"

namespace petersen {

namespace {

constexpr std::pair<GraphFormat, std::string_view> kFormatNames[] = {
    {GraphFormat::dimacs, "dimacs"}, {GraphFormat::edges, "edges"}};

// Isolated nodes a file may declare beyond those its edges touch (DIMACS header, or the largest
// id of an edge list): 2^24 of them cost 64 MiB per per-node array of the matching.
constexpr std::uint64_t kMostIsolatedNodes = std::uint64_t{1} << 24;

// Errors at "source:line"; the line is set as the parse goes, or to an earlier line whose
// content a later check refuses.
struct At {
  const std::string& source;
  std::size_t line = 0;
  [[noreturn]] void fail(const std::string& what) const { throw FileError(source, line, what); }
};

// A node id: a whole non-negative integer below 2^32 - 1 (kNoNode is reserved).
NodeId parse_id(std::string_view token, const At& at, std::string_view what) {
  std::int64_t value = 0;
  if (!text::parse_integer(token, value) || value < 0 || value >= std::int64_t{kNoNode}) {
    at.fail("bad " + std::string(what) + " " + text::Located::quote(token));
  }
  return static_cast<NodeId>(value);
}

// An edge's cost: a whole integer within kMaxFileCost.
std::int64_t parse_cost(std::string_view token, const At& at) {
  std::int64_t value = 0;
  if (!text::parse_integer(token, value)) {
    at.fail("bad cost " + text::Located::quote(token) + " (an integer)");
  }
  if (value > kMaxFileCost || value < -kMaxFileCost) {
    at.fail("cost " + std::to_string(value) + " out of range (at most 2^40 in absolute value)");
  }
  return value;
}

// Whether every edge line gives a cost or none does: the first edge line decides (on line
// `first_line`), a later one that differs is named.
struct CostPresence {
  std::optional<bool> with_cost;
  std::size_t first_line = 0;

  void check(bool has_cost, const At& at) {
    if (!with_cost) {
      with_cost = has_cost;
      first_line = at.line;
    } else if (*with_cost != has_cost) {
      differs(has_cost, first_line, at);
    }
  }
  [[noreturn]] static void differs(bool has_cost, std::size_t other_line, const At& at) {
    at.fail(std::string(has_cost ? "a cost on this edge line, none"
                                 : "no cost on this edge line, one") +
            " on line " + std::to_string(other_line) + " (a cost on every edge line or on none)");
  }
};

void check_node_count(std::uint64_t nodes, std::uint64_t edges, const At& at) {
  if (nodes > 2 * edges + kMostIsolatedNodes) {
    at.fail(std::to_string(nodes) + " nodes for " + std::to_string(edges) +
            " edges: more than 2^24 of them would be isolated");
  }
}

GraphFile parse_dimacs(std::string_view bytes, const std::string& source) {
  GraphFile graph;
  graph.first_id = 1;
  text::Lines lines{bytes};
  At at{source};
  At header_at{source};
  bool have_header = false;
  std::uint64_t declared_edges = 0;
  CostPresence presence;
  std::string_view line, token;
  while (lines.next(line)) {
    at.line = lines.line;
    text::Tokens tokens{line};
    if (!tokens.next(token) || token == "c") continue;
    if (token == "p") {
      if (have_header)
        at.fail("a second 'p' line (the first is line " + std::to_string(header_at.line) + ")");
      if (!tokens.next(token) || (token != "edge" && token != "col")) {
        at.fail("expected 'p edge N M'");
      }
      std::string_view n_token, m_token;
      if (!tokens.next(n_token) || !tokens.next(m_token)) at.fail("expected 'p edge N M'");
      const NodeId n = parse_id(n_token, at, "node count");
      const NodeId m = parse_id(m_token, at, "edge count");
      if (m > lines.remaining() / 6 + 1) {  // "e 1 2\n" is the shortest edge line
        at.fail("header declares " + std::to_string(m) + " edges, more than the remaining " +
                std::to_string(lines.remaining()) + " bytes can hold");
      }
      check_node_count(n, m, at);
      graph.node_count = n;
      declared_edges = m;
      graph.edges.reserve(m);
      have_header = true;
      header_at.line = at.line;
    } else if (token == "e") {
      if (!have_header) at.fail("an edge before the 'p edge N M' line");
      std::string_view a_token, b_token;
      if (!tokens.next(a_token) || !tokens.next(b_token)) at.fail("expected 'e U V'");
      std::array<NodeId, 2> ends{};
      for (int k = 0; k < 2; ++k) {
        const NodeId id = parse_id(k == 0 ? a_token : b_token, at, "node id");
        if (id < 1 || id > graph.node_count) {
          at.fail("node " + std::to_string(id) + " out of range (1 to " +
                  std::to_string(graph.node_count) + ")");
        }
        ends[k] = id - 1;
      }
      graph.edges.push_back(ends);
      const bool has_cost = tokens.next(token);
      presence.check(has_cost, at);
      if (has_cost) graph.costs.push_back(parse_cost(token, at));
    } else {
      at.fail("unknown line type " + text::Located::quote(token) + " (expected c, p or e)");
    }
    if (tokens.next(token)) at.fail("unexpected " + text::Located::quote(token));
  }
  if (!have_header) {
    at.line = std::max<std::size_t>(lines.line, 1);
    at.fail("no 'p edge N M' line");
  }
  if (graph.edges.size() != declared_edges) {
    header_at.fail("header declares " + std::to_string(declared_edges) + " edges, the file has " +
                   std::to_string(graph.edges.size()));
  }
  return graph;
}

GraphFile parse_edge_list(std::string_view bytes, const std::string& source) {
  GraphFile graph;
  text::Lines lines{bytes};
  At at{source};
  std::vector<std::size_t> line_of;  // of each pair, for the errors found after the first pass
  std::string_view line, token;
  // Every data line is a pair, with or without a cost; whether the first is a header is known
  // once all are counted. A header has no cost; with costs, every other line has one.
  CostPresence presence;
  bool first_has_cost = false;
  while (lines.next(line)) {
    at.line = lines.line;
    text::Tokens tokens{text::strip_comment(line)};
    if (!tokens.next(token)) continue;
    std::string_view second;
    if (!tokens.next(second)) at.fail("expected two node ids 'U V'");
    graph.edges.push_back({parse_id(token, at, "node id"), parse_id(second, at, "node id")});
    line_of.push_back(lines.line);
    const bool has_cost = tokens.next(token);
    if (graph.edges.size() == 1) {
      first_has_cost = has_cost;
    } else {
      presence.check(has_cost, at);
    }
    if (has_cost) graph.costs.push_back(parse_cost(token, at));
    if (tokens.next(token)) at.fail("unexpected " + text::Located::quote(token));
  }
  const bool header =
      !graph.edges.empty() && !first_has_cost && graph.edges[0][1] == graph.edges.size() - 1;
  // Without a header, the first line is an edge like the others.
  if (!header && presence.with_cost && first_has_cost != *presence.with_cost) {
    at.line = line_of[0];
    CostPresence::differs(first_has_cost, line_of[1], at);
  }
  if (header) {
    at.line = line_of[0];
    graph.node_count = graph.edges[0][0];
    check_node_count(graph.node_count, graph.edges.size() - 1, at);
    graph.edges.erase(graph.edges.begin());
    line_of.erase(line_of.begin());
    for (std::size_t e = 0; e < graph.edges.size(); ++e) {
      for (NodeId id : graph.edges[e]) {
        if (id >= graph.node_count) {
          at.line = line_of[e];
          at.fail("node " + std::to_string(id) + " out of range (the header on line " +
                  std::to_string(line_of.empty() ? 1 : line_of[0] - 1) + " declares " +
                  std::to_string(graph.node_count) + " nodes)");
        }
      }
    }
    return graph;
  }
  std::uint64_t largest = 0;
  std::size_t largest_edge = 0;
  for (std::size_t e = 0; e < graph.edges.size(); ++e) {
    for (NodeId id : graph.edges[e]) {
      if (id + std::uint64_t{1} > largest) {
        largest = id + std::uint64_t{1};
        largest_edge = e;
      }
    }
  }
  if (!graph.edges.empty()) at.line = line_of[largest_edge];
  check_node_count(largest, graph.edges.size(), at);
  graph.node_count = static_cast<std::uint32_t>(largest);
  return graph;
}

}  // namespace

std::string_view to_string(GraphFormat format) {
  for (auto [f, name] : kFormatNames)
    if (f == format) return name;
  return "?";
}

std::optional<GraphFormat> parse_graph_format(std::string_view name) {
  for (auto [f, n] : kFormatNames)
    if (n == name) return f;
  return std::nullopt;
}

GraphFormat graph_format_of(const std::string& path) {
  std::string_view name = path;
  if (ends_with_nocase(name, ".gz")) name.remove_suffix(3);
  if (ends_with_nocase(name, ".dimacs") || ends_with_nocase(name, ".col")) {
    return GraphFormat::dimacs;
  }
  if (ends_with_nocase(name, ".txt") || ends_with_nocase(name, ".edges")) return GraphFormat::edges;
  throw FileError(path, 0,
                  "unknown graph format (expected .dimacs, .col, .txt or .edges, optionally .gz, "
                  "or a format named by --format)");
}

GraphFile parse_graph(std::string_view bytes, GraphFormat format, const std::string& source) {
  return format == GraphFormat::dimacs ? parse_dimacs(bytes, source)
                                       : parse_edge_list(bytes, source);
}

GraphFile read_graph(const std::string& path, std::optional<GraphFormat> format) {
  const GraphFormat chosen = format ? *format : graph_format_of(path);
  return parse_graph(read_file_bytes(path).view(), chosen, path);
}

}  // namespace petersen
