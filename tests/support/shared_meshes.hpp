#pragma once
// The shared real meshes beside the clone (../shared/meshes), as listed in its SOURCES.md.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace petersen::testing {

struct SharedMesh {
  std::string file;  ///< e.g. "bunny.off.gz"
  std::uint32_t vertices, triangles, genus;
};

/// The closed meshes of SOURCES.md with their V, F and genus, smallest first.
const std::vector<SharedMesh>& shared_closed_meshes();
/// The folder of shared meshes, or nullopt when it is absent (tests then GTEST_SKIP).
std::optional<std::string> shared_mesh_dir();
/// Meshes at most this many triangles, for tests that must stay fast under sanitizers.
std::vector<SharedMesh> shared_meshes_up_to(std::uint32_t max_triangles);
/// A mesh file's name as a test name: "invalid/cow.obj.gz" gives "invalid_cow".
std::string test_name_of_file(const std::string& file);

}  // namespace petersen::testing
