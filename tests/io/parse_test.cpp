// The text and binary parsers on small inputs: every accepted spelling, every located error.

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "petersen/io/read_mesh.hpp"

namespace petersen {
namespace {

std::string polygon_error_of(std::string_view bytes, MeshFormat format) {
  try {
    parse_mesh(bytes, format, "in");
  } catch (const FileError& e) {
    return e.what();
  }
  return "no error";
}

// The faces of a polygon mesh as lists of corners, for comparisons.
std::vector<std::vector<VertexId>> faces_of(const PolygonMesh& mesh) {
  std::vector<std::vector<VertexId>> faces;
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    faces.emplace_back(mesh.face(f).begin(), mesh.face(f).end());
  }
  return faces;
}

// A square, a triangle, a pentagon with a repeated corner: polygons kept exactly.
const std::vector<std::vector<VertexId>> kPolygons{{0, 1, 2, 3}, {0, 2, 4}, {4, 3, 2, 4, 1}};

#define EXPECT_ERROR(bytes, format, expected)                                 \
  do {                                                                        \
    const std::string error_ = polygon_error_of(bytes, format);               \
    EXPECT_NE(error_.find(expected), std::string::npos) << "got: " << error_; \
  } while (0)

const std::vector<std::vector<VertexId>> kTriangle{{0, 1, 2}};

TEST(ParseOff, KeywordCommentsColoursAndCountsOnTheKeywordLine) {
  for (const char* text :
       {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
        "# c\nOFF 3 1 0\n\n0 0 0 # x\n1 0 0\n0 1.0e0 +0\n3 0 1 2 255 0 0\n",
        "COFF\r\n3 1 0\r\n0 0 0 1 1 1 1\r\n1 0 0 1 1 1 1\r\n0 1 0 1 1 1 1\r\n3 0 1 2\r\n",
        "3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2"}) {
    const PolygonMesh mesh = parse_mesh(text, MeshFormat::off, "in");
    ASSERT_EQ(faces_of(mesh), kTriangle) << text;
    EXPECT_TRUE(mesh.all_triangles());
    EXPECT_EQ(mesh.positions[2][1], 1.0);
  }
}

TEST(ParseOff, Errors) {
  EXPECT_ERROR("", MeshFormat::off, "in: empty file");
  EXPECT_ERROR("\n# only a comment\n", MeshFormat::off, "in:2: empty file");
  EXPECT_ERROR("PLY\n", MeshFormat::off, "in:1: not an OFF file");
  EXPECT_ERROR("OFF\n3 1\n0 0 0\n1 0 0\n", MeshFormat::off,
               "in:2: header declares 3 vertices and 1 faces, more than the remaining 12 bytes");
  EXPECT_ERROR("OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n# padding\n", MeshFormat::off,
               "in:6: truncated: expected 1 faces, found 0");
  EXPECT_ERROR("OFF\n3 1\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n", MeshFormat::off,
               "in:4: vertex 1: bad coordinate 'nan'");
  EXPECT_ERROR("OFF\n3 1\n0 0 0\n1 0 inf\n0 1 0\n3 0 1 2\n", MeshFormat::off,
               "in:4: vertex 1: bad coordinate 'inf'");
  EXPECT_ERROR("OFF\n3 1\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n", MeshFormat::off,
               "in:4: vertex 1: expected 3 coordinates");
  EXPECT_ERROR("OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", MeshFormat::off,
               "in:6: face 0: vertex index -1 out of range (3 vertices)");
  EXPECT_ERROR("OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 3 2\n", MeshFormat::off,
               "in:6: face 0: vertex index 3 out of range");
  // A face of four corners, one repeated, is kept as written.
  EXPECT_EQ(
      faces_of(parse_mesh("OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2 0\n", MeshFormat::off, "in")),
      (std::vector<std::vector<VertexId>>{{0, 1, 2, 0}}));
  EXPECT_ERROR("OFF\n3 1000000000000000\n0 0 0\n", MeshFormat::off, "bad count");
  EXPECT_ERROR("OFF\n3 4000000000\n0 0 0\n", MeshFormat::off,
               "in:2: header declares 3 vertices and 4000000000 faces, more than the remaining");
  EXPECT_ERROR("OFF\n-3 1\n", MeshFormat::off, "in:2: bad count '-3'");
  EXPECT_ERROR("OFF\n0 0 0\n", MeshFormat::off, "in: no faces");
  EXPECT_ERROR("4OFF\n", MeshFormat::off, "only 3-dimensional OFF");
}

TEST(ParseObj, CornerSpellingsAndRelativeIndices) {
  const char* text =
      "# cube corner\nmtllib x.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\ng g\n"
      "f 1 2 3\nf 1/1 2/1 3/1\nf 1//1 2//1 3//1\nf 1/1/1 2/1/1 3/1/1\nf -3 -2 -1\n"
      "f -3/1/1 -2//1 -1/1\n";
  const PolygonMesh mesh = parse_mesh(text, MeshFormat::obj, "in");
  ASSERT_EQ(faces_of(mesh), (std::vector<std::vector<VertexId>>(6, {0, 1, 2})));
  EXPECT_EQ(mesh.positions.size(), 3u);
}

TEST(ParseObj, Errors) {
  const std::string vs = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  EXPECT_ERROR("\n\n# nothing\n", MeshFormat::obj, "in: empty file");
  EXPECT_EQ(faces_of(parse_mesh(vs + "f 1 2 3\nf 1 2 3 1 2\n", MeshFormat::obj, "in")),
            (std::vector<std::vector<VertexId>>{{0, 1, 2}, {0, 1, 2, 0, 1}}));
  EXPECT_ERROR(vs + "f 1 2\n", MeshFormat::obj, "in:4: face 1 has 2 corners");
  EXPECT_ERROR(vs + "f 1 2 4\n", MeshFormat::obj,
               "in:4: face 1: vertex index 4 out of range (3 vertices read so far)");
  EXPECT_ERROR(vs + "f 1 2 -4\n", MeshFormat::obj, "in:4: face 1: vertex index -4 out of range");
  EXPECT_ERROR(vs + "f 1 2 0\n", MeshFormat::obj, "in:4: face 1: bad vertex index '0'");
  EXPECT_ERROR(vs + "f 1 2 x/1\n", MeshFormat::obj, "in:4: face 1: bad vertex index 'x/1'");
  EXPECT_ERROR("v 0 0 0\nv 1 NaN 0\n", MeshFormat::obj, "in:2: vertex 2: bad coordinate 'NaN'");
  EXPECT_ERROR("v 0 0\n", MeshFormat::obj, "in:1: vertex 1: expected 3 coordinates");
  EXPECT_ERROR(vs, MeshFormat::obj, "in: no faces");
}

std::string ply_header(const std::string& format, std::size_t vertices, std::size_t faces,
                       const std::string& face_list = "list uchar int vertex_indices") {
  return "ply\nformat " + format + " 1.0\ncomment c\nelement vertex " + std::to_string(vertices) +
         "\nproperty float x\nproperty uchar red\nproperty float y\nproperty float z\n"
         "element edge 1\nproperty list uchar int pair\nelement face " +
         std::to_string(faces) + "\nproperty " + face_list +
         "\nproperty float quality\nend_header\n";
}

TEST(ParsePly, AsciiSkipsOtherPropertiesAndElements) {
  const std::string text =
      ply_header("ascii", 3, 1) + "0 9 0 0\n1 9 0 0\n\n0 9 1 0\n2 0 1\n3 0 1 2 0.5\n";
  const PolygonMesh mesh = parse_mesh(text, MeshFormat::ply, "in");
  ASSERT_EQ(faces_of(mesh), kTriangle);
  EXPECT_EQ(mesh.positions[2], (std::array<double, 3>{0, 1, 0}));
}

// A binary body: three vertices (x, red, y, z), one edge, one face with quality, in either order.
std::string binary_body(bool big, std::int32_t third_index = 2, float y_of_third = 1,
                        std::uint8_t corners = 3) {
  std::string out;
  auto put = [&](const void* p, std::size_t n) {
    std::string raw(static_cast<const char*>(p), n);
    if (big) raw = std::string(raw.rbegin(), raw.rend());
    out += raw;
  };
  const float xyz[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, y_of_third, 0}};
  for (const auto& p : xyz) {
    const std::uint8_t red = 9;
    put(&p[0], 4);
    put(&red, 1);
    put(&p[1], 4);
    put(&p[2], 4);
  }
  const std::uint8_t two = 2;
  const std::int32_t e[2] = {0, 1};
  put(&two, 1);
  put(&e[0], 4);
  put(&e[1], 4);
  const std::int32_t f[3] = {0, 1, third_index};
  put(&corners, 1);
  for (std::uint8_t k = 0; k < corners; ++k) put(&f[k % 3], 4);
  const float quality = 0.5f;
  put(&quality, 4);
  return out;
}

TEST(ParsePly, BinaryLittleAndBigEndian) {
  for (bool big : {false, true}) {
    const std::string bytes =
        ply_header(big ? "binary_big_endian" : "binary_little_endian", 3, 1) + binary_body(big);
    const PolygonMesh mesh = parse_mesh(bytes, MeshFormat::ply, "in");
    ASSERT_EQ(faces_of(mesh), kTriangle);
    EXPECT_EQ(mesh.positions[1], (std::array<double, 3>{1, 0, 0}));
    EXPECT_EQ(mesh.positions[2], (std::array<double, 3>{0, 1, 0}));
  }
}

TEST(ParsePly, BinaryErrorsNameTheElement) {
  const std::string le = ply_header("binary_little_endian", 3, 1);
  const std::string body = binary_body(false);
  // Cut anywhere: either the header's counts no longer fit or a record runs past the end.
  for (std::size_t cut = 0; cut < body.size(); ++cut) {
    const std::string error = polygon_error_of(le + body.substr(0, cut), MeshFormat::ply);
    EXPECT_TRUE(error.find("in: truncated in ") == 0 ||
                error.find("records, more than") != std::string::npos)
        << cut << ": " << error;
  }
  EXPECT_ERROR(le + body.substr(0, 30), MeshFormat::ply,
               "in:4: element 'vertex' declares 3 records, more than the remaining 30 bytes");
  EXPECT_ERROR(le + body.substr(0, body.size() - 6), MeshFormat::ply,
               "in: truncated in face 0 of 1: its list of 3 values runs past the end (byte");
  EXPECT_ERROR(le + binary_body(false, 3), MeshFormat::ply,
               "in: face 0: vertex index 3 out of range (3 vertices)");
  EXPECT_ERROR(le + binary_body(false, -1), MeshFormat::ply, "in: face 0: vertex index -1");
  EXPECT_ERROR(le + binary_body(false, 2, std::nanf("")), MeshFormat::ply,
               "in: vertex 2: non-finite y");
  EXPECT_EQ(faces_of(parse_mesh(le + binary_body(false, 2, 1, 4), MeshFormat::ply, "in")),
            (std::vector<std::vector<VertexId>>{{0, 1, 2, 0}}));
}

// x, y, z stored together as float or double, either byte order (the readers' fast path) and
// ascii: a coordinate that is not finite is refused, naming the vertex and the axis.
template <class Real>
std::string xyz_ply(const std::string& format, Real bad) {
  const std::string type = sizeof(Real) == 8 ? "double" : "float";
  std::string out = "ply\nformat " + format + " 1.0\nelement vertex 3\nproperty " + type +
                    " x\nproperty " + type + " y\nproperty " + type +
                    " z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const Real xyz[3][3] = {{0, 0, 0}, {1, bad, 0}, {0, 1, 0}};
  if (format == "ascii") {
    for (const auto& p : xyz) {
      out += std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) + "\n";
    }
    return out + "3 0 1 2\n";
  }
  const bool big = format == "binary_big_endian";
  auto put = [&](const void* p, std::size_t n) {
    std::string raw(static_cast<const char*>(p), n);
    if (big) raw = std::string(raw.rbegin(), raw.rend());
    out += raw;
  };
  for (const auto& p : xyz)
    for (const Real& value : p) put(&value, sizeof(Real));
  const std::uint8_t three = 3;
  put(&three, 1);
  for (std::int32_t v : {0, 1, 2}) put(&v, 4);
  return out;
}

TEST(ParsePly, NonFiniteCoordinatesAreRefusedInEveryEncoding) {
  for (const std::string format : {"binary_little_endian", "binary_big_endian", "ascii"}) {
    for (double bad : {std::nan(""), HUGE_VAL, -HUGE_VAL}) {
      SCOPED_TRACE(format + " " + std::to_string(bad));
      const std::string expected =
          format == "ascii" ? "in:11: vertex 1: bad value" : "in: vertex 1: non-finite y";
      EXPECT_ERROR(xyz_ply<double>(format, bad), MeshFormat::ply, expected);
      EXPECT_ERROR(xyz_ply<float>(format, float(bad)), MeshFormat::ply, expected);
    }
    // The same bytes with a finite y are read.
    const PolygonMesh mesh = parse_mesh(xyz_ply<double>(format, 0.5), MeshFormat::ply, "in");
    EXPECT_EQ(mesh.positions[1], (std::array<double, 3>{1, 0.5, 0}));
  }
}

// The error's file and line are the message's: the line of a text file, none (0) in a binary
// PLY's records, whose message names the element and the byte.
TEST(ParseErrors, CarryTheFileAndTheLine) {
  auto error = [](std::string_view bytes, MeshFormat format) {
    try {
      parse_mesh(bytes, format, "in.x");
    } catch (const FileError& e) {
      return e;
    }
    return FileError("", 0, "no error");
  };
  const FileError obj = error("v 0 0 0\nv 1 0 0\n\nf 1 2 x\n", MeshFormat::obj);
  EXPECT_EQ(obj.file(), "in.x");
  EXPECT_EQ(obj.line(), 4u);
  EXPECT_STREQ(obj.what(), "in.x:4: face 1: bad vertex index 'x'");
  const FileError ply =
      error(ply_header("binary_little_endian", 3, 1) + binary_body(false, 3), MeshFormat::ply);
  EXPECT_EQ(ply.file(), "in.x");
  EXPECT_EQ(ply.line(), 0u);
  EXPECT_EQ(std::string(ply.what()).rfind("in.x: face 0: vertex index 3 out of range", 0), 0u);
  const FileError header =
      error(ply_header("ascii", 3, 1, "list uchar float vertex_indices"), MeshFormat::ply);
  EXPECT_EQ(header.line(), 11u);
  const FileError empty = error("", MeshFormat::off);
  EXPECT_EQ(empty.line(), 0u);
  EXPECT_STREQ(empty.what(), "in.x: empty file");
}

TEST(ParsePly, HeaderAndAsciiErrors) {
  EXPECT_ERROR("", MeshFormat::ply, "in: empty file");
  EXPECT_ERROR("plx\n", MeshFormat::ply, "in:1: not a PLY file");
  EXPECT_ERROR("ply\nformat ascii 1.0\nelement vertex 3\n", MeshFormat::ply,
               "in:3: truncated header");
  EXPECT_ERROR("ply\nformat binary_middle_endian 1.0\n", MeshFormat::ply,
               "in:2: unknown PLY format");
  EXPECT_ERROR(
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
      "element face 0\nproperty list uchar int vertex_indices\nend_header\n",
      MeshFormat::ply, "in:3: vertex element has no scalar property z");
  EXPECT_ERROR(ply_header("binary_little_endian", 3, 4000000000ull) + binary_body(false),
               MeshFormat::ply, "in:11: element 'face' declares 4000000000 records");
  EXPECT_ERROR(ply_header("binary_little_endian", 3, 1000000000000000ull), MeshFormat::ply,
               "in:11: more than 2^32 - 1 faces");
  EXPECT_ERROR(ply_header("ascii", 1000000000000000ull, 1), MeshFormat::ply,
               "in:4: more than 2^32 - 1 vertices");
  // Lines 1-14 are the header; vertices start on line 15.
  const std::string rest = "0 9 1 0\n2 0 1\n3 0 1 2 0.5\n";
  EXPECT_ERROR(ply_header("ascii", 3, 1) + "0 9 0 0\n1 9 inf 0\n" + rest, MeshFormat::ply,
               "in:16: vertex 1: bad value 'inf' for property y");
  EXPECT_ERROR(ply_header("ascii", 3, 1) + "0 9 0 0\n1 9 0\n" + rest, MeshFormat::ply,
               "in:16: vertex 1: too few values");
  EXPECT_ERROR(ply_header("ascii", 3, 1) + "0 9 0 0\n1 9 0 0" + std::string(40, ' ') + "\n",
               MeshFormat::ply, "in:16: truncated: expected 3 vertex records, found 2");
  EXPECT_ERROR(ply_header("ascii", 3, 1) + "0 9 0 0\n1 9 0 0\n0 9 1 0\n0\n3 0 1 -2 0\n",
               MeshFormat::ply, "in:19: face 0: vertex index -2 out of range");
  EXPECT_ERROR(ply_header("ascii", 3, 1, "list uchar float vertex_indices"), MeshFormat::ply,
               "face indices must have an integer type");
}

TEST(ParsePolygons, EveryFormatKeepsFacesOfAnyArityExactly) {
  const std::string vertices = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 2 0\n";
  const std::string off = "OFF\n5 3 0\n" + vertices + "4 0 1 2 3\n3 0 2 4 255 0 0\n5 4 3 2 4 1\n";
  const std::string obj =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 2 0\nvt 0 0\nvn 0 0 1\n"
      "f 1 2/1 3//1 4/1/1\nf 1 3 5\nf -1 4 -3 5 -4\n";
  const std::string ply_ascii =
      "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\n"
      "property float z\nelement face 3\nproperty list uchar int vertex_indices\nend_header\n" +
      vertices + "4 0 1 2 3\n3 0 2 4\n5 4 3 2 4 1\n";
  for (const auto& [bytes, format] :
       {std::pair{off, MeshFormat::off}, {obj, MeshFormat::obj}, {ply_ascii, MeshFormat::ply}}) {
    const PolygonMesh mesh = parse_mesh(bytes, format, "in");
    EXPECT_EQ(faces_of(mesh), kPolygons) << bytes;
    EXPECT_EQ(mesh.positions.size(), 5u);
    EXPECT_EQ(mesh.positions[4], (std::array<double, 3>{2, 2, 0}));
  }
}

TEST(ParsePolygons, BinaryPlyInBothByteOrdersAndBothLayouts) {
  for (bool big : {false, true}) {
    // The common layout (x y z floats, a face list alone) and a general one (extra properties).
    for (bool extra : {false, true}) {
      std::string out = std::string("ply\nformat ") +
                        (big ? "binary_big_endian" : "binary_little_endian") +
                        " 1.0\nelement vertex 5\nproperty float x\nproperty float y\n"
                        "property float z\n" +
                        (extra ? "property uchar red\n" : "") +
                        "element face 3\nproperty list uchar uint vertex_indices\n" +
                        (extra ? "property float quality\n" : "") + "end_header\n";
      auto put = [&](const void* p, std::size_t n) {
        std::string raw(static_cast<const char*>(p), n);
        if (big != (std::endian::native == std::endian::big)) {
          raw = std::string(raw.rbegin(), raw.rend());
        }
        out += raw;
      };
      const float xyz[5][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 2, 0}};
      for (const auto& p : xyz) {
        for (float x : p) put(&x, 4);
        if (extra) out += '\x09';
      }
      for (const auto& face : kPolygons) {
        const std::uint8_t n = static_cast<std::uint8_t>(face.size());
        put(&n, 1);
        for (VertexId v : face) put(&v, 4);
        const float quality = 0.5f;
        if (extra) put(&quality, 4);
      }
      const PolygonMesh mesh = parse_mesh(out, MeshFormat::ply, "in");
      EXPECT_EQ(faces_of(mesh), kPolygons) << big << extra;
      EXPECT_EQ(mesh.positions[4], (std::array<double, 3>{2, 2, 0}));
      // Every cut inside the body is a located truncation error.
      const std::size_t body = out.find("end_header\n") + 11;
      for (std::size_t cut = body; cut < out.size(); ++cut) {
        const std::string error = polygon_error_of(out.substr(0, cut), MeshFormat::ply);
        EXPECT_TRUE(error.find("in: truncated in ") == 0 ||
                    error.find("records, more than") != std::string::npos)
            << cut << ": " << error;
      }
    }
  }
}

// The common binary layout (float x y z, a face list alone) in the machine's byte order, whose
// runs of triangles are read by a loop of their own: the same faces as the ASCII file of the same
// content, and the same error at the same face, wherever a face that is not a triangle of
// in-range corners interrupts the run (a quad, a corner past the vertices, a negative corner).
TEST(ParsePly, RunsOfTrianglesReadAsTheAsciiFile) {
  const std::string order =
      std::endian::native == std::endian::little ? "binary_little_endian" : "binary_big_endian";
  std::uint64_t state = 12345;
  auto next = [&](std::uint64_t bound) {
    state = state * 6364136223846793005u + 1442695040888963407u;
    return (state >> 33) % bound;
  };
  constexpr std::int64_t kVertices = 7;
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<std::vector<std::int64_t>> faces(1 + next(40));
    for (auto& face : faces) {
      // Mostly triangles; now and then a quad, a corner out of range or a negative one.
      face.resize(next(12) == 0 ? 4 : 3);
      for (auto& corner : face) corner = static_cast<std::int64_t>(next(kVertices));
      if (next(25) == 0) face[next(face.size())] = kVertices + static_cast<std::int64_t>(next(3));
      if (next(40) == 0) face[next(face.size())] = -1;
    }
    for (const std::string type : {"int", "uint"}) {
      std::string header = "element vertex " + std::to_string(kVertices) +
                           "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
                           std::to_string(faces.size()) + "\nproperty list uchar " + type +
                           " vertex_indices\nend_header\n";
      std::string binary = "ply\nformat " + order + " 1.0\n" + header;
      std::string ascii = "ply\nformat ascii 1.0\n" + header;
      for (std::int64_t v = 0; v < kVertices; ++v) {
        const float xyz[3] = {float(v), float(v * v), 1};
        binary.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
        ascii += std::to_string(v) + " " + std::to_string(v * v) + " 1\n";
      }
      for (const auto& face : faces) {
        binary += static_cast<char>(face.size());
        ascii += std::to_string(face.size());
        for (std::int64_t corner : face) {
          const std::uint32_t raw = static_cast<std::uint32_t>(corner);
          binary.append(reinterpret_cast<const char*>(&raw), 4);
          ascii += ' ';  // an append: " " + std::to_string gives GCC 12 a false -Wrestrict
          ascii += std::to_string(type == "int" ? corner : std::int64_t{raw});
        }
        ascii += "\n";
      }
      const std::string binary_error = polygon_error_of(binary, MeshFormat::ply);
      const std::string ascii_error = polygon_error_of(ascii, MeshFormat::ply);
      if (ascii_error == "no error") {
        ASSERT_EQ(binary_error, "no error") << trial;
        EXPECT_EQ(faces_of(parse_mesh(binary, MeshFormat::ply, "in")),
                  faces_of(parse_mesh(ascii, MeshFormat::ply, "in")))
            << trial;
      } else {
        // The ASCII error names its line ("in:N: face ..."), the binary one its byte.
        const std::string what = ascii_error.substr(ascii_error.find(" face "));
        EXPECT_EQ(binary_error.substr(0, 3 + what.size()), "in:" + what) << trial;
      }
    }
  }
}

TEST(ParsePolygons, FewerThanThreeCornersAndOtherErrors) {
  const std::string vs = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  EXPECT_EQ(polygon_error_of(vs + "f 1 2 3\nf 1 2\n", MeshFormat::obj),
            "in:5: face 2 has 2 corners; a face needs at least 3");
  EXPECT_EQ(polygon_error_of(vs + "f\n", MeshFormat::obj),
            "in:4: face 1 has 0 corners; a face needs at least 3");
  EXPECT_EQ(polygon_error_of(vs + "f 1 2 3 4\n", MeshFormat::obj),
            "in:4: face 1: vertex index 4 out of range (3 vertices read so far)");
  const std::string off = "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  EXPECT_EQ(polygon_error_of(off + "2 0 1\n", MeshFormat::off),
            "in:7: face 1 has 2 corners; a face needs at least 3");
  EXPECT_EQ(polygon_error_of(off + "5 0 1 2 0\n", MeshFormat::off),
            "in:7: face 1: expected 5 vertex indices");
  EXPECT_EQ(polygon_error_of(off + "-4 0 1 2 0\n", MeshFormat::off),
            "in:7: face 1: bad corner count '-4'");
  EXPECT_EQ(polygon_error_of(off + "4 0 1 2 3\n", MeshFormat::off),
            "in:7: face 1: vertex index 3 out of range (3 vertices)");
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n";
  EXPECT_EQ(polygon_error_of(ply + "2 0 1\n", MeshFormat::ply),
            "in:13: face 0 has 2 corners; a face needs at least 3");
  EXPECT_EQ(polygon_error_of(ply + "4 0 1 2\n", MeshFormat::ply), "in:13: face 0: too few values");
  EXPECT_EQ(polygon_error_of("", MeshFormat::ply), "in: empty file");
  EXPECT_EQ(polygon_error_of(vs, MeshFormat::obj), "in: no faces");
}

}  // namespace
}  // namespace petersen
