// petersen_check_quads SOURCE OUTPUT: the independent check of a conversion's output file against
// its input, for outputs too large for a unit test (the out-of-core runs of bench/RESULTS.md).
// Reads both with the ordinary reader and checks, without the library's pairing code, that the
// output has the source's positions and its faces are the source's triangles each used once
// (pairing_problem) and, where every face is a quad, that they form a closed quad mesh of the
// same surface (quad_mesh_problem). An output with more vertices than the source is an
// --all-quad output, checked by all_quad_file_problem (quad_mesh_check.hpp). Prints the counts and
// exits 0, or prints the first problem and exits 1. O(F log F) time; about 160 bytes per triangle
// (15.3 GB at 10^8).

#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>

#include "petersen/io/read_mesh.hpp"
#include "quad_mesh_check.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s SOURCE OUTPUT\n", argv[0]);
    return 2;
  }
  try {
    const petersen::PolygonMesh source = petersen::read_mesh(argv[1]);
    const petersen::PolygonMesh output = petersen::read_mesh(argv[2]);
    if (output.positions.size() > source.positions.size()) {
      // Vertices added: an --all-quad output (all_quad_file_problem).
      petersen::testing::AllQuadFileCounts counts;
      const std::string problem = petersen::testing::all_quad_file_problem(source, output, counts);
      if (!problem.empty()) {
        std::fprintf(stderr, "%s: %s\n", argv[2], problem.c_str());
        return 1;
      }
      std::printf(
          "%s: all quads: %llu quads (%llu triangles kept, repeating a vertex), "
          "%llu midpoints and %llu centres added; a refinement of the source's surface\n",
          argv[2], (unsigned long long)counts.quads, (unsigned long long)counts.kept_triangles,
          (unsigned long long)counts.midpoints, (unsigned long long)counts.centres);
      return 0;
    }
    std::uint64_t quads = 0;
    std::string problem = output.positions == source.positions
                              ? petersen::testing::pairing_problem(source, output, quads)
                              : "the positions differ from the source's";
    const bool all_quads = problem.empty() && 2 * quads == source.face_count();
    if (all_quads) problem = petersen::testing::quad_mesh_problem(source, output);
    if (!problem.empty()) {
      std::fprintf(stderr, "%s: %s\n", argv[2], problem.c_str());
      return 1;
    }
    std::printf("%s: %llu quads and %llu triangles, the source's %llu triangles each once%s\n",
                argv[2], (unsigned long long)quads,
                (unsigned long long)(source.face_count() - 2 * quads),
                (unsigned long long)source.face_count(),
                all_quads ? "; a quad mesh of the same surface" : "");
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
}
