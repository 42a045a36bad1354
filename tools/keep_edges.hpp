#pragma once
// --keep-edges FILE: the edges a user wants kept (never removed by a pair), as vertex pairs.

#include <array>
#include <string>
#include <vector>

#include "petersen/mesh/mesh.hpp"

namespace petersen::cli {

/// Reads "a b" per line (0-based vertex ids below `vertex_count`, the mesh's; blank lines and '#'
/// comments skipped). Throws MeshError naming the file and line for anything else, an id out of
/// range included.
std::vector<std::array<VertexId, 2>> read_keep_edges(const std::string& path,
                                                     std::size_t vertex_count);

}  // namespace petersen::cli
