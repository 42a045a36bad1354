// libFuzzer target for the whole conversion, bytes to quads: the input is an OBJ, OFF or PLY file
// (PETERSEN_FUZZ_FORMAT), its last byte also choosing the options (algorithm, objective, all-quad,
// a corner threshold, which attribute borders may be crossed). What does not parse is the readers'
// business (their own targets); what parses must convert, or throw MeshError where the options ask
// for the impossible (all-quad with a leftover triangle that cannot become a quad). Any other
// exception, a crash, a sanitizer report, a hang or a huge allocation is a finding, and so is a
// result that breaks what QuadResult promises: an uncertified pairing, pair counts that do not add
// up, an output face out of range, attributes inconsistent with the faces, a triangle left by
// all-quad; and `petersen info`'s report, `petersen render` and the writers run on the way (the
// result read back the same).

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "petersen/io/read_mesh.hpp"
#include "petersen/io/write_mesh.hpp"
#include "petersen/mesh/mesh_report.hpp"
#include "petersen/quadrangulate/quadrangulate.hpp"
#include "petersen/render/render_mesh.hpp"
#include "require.hpp"

namespace {

using namespace petersen;

// Equal values, NaN equal to NaN: a property or a PLY texture coordinate is kept as read, NaN
// included (parse_ply.cpp), and must read back so.
bool same(double a, double b) {
  return a == b || (std::isnan(a) && std::isnan(b));
}
template <class Values>
bool same(const Values& a, const Values& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                    [](double x, double y) { return same(x, y); });
}

constexpr MeshFormat kFormat = MeshFormat::PETERSEN_FUZZ_FORMAT;
constexpr const char* kOwnExtension = kFormat == MeshFormat::obj   ? ".obj"
                                      : kFormat == MeshFormat::ply ? ".ply"
                                                                   : ".off";

QuadOptions options_from(std::uint8_t choice) {
  // ds and gw pair small closed components by reductions, lrs by contraction; frink is their
  // O(n^2) oracle (inputs stay under -max_len, so it stays quick).
  constexpr PairingAlgorithm kAlgorithms[] = {Algorithm::ps,        Algorithm::sg, kLrs,
                                              Algorithm::gw,        Algorithm::ds, Algorithm::frink,
                                              Algorithm::automatic, kLrs};
  QuadOptions options;
  options.algorithm = kAlgorithms[choice & 7];
  options.objective = (choice & 8) ? Objective::quality : Objective::pairs;
  options.all_quad = (choice & 16) != 0;
  if (choice & 32) options.max_corner_deviation = 40.0;
  if (choice & 64) options.cross = {CutCause::uv_seam, CutCause::material, CutCause::group};
  options.threads = (choice & 128) ? 2 : 1;
  return options;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  PolygonMesh mesh;
  try {
    mesh = parse_mesh(bytes, kFormat, "fuzz");
  } catch (const FileError&) {
    return 0;
  }
  const QuadOptions options = options_from(data[size - 1]);
  QuadResult result;
  try {
    result = quadrangulate(mesh, options);
  } catch (const MeshError&) {
    REQUIRE(options.all_quad);  // the one refusal a parsed mesh may meet
    return 0;
  }
  const QuadStats& stats = result.stats;
  REQUIRE(stats.maximum_certified);
  REQUIRE(options.objective != Objective::quality || stats.optimality_certified);
  REQUIRE(stats.faces_in == mesh.face_count());
  REQUIRE(2 * stats.pairs + stats.triangles_left == stats.triangles);
  REQUIRE(stats.triangles + stats.polygons_kept == stats.faces_in);
  if (!options.all_quad) REQUIRE(result.mesh.face_count() == stats.faces_in - stats.pairs);
  REQUIRE(result.sources.size() == result.mesh.face_count());
  REQUIRE(result.mesh.positions.size() == mesh.positions.size() + stats.added_vertices);
  try {
    check_attributes(result.mesh);
  } catch (const MeshError& e) {
    fuzz::broken(e.what(), __FILE__, __LINE__);
  }
  for (std::size_t f = 0; f < result.mesh.face_count(); ++f) {
    const auto face = result.mesh.face(static_cast<FaceId>(f));
    REQUIRE(face.size() >= 3);
    REQUIRE(!options.all_quad || face.size() != 3);
    for (VertexId v : face) REQUIRE(v < result.mesh.positions.size());
  }
  // `petersen info` on the input, and the output written and read back, as OBJ, binary PLY or
  // OFF by the first byte: the same numbers and faces (write_mesh promises both); in the input's
  // own format, nothing dropped (what it carried, it can hold). A name or value the format cannot
  // spell is the writer's one refusal.
  (void)describe(inspect_mesh(mesh));
  static const std::string stem = "/dev/shm/petersen-quad-fuzz-" + std::to_string(getpid());
  // `petersen render` of the result, at its smallest (a picture of every input would be most of the
  // time), PNG or SVG by the first byte: its refusals are for paths and views, neither of which
  // occurs.
  if (data[0] & 4) {
    const std::string picture = stem + ((data[0] & 8) ? ".svg" : ".png");
    render_mesh(result.mesh, picture,
                {.width = 200,
                 .height = 200,
                 .first_added_vertex = static_cast<VertexId>(mesh.positions.size()),
                 .caption = {"fuzz"}});
    std::remove(picture.c_str());
  }
  const char* const extension[] = {".obj", ".ply", ".off"};
  const std::string path = stem + extension[data[0] % 3];
  std::vector<std::string> dropped;
  try {
    dropped = write_mesh(path, result.mesh);
  } catch (const FileError&) {
    return 0;
  }
  REQUIRE(!path.ends_with(kOwnExtension) || dropped.empty());
  const PolygonMesh back = read_mesh(path);
  std::remove(path.c_str());
  REQUIRE(back.positions == result.mesh.positions);
  REQUIRE(back.corners == result.mesh.corners);
  REQUIRE(back.face_count() == result.mesh.face_count());
  for (std::size_t f = 0; f < back.face_count(); ++f) {
    REQUIRE(back.arity(static_cast<FaceId>(f)) == result.mesh.arity(static_cast<FaceId>(f)));
  }
  if (!path.ends_with(kOwnExtension)) return 0;
  // In its own format, the values the result carries read back as they are.
  const MeshAttributes &a = result.mesh.attributes, &b = back.attributes;
  REQUIRE(b.position_type == a.position_type);
  REQUIRE(b.vertex_properties.size() == a.vertex_properties.size());
  for (std::size_t i = 0; i < a.vertex_properties.size(); ++i) {
    REQUIRE(same(b.vertex_properties[i].values, a.vertex_properties[i].values));
  }
  REQUIRE(b.face_properties.size() == a.face_properties.size());
  for (std::size_t i = 0; i < a.face_properties.size(); ++i) {
    REQUIRE(same(b.face_properties[i].values, a.face_properties[i].values));
  }
  REQUIRE(b.corner_texcoord.empty() == a.corner_texcoord.empty());
  for (std::size_t c = 0; c < a.corner_texcoord.size(); ++c) {
    const std::uint32_t i = a.corner_texcoord[c], j = b.corner_texcoord[c];
    REQUIRE((i == kNoAttribute) == (j == kNoAttribute));
    if (i != kNoAttribute) REQUIRE(same(a.texcoords[i], b.texcoords[j]));
  }
  return 0;
}
