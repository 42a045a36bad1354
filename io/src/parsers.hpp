#pragma once
// The per-format parsers behind parse_mesh; each throws located FileErrors.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "petersen/io/read_mesh.hpp"
#include "petersen/mesh/mesh.hpp"

namespace petersen {

/// Each parser appends to `dropped` one line per kind of thing it read past (see read_mesh).
/// The mesh's arrays are on `memory` (ReadMeshOptions::memory).
PolygonMesh parse_off(std::string_view bytes, const std::string& source,
                      std::vector<std::string>& dropped, std::pmr::memory_resource* memory);
PolygonMesh parse_obj(std::string_view bytes, const std::string& source,
                      const ReadMeshOptions& options, std::vector<std::string>& dropped);
PolygonMesh parse_ply(std::string_view bytes, const std::string& source,
                      std::vector<std::string>& dropped, std::pmr::memory_resource* memory);

/// Counts what a text reader reads past, per kind, remembering the first line of each; the
/// dropped list gets one line per kind ("3 'l' lines (polylines), the first at line 12") rather
/// than one per occurrence.
class DroppedTally {
 public:
  void add(std::string_view kind, std::size_t line) {
    for (Entry& entry : entries_) {
      if (entry.kind == kind) {
        ++entry.count;
        return;
      }
    }
    entries_.push_back({std::string(kind), 1, line});
  }
  void report(std::vector<std::string>& dropped) const {
    for (const Entry& entry : entries_) {
      dropped.push_back(std::to_string(entry.count) + " " + entry.kind + ", the first at line " +
                        std::to_string(entry.first_line));
    }
  }

 private:
  struct Entry {
    std::string kind;
    std::uint64_t count = 0;
    std::size_t first_line = 0;
  };
  std::vector<Entry> entries_;
};

/// Appends `value` for the next element (corner or face) to a per-element attribute array that
/// stays empty while every value is `none`: at the first other value it is filled with `none` for
/// the `before` elements already read.
inline void push_attribute(std::pmr::vector<std::uint32_t>& values, std::uint32_t value,
                           std::uint32_t none, std::size_t before) {
  if (values.empty()) {
    if (value == none) return;
    values.assign(before, none);
  }
  values.push_back(value);
}

/// True when a face of `corners` corners is a face: three or more.
inline bool corner_count_ok(std::uint64_t corners) {
  return corners >= 3;
}

/// The complaint about face `face` whose corner count corner_count_ok refused, worded the same
/// by every parser.
inline std::string corner_count_error(std::uint64_t face, std::uint64_t corners) {
  return "face " + std::to_string(face) + " has " + std::to_string(corners) +
         " corners; a face needs at least 3";
}

/// The corners a mesh can hold: face_start holds 32-bit offsets.
inline bool corners_fit(const PolygonMesh& mesh, std::uint64_t more) {
  return mesh.corners.size() + more <= 0xFFFFFFFFu;
}

}  // namespace petersen
