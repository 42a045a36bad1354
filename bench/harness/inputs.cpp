#include "inputs.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "petersen/io/read_mesh.hpp"
#include "plate.hpp"
#include "simplify.hpp"

namespace petersen::bench {

namespace {

// Fitted plates are within this of their target triangle count (Table 4.2 asks for 2 %).
constexpr double kFitTolerance = 0.005;
constexpr std::uint32_t kMaxPlateUnits = 200;

bool is_mesh_file(const std::filesystem::path& path) {
  std::string name = path.filename().string();
  if (name.ends_with(".gz")) name.resize(name.size() - 3);
  return name.ends_with(".off") || name.ends_with(".obj") || name.ends_with(".ply");
}

std::string stem_of(const std::filesystem::path& path) {
  std::string name = path.filename().string();
  if (name.ends_with(".gz")) name.resize(name.size() - 3);
  return name.substr(0, name.rfind('.'));
}

std::string describe(const PlateShape& shape) {
  std::ostringstream text;
  text << shape.holes_x << "x" << shape.holes_y << (shape.dents ? " dents" : " holes") << ", walls "
       << shape.wall_x << "/" << shape.wall_y << ", holes " << shape.hole_x << "/" << shape.hole_y
       << ", thickness " << shape.thickness;
  if (shape.dents) text << ", dent depth " << shape.dent_depth;
  return text.str();
}

// A mesh file's triangles: every face must be one (build_dual names the first that is not), and
// what else the file carries is not needed.
PolygonMesh read_triangles(const std::string& path) {
  PolygonMesh mesh = read_mesh(path);
  mesh.attributes = {};
  return mesh;
}

InputSpec plate_input(std::string name, std::string group, const std::string& how,
                      const PlateShape& shape) {
  return {std::move(name),        std::move(group), how + "; plate " + describe(shape),
          shape.triangle_count(), shape.genus(),    [shape] { return plate_mesh(shape); }};
}

}  // namespace

std::vector<InputSpec> shared_mesh_inputs(const std::string& directory) {
  std::vector<std::filesystem::path> files;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(directory, error))
    if (entry.is_regular_file() && is_mesh_file(entry.path())) files.push_back(entry.path());
  std::sort(files.begin(), files.end(), [](const auto& a, const auto& b) {
    return std::filesystem::file_size(a) < std::filesystem::file_size(b);
  });
  std::vector<InputSpec> inputs;
  for (const auto& path : files) {
    inputs.push_back({stem_of(path), "mesh", "shared mesh " + path.filename().string(), 0,
                      std::nullopt, [path] { return read_triangles(path.string()); }});
  }
  return inputs;
}

std::vector<InputSpec> family_inputs(char family, const std::vector<int>& members) {
  auto fit = [family](std::uint64_t triangles) {
    return family == 'A' ? fit_plate(62, 62, true, triangles, kFitTolerance, kMaxPlateUnits)
                         : fit_plate(70, 50, false, triangles, kFitTolerance, kMaxPlateUnits);
  };
  const PlateShape largest = fit(kPaperTable42[family == 'A' ? 0 : 5].triangles);
  std::vector<InputSpec> inputs;
  for (int member : members) {
    std::string name(1, family);
    name += std::to_string(member);
    const std::optional<PaperMesh> paper = paper_mesh(name);
    if (!paper) throw std::invalid_argument("no family member " + name + " in Table 4.2");
    // As in the paper, the smaller members are simplifications of the largest one.
    if (member > 1) {
      const std::uint64_t target = paper->triangles;
      inputs.push_back({name, std::string(1, family),
                        "simplified from " + std::string(1, family) +
                            "1 (shortest contractible edge first, link condition); " +
                            describe(largest),
                        target, largest.genus(),
                        [largest, target] { return simplify(plate_mesh(largest), target); }});
      continue;
    }
    inputs.push_back(plate_input(name, std::string(1, family), "regular", fit(paper->triangles)));
  }
  return inputs;
}

std::vector<InputSpec> doubling_inputs(std::uint32_t steps) {
  // Every dimension scales with the subdivision s, so the triangles grow as s²: s ≈ √2^k·s₀.
  const double unit = double(uniform_plate(8, 8, true, 1).triangle_count());
  std::vector<InputSpec> inputs;
  for (std::uint32_t k = 0; k < steps; ++k) {
    const double s = std::round(std::sqrt(double(std::uint64_t{65536} << k) / unit));
    std::string name = "D";
    name += std::to_string(k);
    inputs.push_back(
        plate_input(name, "doubling", "regular",
                    uniform_plate(8, 8, true, std::max<std::uint32_t>(1, std::uint32_t(s)))));
  }
  return inputs;
}

MeshFacts mesh_facts(const PolygonMesh& mesh, std::uint32_t components) {
  std::vector<std::uint8_t> used(mesh.positions.size(), 0);
  for (VertexId v : mesh.corners) used[v] = 1;
  MeshFacts facts;
  facts.vertices = static_cast<std::uint64_t>(std::count(used.begin(), used.end(), 1));
  facts.triangles = mesh.face_count();
  facts.edges = 3 * facts.triangles / 2;
  const std::int64_t euler =
      std::int64_t(facts.vertices) - std::int64_t(facts.edges) + std::int64_t(facts.triangles);
  facts.genus = (2 * std::int64_t{components} - euler) / 2;
  return facts;
}

}  // namespace petersen::bench
