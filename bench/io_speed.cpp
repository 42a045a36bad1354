// IO speed: reading the shared meshes and writing armadillo-sub2, in seconds,
// beside `gzip -dc FILE > /dev/null` of the same file measured in the same run.
// Usage: petersen_io_speed [mesh files...] (default: armadillo-sub2.ply.gz, nefertiti.obj.gz and
// armadillo.obj.gz from the shared meshes). Each time is the best of 5 runs, in CPU seconds
// (user + system, of this process or of the gzip child): on a machine shared with other work the
// wall clock moved by 2x between runs, the CPU time by a few percent.

#include <sys/resource.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "memory_pool.hpp"
#include "petersen/io/read_mesh.hpp"
#include "petersen/io/write_mesh.hpp"

namespace {

using namespace petersen;

// CPU seconds (user + system) of this process, or of its finished children.
double cpu_seconds(int who) {
  rusage usage;
  getrusage(who, &usage);
  return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

double best_seconds(const std::function<void()>& run, int who = RUSAGE_SELF, int runs = 5) {
  double best = 0;
  for (int r = 0; r < runs; ++r) {
    const double start = cpu_seconds(who);
    run();
    const double s = cpu_seconds(who) - start;
    if (r == 0 || s < best) best = s;
  }
  return best;
}

double gzip_seconds(const std::string& path) {
  const std::string command = "gzip -dc '" + path + "' > /dev/null";
  return best_seconds(
      [&] {
        if (std::system(command.c_str()) != 0)
          std::fprintf(stderr, "failed: %s\n", command.c_str());
      },
      RUSAGE_CHILDREN);
}

}  // namespace

int main(int argc, char** argv) {
  petersen::bench::install_memory_pool();
  std::vector<std::string> files(argv + 1, argv + argc);
  const std::string shared = PETERSEN_SHARED_MESHES;
  if (files.empty()) {
    for (const char* name : {"armadillo-sub2.ply.gz", "nefertiti.obj.gz", "armadillo.obj.gz"}) {
      files.push_back(shared + "/" + name);
    }
  }
  std::printf("%-24s %10s %10s %10s %8s\n", "file", "faces", "gzip -dc s", "read s", "read/gz");
  for (const std::string& file : files) {
    if (!std::filesystem::exists(file)) {
      std::printf("%s: absent, skipped\n", file.c_str());
      continue;
    }
    std::size_t faces = 0;
    const double read = best_seconds([&] { faces = read_mesh(file).face_count(); });
    const double gz = gzip_seconds(file);
    std::printf("%-24s %10zu %10.3f %10.3f %8.2f\n", std::filesystem::path(file).filename().c_str(),
                faces, gz, read, read / gz);
  }
  // Writing: the first file read, as binary PLY and as OBJ, into the temporary folder.
  const PolygonMesh mesh = read_mesh(files.front());
  const auto dir = std::filesystem::temp_directory_path();
  std::printf("%-24s %10s %10s\n", "write", "bytes", "s");
  for (const char* ext : {".ply", ".obj", ".ply.gz"}) {
    const std::string out = (dir / ("petersen-io-speed" + std::string(ext))).string();
    const double s = best_seconds([&] { write_mesh(out, mesh); });
    std::printf("%-24s %10ju %10.3f\n", ext, std::uintmax_t(std::filesystem::file_size(out)), s);
    std::filesystem::remove(out);
  }
}
