// RapidCheck fuzzing of the parsers: small valid files with random bytes changed, cuts, and
// duplicated lines must parse or throw FileError; never crash, never allocate beyond what the
// input could describe. The sanitizer build runs this too.

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cstring>

#include "petersen/dualize/dual.hpp"
#include "petersen/io/read_mesh.hpp"
#include "petersen/mesh/mesh_report.hpp"

namespace petersen {
namespace {

std::string binary_ply(bool big) {
  std::string out = std::string("ply\nformat ") +
                    (big ? "binary_big_endian" : "binary_little_endian") +
                    " 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                    "element face 4\nproperty list uchar int vertex_indices\nend_header\n";
  auto put = [&](const void* p, std::size_t n) {
    std::string raw(static_cast<const char*>(p), n);
    if (big) raw = std::string(raw.rbegin(), raw.rend());
    out += raw;
  };
  const float xyz[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (const auto& p : xyz)
    for (float x : p) put(&x, 4);
  const std::int32_t faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  for (const auto& f : faces) {
    const std::uint8_t three = 3;
    put(&three, 1);
    for (std::int32_t v : f) put(&v, 4);
  }
  return out;
}

struct Seed {
  MeshFormat format;
  std::string bytes;
};

const std::vector<Seed>& seeds() {
  static const std::vector<Seed> all = {
      {MeshFormat::off,
       "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n"},
      {MeshFormat::obj,
       "# t\nmtllib a.mtl\nv 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nv 0 0 1 1 1 1\nvt 0 0\n"
       "vt 1 0 0.5\nvn 0 0 1\no thing\ng a group\nusemtl m\ns 1\nf 1 3 2\nf 1/1 2/-1 4/1\n"
       "usemtl n\ns off\nl 1 2\nf 2//1 3//1 4//-1\ng\nf -4/1/1 -1/2/1 -2/1/1\n"},
      {MeshFormat::off,
       "CNOFF\n4 4 6\n0 0 0 0 0 1 255 0 0 255\n1 0 0 0 0 1 0 255 0 255\n0 1 0 0 0 1 0 0 255 9\n"
       "0 0 1 0 0 1 9 9 9 9\n3 0 2 1 0.5 0.5 0.5\n3 0 1 3\n3 1 2 3 1 0 0\n3 0 3 2 7\n"},
      {MeshFormat::ply,
       "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty uchar red\nproperty "
       "float y\nproperty float z\nproperty list uchar int n\nelement face 4\nproperty list "
       "uchar int vertex_indices\nproperty short q\nproperty list uchar float texcoord\nelement "
       "edge 1\nproperty int a\nend_header\n0 1 0 0 0\n1 2 0 0 1 5\n0 3 1 0 0\n0 4 0 1 0\n"
       "3 0 2 1 -3 6 0 0 1 0 1 1\n3 0 1 3 4 0\n3 1 2 3 5 0\n3 0 3 2 6 6 0 0 0 0 0 0\n7\n"},
      {MeshFormat::ply,
       "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty "
       "float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 "
       "0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n"},
      {MeshFormat::ply, binary_ply(false)},
      {MeshFormat::ply, binary_ply(true)},
  };
  return all;
}

// One edit: overwrite a byte, insert a byte, cut the tail, or duplicate a line.
std::string mutate(std::string bytes, int kind, std::size_t where, char byte) {
  if (bytes.empty()) return bytes;
  where %= bytes.size();
  switch (kind) {
    case 0:
      bytes[where] = byte;
      break;
    case 1:
      bytes.insert(bytes.begin() + static_cast<std::ptrdiff_t>(where), byte);
      break;
    case 2:
      bytes.resize(where);
      break;
    default: {
      const std::size_t begin =
          bytes.rfind('\n', where) == std::string::npos ? 0 : bytes.rfind('\n', where) + 1;
      const std::size_t end = bytes.find('\n', where);
      const std::string line =
          bytes.substr(begin, end == std::string::npos ? std::string::npos : end - begin + 1);
      bytes.insert(begin, line);
    }
  }
  return bytes;
}

// One to five mutations drawn at random. Digits, signs and separators make structured damage more
// likely than random bytes alone.
std::string damaged(std::string bytes) {
  const auto edits = *rc::gen::inRange(1, 6);
  for (int i = 0; i < edits; ++i) {
    const int kind = *rc::gen::inRange(0, 4);
    const auto where = *rc::gen::arbitrary<std::size_t>();
    const char byte = *rc::gen::oneOf(rc::gen::arbitrary<char>(),
                                      rc::gen::elementOf(std::string("0123456789-+.e \n/#")));
    bytes = mutate(std::move(bytes), kind, where, byte);
  }
  return bytes;
}

TEST(ParserFuzz, SeedsParseAsTetrahedra) {
  for (const Seed& seed : seeds()) {
    const PolygonMesh mesh = parse_mesh(seed.bytes, seed.format, "seed");
    EXPECT_EQ(mesh.face_count(), 4u);
    EXPECT_TRUE(mesh.all_triangles());
    EXPECT_EQ(inspect_mesh(mesh).genus, 0);
  }
}

RC_GTEST_PROP(ParserFuzz, MutatedFilesParseOrThrowFileError, ()) {
  const Seed& seed = *rc::gen::elementOf(seeds());
  const std::string bytes = damaged(seed.bytes);
  try {
    const PolygonMesh mesh = parse_mesh(bytes, seed.format, "fuzz");
    RC_ASSERT(mesh.positions.size() + mesh.face_count() <= bytes.size());
    // Whatever parsed must be safe to inspect and to dualize (which may refuse it: a closed
    // surface of triangles it accepts).
    const MeshReport report = inspect_mesh(mesh);
    RC_ASSERT(report.faces == mesh.face_count());
    const bool triangles = report.faces_by_arity.size() == 1 && report.faces_by_arity.count(3);
    try {
      build_dual(mesh);
    } catch (const MeshError&) {
      RC_ASSERT(!report.closed() || !triangles);
    }
  } catch (const FileError& e) {
    RC_ASSERT(std::string(e.what()).rfind("fuzz", 0) == 0);  // every message names its source
  }
}

// The polygon reader on the same damaged files and on polygon seeds: FileError or a well-formed
// mesh (every face of 3 or more corners, every corner a vertex).
const std::vector<Seed>& polygon_seeds() {
  static const std::vector<Seed> all = [] {
    std::vector<Seed> seeds = petersen::seeds();
    seeds.push_back({MeshFormat::off,
                     "OFF\n5 3 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 2 0\n4 0 1 2 3\n3 0 2 4\n"
                     "5 4 3 2 4 1\n"});
    seeds.push_back({MeshFormat::obj,
                     "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 2 0\nf 1 2/1 3//1 4/1/1\n"
                     "f 1 3 5\nf -1 4 -3 5 -4\n"});
    seeds.push_back({MeshFormat::ply,
                     "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float "
                     "y\nproperty float z\nelement face 3\nproperty list uchar int "
                     "vertex_indices\nend_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 2 0\n4 0 1 2 "
                     "3\n3 0 2 4\n5 4 3 2 4 1\n"});
    // Files as they come: triangle strips with a restart and a turn, dangling attribute
    // references, degenerate and duplicate faces.
    seeds.push_back({MeshFormat::ply,
                     "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float "
                     "y\nproperty float z\nelement tristrips 2\nproperty list int int "
                     "vertex_indices\nend_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 2 0\n"
                     "8 0 1 3 2 2 4 -1 0\n4 1 2 4 3\n"});
    seeds.push_back({MeshFormat::obj,
                     "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nf 1//1 2//1 3//1\n"
                     "f 1/1 3/2 4/1\nf 1/-2 2 4\n"});
    seeds.push_back({MeshFormat::off,
                     "OFF\n4 4 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 0 1\n3 0 1 2\n3 2 1 0\n"
                     "4 0 1 1 3\n"});
    return seeds;
  }();
  return all;
}

RC_GTEST_PROP(ParserFuzz, MutatedPolygonFilesParseOrThrowFileError, ()) {
  const Seed& seed = *rc::gen::elementOf(polygon_seeds());
  const std::string bytes = damaged(seed.bytes);
  try {
    const PolygonMesh mesh = parse_mesh(bytes, seed.format, "fuzz");
    RC_ASSERT(mesh.positions.size() + mesh.face_count() <= bytes.size());
    for (FaceId f = 0; f < mesh.face_count(); ++f) {
      RC_ASSERT(mesh.face(f).size() >= 3u);
      for (VertexId v : mesh.face(f)) RC_ASSERT(v < mesh.positions.size());
    }
  } catch (const FileError& e) {
    RC_ASSERT(std::string(e.what()).rfind("fuzz", 0) == 0);
  }
}

}  // namespace
}  // namespace petersen
