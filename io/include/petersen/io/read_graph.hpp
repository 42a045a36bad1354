#pragma once
// Graph files for `petersen match` and for library users: DIMACS and plain edge lists, plain or
// gzip-compressed, with errors located at "file:line".

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "petersen/graph/cubic_graph.hpp"
#include "petersen/io/file_error.hpp"

namespace petersen {

// Either format may give each edge a cost, a third number on its line ("e U V C", "U V C"), on
// every edge line or on none: an integer or a decimal with an optional exponent ("-2", "0.25",
// "6.02e-3"), of either sign.
enum class GraphFormat {
  dimacs,  ///< "c" comment lines, one "p edge N M" line ("p col" too), M lines "e U V", 1-based
  edges,   ///< one "U V" per line, 0-based, '#' comments; a comment "# nodes N" (or "# nodes N
           ///< edges M") before the first edge declares the node count (and checks the edges'),
           ///< else N is the largest id + 1; every other line is an edge
};

/// The largest integer cost GraphFile::costs holds, in absolute value: 2^40, the bound of the
/// minimum-cost matching's costs (kMaxCost).
inline constexpr std::int64_t kMaxFileCost = std::int64_t{1} << 40;

/// Isolated nodes a file may declare beyond those its edges touch (DIMACS header, an edge list's
/// "# nodes N" or largest id): 2^24 of them cost 64 MiB per per-node array of the matching.
inline constexpr std::uint64_t kMostIsolatedNodes = std::uint64_t{1} << 24;

std::string_view to_string(GraphFormat format);
std::optional<GraphFormat> parse_graph_format(std::string_view name);

/// The format by extension: .dimacs or .col is DIMACS, .txt or .edges an edge list, each
/// optionally followed by .gz. Throws FileError naming the path for any other name.
GraphFormat graph_format_of(const std::string& path);

/// A graph as its file gave it.
struct GraphFile {
  std::uint32_t node_count = 0;
  /// 0-based endpoints, in the file's order; loops and parallel edges kept.
  std::vector<std::array<NodeId, 2>> edges;
  /// Added to a node id to give the file's own id: 1 for DIMACS, 0 for edge lists.
  std::uint32_t first_id = 0;
  /// The file's line of each edge (1-based), for messages in the file's own terms.
  std::vector<std::uint32_t> edge_lines;
  /// The edges' costs, in the edges' order, exactly: the file's numbers times
  /// 10^cost_decimals, when that power of ten (the most digits after the point any cost has)
  /// makes every one an integer within kMaxFileCost. Empty when the file gives no costs, or
  /// when they do not fit so; real_costs then holds them.
  std::vector<std::int64_t> costs;
  std::uint32_t cost_decimals = 0;
  /// The costs as the nearest doubles, when costs cannot hold them exactly (too many digits, or
  /// too large): a solver rounds them (integer_costs) and states the tolerance. Else empty.
  std::vector<double> real_costs;

  bool has_costs() const { return !costs.empty() || !real_costs.empty(); }
  /// A node's id as the file writes it.
  std::uint64_t file_id(NodeId v) const { return std::uint64_t{v} + first_id; }
};

/// Parses a graph file's bytes; `source` names it in errors. A UTF-8 byte-order mark is
/// skipped; lines end in "\n", "\r\n" or "\r". Throws FileError "source:line: what" for a line
/// that does not parse, an id out of range, a cost that is not a finite number, an edge line
/// without a cost in a file whose other edge lines have one (or the reverse), a missing or
/// repeated header, an edge count that differs from the header's, more nodes than the file's
/// edges could touch plus kMostIsolatedNodes (so that a forged count allocates nothing absurd),
/// or an empty file (no edge and no header, in either format: "source:1: empty graph file").
/// O(bytes).
GraphFile parse_graph(std::string_view bytes, GraphFormat format, const std::string& source);

/// Reads and parses a graph file (decompressed first when it is gzip), in the given format or the
/// one its extension names. Throws FileError naming the path when it cannot be read.
GraphFile read_graph(const std::string& path, std::optional<GraphFormat> format = std::nullopt);

}  // namespace petersen
