#pragma once
// The bench's inputs: the shared real meshes, the paper's families A and B (Table 4.2), and a
// doubling series of one surface for growth curves.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "paper_figures.hpp"
#include "petersen/mesh/mesh.hpp"

namespace petersen::bench {

struct InputSpec {
  std::string name;                      ///< "armadillo-sub2", "A5", "D3", ...
  std::string group;                     ///< "mesh", "A", "B" or "doubling"
  std::string note;                      ///< how it was made, e.g. "regular (not simplified)"
  std::uint64_t expected_triangles = 0;  ///< known before loading (0 for files): sorts inputs
  std::optional<std::uint64_t> expected_genus;  ///< what the generator promises
  std::function<PolygonMesh()> load;            ///< an all-triangle mesh
};

/// Every mesh file (.off, .obj, .ply, optionally .gz) directly in `directory`, smallest file
/// first; the `invalid/` subfolder is not read. Empty when the directory does not exist.
std::vector<InputSpec> shared_mesh_inputs(const std::string& directory);

/// Members of family A (62×62 dents, genus 0) or B (70×50 through-holes, genus 3,500) named in
/// `members` (1…5). Member 1 is a regular plate fitted within a fraction of a percent of the
/// paper's triangle count; with petersen::lrs, members 2–5 are simplifications of member 1 to the
/// paper's counts (as in the paper), without it regular plates fitted at their own sizes.
std::vector<InputSpec> family_inputs(char family, const std::vector<int>& members);

/// `steps` plates of the same shape (8×8 dents, genus 0, every width and depth equal) scaled to
/// about 65,536·2^k triangles (k < steps): the integer scale makes each step ×1.8 to ×2.3.
std::vector<InputSpec> doubling_inputs(std::uint32_t steps);

/// V (referenced vertices), E, F and genus (from V − E + F = 2·components − 2g, components of
/// the dual given) of a closed triangle mesh.
struct MeshFacts {
  std::uint64_t vertices = 0, edges = 0, triangles = 0;
  std::int64_t genus = 0;
};
MeshFacts mesh_facts(const PolygonMesh& mesh, std::uint32_t components);

}  // namespace petersen::bench
