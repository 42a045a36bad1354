#include "shared_meshes.hpp"

#include <cctype>
#include <cstdlib>
#include <filesystem>

namespace petersen::testing {

const std::vector<SharedMesh>& shared_closed_meshes() {
  static const std::vector<SharedMesh> meshes = {
      {"decimated-knight.off.gz", 502, 1000, 0},
      {"spot.obj.gz", 2930, 5856, 0},
      {"bunny.off.gz", 3485, 6966, 0},
      {"3holes.off.gz", 3596, 7200, 3},
      {"fertility.off.gz", 4494, 9000, 4},
      {"homer.obj.gz", 6002, 12000, 0},
      {"fandisk.obj.gz", 6475, 12946, 0},
      {"cheburashka.obj.gz", 6669, 13334, 0},
      {"rocker-arm.obj.gz", 10044, 20088, 1},
      {"bumpy-cube.obj.gz", 19970, 39936, 0},
      {"armadillo.obj.gz", 43243, 86482, 0},
      {"nefertiti.obj.gz", 49971, 99938, 0},
      {"fertility-sub3.ply.gz", 287994, 576000, 4},
      {"rocker-arm-sub3.ply.gz", 642816, 1285632, 1},
      {"armadillo-sub2.ply.gz", 691858, 1383712, 0},
  };
  return meshes;
}

std::optional<std::string> shared_mesh_dir() {
  const char* env = std::getenv("PETERSEN_SHARED_MESHES");
  std::string dir = env ? env : "../shared/meshes";
  if (std::filesystem::is_directory(dir)) return dir;
  return std::nullopt;
}

std::vector<SharedMesh> shared_meshes_up_to(std::uint32_t max_triangles) {
  std::vector<SharedMesh> out;
  for (const auto& m : shared_closed_meshes())
    if (m.triangles <= max_triangles) out.push_back(m);
  return out;
}

std::string test_name_of_file(const std::string& file) {
  std::string name = file.substr(0, file.find('.'));
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

}  // namespace petersen::testing
