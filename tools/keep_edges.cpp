#include "keep_edges.hpp"

#include <charconv>
#include <fstream>

namespace petersen::cli {

std::vector<std::array<VertexId, 2>> read_keep_edges(const std::string& path,
                                                     std::size_t vertex_count) {
  std::ifstream in(path);
  if (!in) throw MeshError(path + ": cannot open");
  std::vector<std::array<VertexId, 2>> edges;
  std::string line;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    const std::size_t hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    const char* p = line.data();
    const char* end = line.data() + line.size();
    auto skip_space = [&] {
      while (p != end && (*p == ' ' || *p == '\t' || *p == '\r')) ++p;
    };
    skip_space();
    if (p == end) continue;
    std::array<VertexId, 2> edge{};
    for (VertexId& v : edge) {
      skip_space();
      const auto [next, error] = std::from_chars(p, end, v);
      if (error != std::errc()) {
        throw MeshError(path + ":" + std::to_string(number) +
                        ": expected two vertex ids (0-based) per line");
      }
      p = next;
      if (v >= vertex_count) {
        throw MeshError(path + ":" + std::to_string(number) + ": vertex id " + std::to_string(v) +
                        " out of range (" + std::to_string(vertex_count) + " vertices)");
      }
    }
    skip_space();
    if (p != end) {
      throw MeshError(path + ":" + std::to_string(number) + ": more than two vertex ids");
    }
    edges.push_back(edge);
  }
  return edges;
}

}  // namespace petersen::cli
