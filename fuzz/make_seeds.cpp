// Writes the fuzzers' seed corpora: small meshes made by the project's own generators and
// writers, in every format the readers take (OFF, OBJ in several corner spellings and with
// dangling attribute references, PLY ascii, binary little and big endian, faces and triangle
// strips), triangles, polygons, degenerate and duplicate faces; and small graphs from the graph
// generators as DIMACS and edge lists, with and without costs. Usage: petersen_fuzz_seeds DIR;
// writes DIR/off, DIR/obj, DIR/ply, DIR/dimacs and DIR/edges.

#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "petersen/generators/graph_generators.hpp"
#include "petersen/generators/surface_generators.hpp"
#include "petersen/io/write_mesh.hpp"

namespace {

using namespace petersen;
namespace fs = std::filesystem;

// A pentagonal prism (two pentagons, five quads) and, beside it, a fan of a hexagon, a triangle
// and a face with a repeated corner: polygons of several arities in one mesh.
PolygonMesh mixed_polygons() {
  PolygonMesh mesh;
  for (int level = 0; level < 2; ++level) {
    for (int k = 0; k < 5; ++k) {
      mesh.positions.push_back({std::cos(1.2566 * k), std::sin(1.2566 * k), double(level)});
    }
  }
  const std::vector<VertexId> bottom{4, 3, 2, 1, 0}, top{5, 6, 7, 8, 9};
  mesh.add_face(bottom);
  mesh.add_face(top);
  for (VertexId k = 0; k < 5; ++k) {
    const std::vector<VertexId> side{k, VertexId((k + 1) % 5), VertexId(5 + (k + 1) % 5),
                                     VertexId(5 + k)};
    mesh.add_face(side);
  }
  const std::vector<VertexId> triangle{0, 1, 5}, hexagon{0, 1, 2, 3, 4, 5}, repeated{0, 1, 0, 2};
  mesh.add_face(triangle);
  mesh.add_face(hexagon);
  mesh.add_face(repeated);
  return mesh;
}

// The mesh with every kind of attribute the writers write back: a texture coordinate and normal
// per corner (some corners without), materials, groups, objects and smoothing groups per face,
// a material library, byte colours per vertex and a float property per face; each format's
// writer keeps what it holds, so the seeds hold the readers' attribute syntax.
PolygonMesh with_attributes(PolygonMesh mesh) {
  MeshAttributes& a = mesh.attributes;
  for (std::uint32_t c = 0; c < mesh.corners.size(); ++c) {
    a.texcoords.push_back({0.25 * (c % 5), 0.125 * (c % 7), 0});
    a.corner_texcoord.push_back(c % 9 == 4 ? kNoAttribute : c);
    a.corner_normal.push_back(c % 3);
  }
  a.normals = {{0, 0, 1}, {0, 1, 0}, {1, 0, 0}};
  a.material_names = {"red", "blue"};
  a.group_names = {"left part"};
  a.object_names = {"thing"};
  a.material_libraries = {"scene.mtl"};
  for (std::uint32_t f = 0; f < mesh.face_count(); ++f) {
    a.face_material.push_back(f % 2);
    a.face_group.push_back(f < 2 ? kNoAttribute : 0);
    a.face_object.push_back(0);
    a.face_smoothing.push_back(f % 3);
  }
  for (const char* name : {"red", "green", "blue"}) {
    PropertyColumn column{name, ScalarType::uint8, {}};
    for (std::size_t v = 0; v < mesh.positions.size(); ++v)
      column.values.push_back(double(v % 256));
    a.vertex_properties.push_back(std::move(column));
  }
  PropertyColumn quality{"quality", ScalarType::float32, {}};
  for (std::uint32_t f = 0; f < mesh.face_count(); ++f) quality.values.push_back(0.5 * f);
  a.face_properties.push_back(std::move(quality));
  return mesh;
}

void save(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// OBJ with corners spelled v/vt/vn, v//vn and negative (relative) indices.
std::string obj_spellings(const PolygonMesh& mesh) {
  std::string out = "# seed\nmtllib m.mtl\nvt 0 0\nvn 0 0 1\n";
  for (const auto& p : mesh.positions) {
    out += "v " + std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) +
           "\n";
  }
  const long count = static_cast<long>(mesh.positions.size());
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    out += f % 2 ? "f" : "g part\nf";
    int k = 0;
    for (VertexId v : mesh.face(static_cast<FaceId>(f))) {
      const long one_based = long(v) + 1, relative = long(v) - count;
      switch ((f + k++) % 3) {
        case 0:
          out += " " + std::to_string(one_based) + "/1/1";
          break;
        case 1:
          out += " " + std::to_string(relative) + "//1";
          break;
        default:
          out += " " + std::to_string(one_based);
      }
    }
    out += "\n";
  }
  return out;
}

// PLY in ascii or binary big endian, with float coordinates, an extra property and an extra
// element, so the readers' skipping and conversions are in the corpus too.
std::string ply_other(const PolygonMesh& mesh, bool ascii) {
  std::string out = std::string("ply\nformat ") + (ascii ? "ascii" : "binary_big_endian") +
                    " 1.0\ncomment seed\nelement vertex " + std::to_string(mesh.positions.size()) +
                    "\nproperty float x\nproperty uchar red\nproperty float y\nproperty float z\n"
                    "element face " +
                    std::to_string(mesh.face_count()) +
                    "\nproperty list uchar int vertex_indices\nproperty float quality\n"
                    "element edge 1\nproperty list ushort uint pair\nend_header\n";
  auto put = [&](const void* p, std::size_t n) {
    std::string raw(static_cast<const char*>(p), n);
    if (std::endian::native == std::endian::little) raw = std::string(raw.rbegin(), raw.rend());
    out += raw;
  };
  const std::uint8_t red = 7;
  const float quality = 0.5f;
  for (const auto& p : mesh.positions) {
    const float xyz[3] = {float(p[0]), float(p[1]), float(p[2])};
    if (ascii) {
      out += std::to_string(xyz[0]) + " 7 " + std::to_string(xyz[1]) + " " +
             std::to_string(xyz[2]) + "\n";
      continue;
    }
    put(&xyz[0], 4);
    put(&red, 1);
    put(&xyz[1], 4);
    put(&xyz[2], 4);
  }
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const auto face = mesh.face(static_cast<FaceId>(f));
    const std::uint8_t n = static_cast<std::uint8_t>(face.size());
    if (ascii) {
      out += std::to_string(n);
      for (VertexId v : face) out += " " + std::to_string(v);
      out += " 0.5\n";
      continue;
    }
    put(&n, 1);
    for (VertexId v : face) {
      const std::int32_t index = static_cast<std::int32_t>(v);
      put(&index, 4);
    }
    put(&quality, 4);
  }
  const std::uint16_t two = 2;
  const std::uint32_t pair[2] = {0, 1};
  if (ascii) {
    out += "2 0 1\n";
  } else {
    put(&two, 2);
    put(&pair[0], 4);
    put(&pair[1], 4);
  }
  return out;
}

// The mesh's triangles as PLY triangle strips (ascii or binary little endian): each triangle a
// strip of its own, the first few joined into one strip by a repeated vertex, a -1 between
// strips.
std::string ply_tristrips(const PolygonMesh& mesh, bool ascii) {
  std::vector<std::int32_t> items;
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    const auto c = mesh.face(f);
    if (c.size() != 3) continue;
    items.insert(items.end(), c.begin(), c.end());
    if (f % 2 == 0) items.push_back(c[2]);  // a turn: triangles repeating a vertex
    items.push_back(-1);
  }
  std::string out = std::string("ply\nformat ") + (ascii ? "ascii" : "binary_little_endian") +
                    " 1.0\nelement vertex " + std::to_string(mesh.positions.size()) +
                    "\nproperty float x\nproperty float y\nproperty float z\nelement tristrips 1"
                    "\nproperty list int int vertex_indices\nend_header\n";
  auto put = [&](const void* p, std::size_t n) {
    std::string raw(static_cast<const char*>(p), n);
    if (std::endian::native == std::endian::big) raw = std::string(raw.rbegin(), raw.rend());
    out += raw;
  };
  for (const auto& p : mesh.positions) {
    const float xyz[3] = {float(p[0]), float(p[1]), float(p[2])};
    if (ascii) {
      out += std::to_string(xyz[0]) + " " + std::to_string(xyz[1]) + " " + std::to_string(xyz[2]) +
             "\n";
    } else {
      for (float x : xyz) put(&x, 4);
    }
  }
  const auto count = static_cast<std::int32_t>(items.size());
  if (ascii) {
    out += std::to_string(count);
    for (std::int32_t v : items) out += " " + std::to_string(v);
    out += "\n";
  } else {
    put(&count, 4);
    for (std::int32_t v : items) put(&v, 4);
  }
  return out;
}

// An OBJ whose faces name normals and texture coordinates the file does not have (as a
// subdivision test suite writes them), every other face.
std::string obj_dangling(const PolygonMesh& mesh) {
  std::string out = "# seed\nvt 0 0\n";
  for (const auto& p : mesh.positions) {
    out += "v " + std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) +
           "\n";
  }
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    out += "f";
    for (VertexId v : mesh.face(f)) {
      out += " " + std::to_string(v + 1) + (f % 2 == 0 ? "//1" : "/2");
    }
    out += "\n";
  }
  return out;
}

// The mesh with degenerate faces (a triangle's corner collapsed onto the one before it) and a
// duplicate of its first face.
PolygonMesh with_degenerate_faces(PolygonMesh mesh) {
  const std::array<VertexId, 3> sliver{mesh.corners[0], mesh.corners[1], mesh.corners[0]};
  const std::vector<VertexId> first(mesh.face(0).begin(), mesh.face(0).end());
  mesh.add_face(sliver);
  mesh.add_face(first);
  mesh.corners[mesh.face(1).data() - mesh.corners.data() + 1] = mesh.face(1)[0];
  return mesh;
}

// A graph as DIMACS (1-based, a comment, costs on every edge line when `costs`) and as an edge
// list (0-based, a header and a comment, the same costs).
void save_graph(const fs::path& dir, const std::string& name, const CubicGraph& graph, bool costs) {
  std::string dimacs = "c seed\np edge " + std::to_string(graph.node_count()) + " " +
                       std::to_string(graph.edge_count()) + "\n";
  std::string edges =
      std::to_string(graph.node_count()) + " " + std::to_string(graph.edge_count()) + "  # seed\n";
  for (EdgeId e = 0; e < graph.edge_count(); ++e) {
    const auto [a, b] = graph.endpoints(e);
    const std::string cost = costs ? " " + std::to_string(long(e % 7) * 13 - 20) : "";
    dimacs += "e " + std::to_string(a + 1) + " " + std::to_string(b + 1) + cost + "\n";
    edges += std::to_string(a) + " " + std::to_string(b) + cost + "\n";
  }
  save(dir / "dimacs" / (name + ".dimacs"), dimacs);
  save(dir / "edges" / (name + ".edges"), edges);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s DIR\n", argv[0]);
    return 2;
  }
  const fs::path dir = argv[1];
  for (const char* format : {"off", "obj", "ply", "dimacs", "edges"}) {
    fs::create_directories(dir / format);
  }
  const std::vector<std::pair<std::string, PolygonMesh>> meshes = {
      {"cube", random_closed_surface(0, 0, 0, 1)},
      {"irregular", random_closed_surface(0, 6, 12, 2)},
      {"torus", random_closed_surface(1, 2, 4, 3)},
      {"polygons", mixed_polygons()},
  };
  for (const auto& [name, mesh] : meshes) {
    for (const char* format : {"off", "obj", "ply"}) {
      write_mesh((dir / format / (name + "." + format)).string(), mesh);
    }
    for (const char* format : {"off", "obj", "ply"}) {
      write_mesh((dir / format / (name + "-attributes." + format)).string(), with_attributes(mesh));
    }
    save(dir / "obj" / (name + "-spellings.obj"), obj_spellings(mesh));
    save(dir / "ply" / (name + "-ascii.ply"), ply_other(mesh, true));
    save(dir / "ply" / (name + "-big-endian.ply"), ply_other(mesh, false));
    save(dir / "obj" / (name + "-dangling.obj"), obj_dangling(mesh));
    write_mesh((dir / "off" / (name + "-degenerate.off")).string(), with_degenerate_faces(mesh));
    if (mesh.all_triangles()) {
      save(dir / "ply" / (name + "-tristrips-ascii.ply"), ply_tristrips(mesh, true));
      save(dir / "ply" / (name + "-tristrips.ply"), ply_tristrips(mesh, false));
    }
  }
  save_graph(dir, "petersen", petersen_graph(), false);
  save_graph(dir, "petersen-costs", petersen_graph(), true);
  save_graph(dir, "random-costs", random_cubic_bridgeless(24, 3), true);
  std::size_t files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) files += entry.is_regular_file();
  std::printf("%zu seed files in %s\n", files, dir.c_str());
}
