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

// A cost as the file writes it: value, and when its digits allow, exactly mantissa ·
// 10^exponent (at most 18 significant digits, trailing zeros moved into the exponent).
struct Decimal {
  double value = 0;
  bool exact = false;
  std::int64_t mantissa = 0;
  std::int64_t exponent = 0;
};

// [+-] digits [. digits] [(e|E) [+-] digits], at least one digit before the exponent.
Decimal parse_cost(std::string_view token, const At& at) {
  auto bad = [&]() { at.fail("bad cost " + text::Located::quote(token) + " (a number)"); };
  Decimal d;
  if (!text::parse_real(token, d.value)) bad();
  std::size_t i = token.empty() || (token[0] != '+' && token[0] != '-') ? 0 : 1;
  const bool negative = i == 1 && token[0] == '-';
  int digits = 0, significant = 0;
  bool point = false;
  for (; i < token.size() && token[i] != 'e' && token[i] != 'E'; ++i) {
    if (token[i] == '.' && !point) {
      point = true;
      continue;
    }
    if (token[i] < '0' || token[i] > '9') bad();  // hex floats, inf, nan: from_chars took them
    ++digits;
    if (point) --d.exponent;
    if (d.mantissa == 0 && token[i] == '0') continue;
    if (++significant > 18) return d;  // inexact: the double only
    d.mantissa = 10 * d.mantissa + (token[i] - '0');
  }
  if (digits == 0) bad();
  if (i < token.size()) {
    std::int64_t e = 0;
    if (!text::parse_integer(token.substr(i + 1), e) || e > 100000 || e < -100000) return d;
    d.exponent += e;
  }
  while (d.mantissa != 0 && d.mantissa % 10 == 0) {
    d.mantissa /= 10;
    ++d.exponent;
  }
  if (d.mantissa == 0) d.exponent = 0;
  if (negative) d.mantissa = -d.mantissa;
  d.exact = true;
  return d;
}

// The parsed costs into `graph`: integers times 10^decimals when every one is exact and fits
// within kMaxFileCost so, else the doubles.
void set_costs(const std::vector<Decimal>& parsed, GraphFile& graph) {
  std::int64_t decimals = 0;
  bool exact = true;
  for (const Decimal& d : parsed) {
    exact = exact && d.exact;
    if (d.exact) decimals = std::max(decimals, -d.exponent);
  }
  if (exact && decimals <= 18) {
    std::vector<std::int64_t> costs;
    costs.reserve(parsed.size());
    for (const Decimal& d : parsed) {
      // |mantissa| < 10^18 and |value| <= 2^40 < 10^13 leave no room for overflow.
      std::int64_t scaled = d.mantissa;
      for (std::int64_t k = d.exponent + decimals; k > 0 && exact; --k) {
        exact = scaled <= kMaxFileCost && scaled >= -kMaxFileCost;
        scaled *= 10;
      }
      exact = exact && scaled <= kMaxFileCost && scaled >= -kMaxFileCost;
      costs.push_back(scaled);
    }
    if (exact) {
      graph.costs = std::move(costs);
      graph.cost_decimals = static_cast<std::uint32_t>(decimals);
      return;
    }
  }
  graph.real_costs.reserve(parsed.size());
  for (const Decimal& d : parsed) graph.real_costs.push_back(d.value);
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
      at.fail(std::string(has_cost ? "a cost on this edge line, none"
                                   : "no cost on this edge line, one") +
              " on line " + std::to_string(first_line) + " (a cost on every edge line or on none)");
    }
  }
};

void check_node_count(std::uint64_t nodes, std::uint64_t edges, const At& at) {
  if (nodes > 2 * edges + kMostIsolatedNodes) {
    at.fail(std::to_string(nodes) + " nodes for " + std::to_string(edges) +
            " edges: more than 2^24 of them would be isolated");
  }
}

[[noreturn]] void empty_file(At& at) {
  at.line = 1;
  at.fail("empty graph file (no edge and no header)");
}

GraphFile parse_dimacs(std::string_view bytes, const std::string& source) {
  GraphFile graph;
  graph.first_id = 1;
  text::Lines lines{bytes};
  At at{source};
  At header_at{source};
  bool have_header = false, any_line = false;
  std::uint64_t declared_edges = 0;
  CostPresence presence;
  std::vector<Decimal> costs;
  std::string_view line, token;
  while (lines.next(line)) {
    at.line = lines.line;
    text::Tokens tokens{line};
    if (!tokens.next(token) || token == "c") continue;
    any_line = true;
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
      graph.edge_lines.push_back(static_cast<std::uint32_t>(at.line));
      const bool has_cost = tokens.next(token);
      presence.check(has_cost, at);
      if (has_cost) costs.push_back(parse_cost(token, at));
    } else {
      at.fail("unknown line type " + text::Located::quote(token) + " (expected c, p or e)");
    }
    if (tokens.next(token)) at.fail("unexpected " + text::Located::quote(token));
  }
  if (!any_line) empty_file(at);
  if (!have_header) {
    at.line = std::max<std::size_t>(lines.line, 1);
    at.fail("no 'p edge N M' line");
  }
  if (graph.edges.size() != declared_edges) {
    header_at.fail("header declares " + std::to_string(declared_edges) + " edges, the file has " +
                   std::to_string(graph.edges.size()));
  }
  set_costs(costs, graph);
  return graph;
}

// The edge list's header: a comment "# nodes N" or "# nodes N edges M" (nothing else on it)
// before the first edge. A comment whose first words are not "nodes" and an integer is none.
struct EdgeListHeader {
  std::uint32_t nodes = 0;
  std::optional<std::uint64_t> edges;
  std::size_t line = 0;
};

// The header a comment line declares, if it is one; `comment` is the text after '#'.
std::optional<EdgeListHeader> header_of(std::string_view comment, const At& at) {
  text::Tokens tokens{comment};
  std::string_view token, n_token, m_token;
  std::int64_t count = 0;
  if (!tokens.next(token) || token != "nodes" || !tokens.next(n_token) ||
      !text::parse_integer(n_token, count)) {
    return std::nullopt;  // a comment like any other
  }
  EdgeListHeader header;
  header.line = at.line;
  header.nodes = parse_id(n_token, at, "node count");
  if (tokens.next(token)) {
    if (token != "edges" || !tokens.next(m_token))
      at.fail("expected '# nodes N' or '# nodes N edges M'");
    header.edges = parse_id(m_token, at, "edge count");
  }
  if (tokens.next(token)) at.fail("unexpected " + text::Located::quote(token) + " in the header");
  return header;
}

GraphFile parse_edge_list(std::string_view bytes, const std::string& source) {
  GraphFile graph;
  text::Lines lines{bytes};
  At at{source};
  std::optional<EdgeListHeader> header;
  CostPresence presence;
  std::vector<Decimal> costs;
  std::string_view line, token;
  while (lines.next(line)) {
    at.line = lines.line;
    const std::string_view data = text::strip_comment(line);
    if (graph.edges.empty() && data.size() < line.size()) {
      // Only a whole-line comment before the first edge can be the header.
      text::Tokens before{data};
      if (!before.next(token)) {
        if (std::optional<EdgeListHeader> h = header_of(line.substr(data.size() + 1), at)) {
          if (header) {
            at.fail("a second '# nodes' header (the first is line " + std::to_string(header->line) +
                    ")");
          }
          header = h;
        }
      }
    }
    text::Tokens tokens{data};
    if (!tokens.next(token)) continue;
    std::string_view second;
    if (!tokens.next(second)) at.fail("expected two node ids 'U V'");
    const std::array<NodeId, 2> ends{parse_id(token, at, "node id"),
                                     parse_id(second, at, "node id")};
    for (NodeId id : ends) {
      if (header && id >= header->nodes) {
        at.fail("node " + std::to_string(id) + " out of range (the header on line " +
                std::to_string(header->line) + " declares " + std::to_string(header->nodes) +
                " nodes)");
      }
    }
    graph.edges.push_back(ends);
    graph.edge_lines.push_back(static_cast<std::uint32_t>(at.line));
    const bool has_cost = tokens.next(token);
    presence.check(has_cost, at);
    if (has_cost) costs.push_back(parse_cost(token, at));
    if (tokens.next(token)) at.fail("unexpected " + text::Located::quote(token));
  }
  set_costs(costs, graph);
  if (header) {
    at.line = header->line;
    if (header->edges && *header->edges != graph.edges.size()) {
      at.fail("header declares " + std::to_string(*header->edges) + " edges, the file has " +
              std::to_string(graph.edges.size()));
    }
    check_node_count(header->nodes, graph.edges.size(), at);
    graph.node_count = header->nodes;
    return graph;
  }
  if (graph.edges.empty()) empty_file(at);
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
  at.line = graph.edge_lines[largest_edge];
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
