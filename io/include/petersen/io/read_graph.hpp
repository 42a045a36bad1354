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

// Either format may give each edge a cost, a third number on its line ("e U V C", "U V C"): an
// integer of at most 2^40 in absolute value, on every edge line or on none.
enum class GraphFormat {
  dimacs,  ///< "c" comment lines, one "p edge N M" line ("p col" too), M lines "e U V", 1-based
  edges,   ///< one "U V" per line, 0-based, '#' comments; a first line "N M" is a header when M
           ///< equals the number of edge lines after it (without one, N is the largest id + 1)
};

/// The largest cost a graph file may give an edge, in absolute value: 2^40, the bound of the
/// minimum-cost matching's costs (kMaxCost).
inline constexpr std::int64_t kMaxFileCost = std::int64_t{1} << 40;

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
  /// The edges' costs, in the edges' order, when the file gives them; else empty.
  std::vector<std::int64_t> costs;
};

/// Parses a graph file's bytes; `source` names it in errors. Throws FileError
/// "source:line: what" for a line that does not parse, an id out of range, a cost that is not
/// an integer within kMaxFileCost, an edge line without a cost in a file whose other edge lines
/// have one (or the reverse), a missing or repeated DIMACS header, an edge count that differs
/// from the header's, or more nodes than the file's edges could touch plus 2^24 isolated ones
/// (so that a forged count allocates nothing absurd). O(bytes).
GraphFile parse_graph(std::string_view bytes, GraphFormat format, const std::string& source);

/// Reads and parses a graph file (decompressed first when it is gzip), in the given format or the
/// one its extension names. Throws FileError naming the path when it cannot be read.
GraphFile read_graph(const std::string& path, std::optional<GraphFormat> format = std::nullopt);

}  // namespace petersen
