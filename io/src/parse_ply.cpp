// PLY: a text header declaring elements and their properties (ply_header.cpp), then the records
// in ascii (one per line) or binary (little or big endian), decoded here by one loop over either
// source (ply_sources.hpp). Kept: vertex x, y, z, the face index list, every other scalar
// property of a vertex or face (a PropertyColumn with its declared type; a float written in ascii
// is rounded to float, as a binary file would hold it) and MeshLab's per-corner "texcoord" face
// list (u v per corner, or empty). Or, instead of a face element, a tristrips one: each record's
// vertex_indices list is strips separated by -1, read as their triangles (read_strips). Other
// lists and other elements are read past according to their declared type and reported as
// dropped.

#include <bit>
#include <cstring>
#include <vector>

#include "parsers.hpp"
#include "ply_header.hpp"
#include "ply_sources.hpp"

namespace petersen {

namespace {

using ply::Element;
using ply::Property;
using ply::Role;
using ply::Use;

class PlyReader {
 public:
  PlyReader(std::string_view bytes, const std::string& source, std::vector<std::string>& dropped,
            std::pmr::memory_resource* memory)
      : bytes_(bytes), source_(source), dropped_(dropped), lines_{bytes}, mesh_(memory) {}

  PolygonMesh read() {
    ply::Header header = ply::read_header(lines_, source_, dropped_);
    vertex_count_ = header.vertex_count;
    mesh_.attributes.vertex_properties = std::move(header.vertex_columns);
    mesh_.attributes.face_properties = std::move(header.face_columns);
    mesh_.attributes.position_type = header.position_type;
    for (const Element& element : header.elements) {
      check_fits(element, header.encoding);
      reserve(element);
      switch (header.encoding) {
        case ply::Encoding::ascii: {
          ply::AsciiSource in(lines_, source_);
          read_records(element, in);
          break;
        }
        case ply::Encoding::little:
          read_binary<std::endian::native != std::endian::little>(element);
          break;
        case ply::Encoding::big:
          read_binary<std::endian::native != std::endian::big>(element);
          break;
      }
    }
    if (strip_turns_ > 0) {
      dropped_.push_back(std::to_string(strip_turns_) +
                         " triangles of strips repeating a vertex (a strip's turns and joins)");
    }
    return std::move(mesh_);
  }

 private:
  // Refuses counts the rest of the file cannot hold before anything is reserved: a binary record
  // takes at least its scalars and list counts, an ascii one at least two bytes per property.
  void check_fits(const Element& element, ply::Encoding encoding) const {
    const bool ascii = encoding == ply::Encoding::ascii;
    std::size_t min_bytes = 0;
    for (const Property& p : element.properties) {
      min_bytes += ascii ? 2 : ply::size_of(p.is_list ? p.count_type : p.type);
    }
    if (ascii) min_bytes = std::max<std::size_t>(min_bytes, 1);
    const std::size_t remaining = bytes_.size() - lines_.pos;
    if (min_bytes > 0 && element.count > (remaining + 1) / min_bytes) {
      throw FileError(source_, element.line,
                      "element '" + element.name + "' declares " + std::to_string(element.count) +
                          " records, more than the remaining " + std::to_string(remaining) +
                          " bytes can hold");
    }
  }

  // Room for the element's records, once check_fits has bounded their count.
  void reserve(const Element& element) {
    if (element.role == Role::vertex) {
      mesh_.positions.reserve(element.count);
      for (PropertyColumn& column : mesh_.attributes.vertex_properties) {
        column.values.reserve(element.count);
      }
    }
    // Triangles are the common case; a face record holds at least one byte per corner.
    if (element.role == Role::face) {
      mesh_.corners.reserve(std::min(3 * element.count, bytes_.size() - lines_.pos));
      for (PropertyColumn& column : mesh_.attributes.face_properties) {
        column.values.reserve(element.count);
      }
    }
  }

  template <bool kSwap>
  void read_binary(const Element& element) {
    ply::BinarySource<kSwap> in(bytes_, lines_.pos, source_);
    bool read = false;
    if constexpr (!kSwap) read = read_float_vertices(element, in) || read_int_faces(element, in);
    if (!read) read_records(element, in);
    lines_.pos = in.pos();
  }

  // The record decoder of every encoding: each record's properties in the header's order, each
  // value read from the source and put where its use says.
  template <class Source>
  void read_records(const Element& element, Source& in) {
    // A binary record of no properties has no bytes; an ascii one still takes a line.
    if (element.properties.empty() && !Source::kRecordPerLine) return;
    std::vector<PropertyColumn>& columns = element.role == Role::face
                                               ? mesh_.attributes.face_properties
                                               : mesh_.attributes.vertex_properties;
    for (std::uint64_t i = 0; i < element.count; ++i) {
      in.begin_record(element, i);
      std::array<double, 3> position{};
      face_.clear();
      for (const Property& property : element.properties) {
        switch (property.use) {
          case Use::coordinate:
            position[property.slot] = in.coordinate(property);
            break;
          case Use::column:
            columns[property.slot].values.push_back(in.column_value(property));
            break;
          case Use::skip:
            in.skip(property);
            break;
          case Use::corners:
            if (element.role == Role::strips) {
              read_strips(element, i, property, in);
            } else {
              read_corners(element, i, property, in);
            }
            break;
          case Use::texcoords:
            for (std::uint64_t j = in.list_length(property); j > 0; --j) {
              texcoord_values_.push_back(in.list_real(property));
            }
            break;
          case Use::skip_list:
            in.skip_list(property, in.list_length(property));
            break;
        }
      }
      if (element.role == Role::vertex) mesh_.positions.push_back(position);
      if (element.role == Role::face) add_face(i, in);
    }
  }

  template <class Source>
  void read_corners(const Element& element, std::uint64_t i, const Property& property, Source& in) {
    const std::uint64_t corners = in.list_length(property);
    check_corner_count(i, corners, in);
    for (std::uint64_t j = 0; j < corners; ++j) {
      face_.push_back(checked_index(element, i, in.list_index(property), in));
    }
  }

  // What ends a strip besides -1: in an unsigned index type its largest value (-1's bits, as a
  // primitive-restart index is written).
  static std::int64_t strip_restart(ScalarType type) {
    switch (type) {
      case ScalarType::uint8:
        return 0xFF;
      case ScalarType::uint16:
        return 0xFFFF;
      case ScalarType::uint32:
        return 0xFFFFFFFF;
      default:
        return -1;
    }
  }

  // A tristrips record: strips a b c d ... separated by -1 (strip_restart), each the triangles (a,
  // b, c), (c, b, d), (c, d, e), ...: the k-th triangle of a strip (from 0) is its corners k, k +
  // 1, k + 2, the first two swapped when k is odd, so that every triangle turns the way the first
  // does. A triangle repeating a vertex is how strips turn or join, no face: left out, counted.
  template <class Source>
  void read_strips(const Element& element, std::uint64_t i, const Property& property, Source& in) {
    const std::uint64_t items = in.list_length(property);
    const std::int64_t restart = strip_restart(property.type);
    std::uint64_t strip = 0, in_strip = 0;  // the strip being read, and its items so far
    VertexId a = 0, b = 0;                  // its last two corners
    for (std::uint64_t j = 0; j < items; ++j) {
      const std::int64_t index = in.list_index(property);
      if (index == -1 || index == restart) {
        ++strip;
        in_strip = 0;
        continue;
      }
      if (index < 0 || static_cast<std::uint64_t>(index) >= vertex_count_) {
        in.fail(ply::record_name(element, i) + ", strip " + std::to_string(strip) +
                " (list position " + std::to_string(j) + "): vertex index " +
                std::to_string(index) + " out of range (" + std::to_string(vertex_count_) +
                " vertices)");
      }
      const auto c = static_cast<VertexId>(index);
      if (in_strip >= 2) {
        const bool odd = in_strip % 2 == 1;
        const std::array<VertexId, 3> triangle{odd ? b : a, odd ? a : b, c};
        if (a == b || b == c || a == c) {
          ++strip_turns_;
        } else {
          if (!corners_fit(mesh_, 3)) in.fail("more than 2^32 - 1 face corners");
          mesh_.add_face(triangle);
        }
      }
      a = b;
      b = c;
      ++in_strip;
    }
  }

  // The face's corner count and corners are checked the same way in every encoding.
  template <class Source>
  void check_corner_count(std::uint64_t i, std::uint64_t corners, const Source& in) const {
    if (!corner_count_ok(corners)) in.fail(corner_count_error(i, corners));
    if (!corners_fit(mesh_, corners)) in.fail("more than 2^32 - 1 face corners");
  }

  template <class Source>
  VertexId checked_index(const Element& element, std::uint64_t i, std::int64_t index,
                         const Source& in) const {
    if (index < 0 || static_cast<std::uint64_t>(index) >= vertex_count_) {
      in.fail(ply::record_name(element, i) + ": vertex index " + std::to_string(index) +
              " out of range (" + std::to_string(vertex_count_) + " vertices)");
    }
    return static_cast<VertexId>(index);
  }

  // Ends a face record: its corners, and their texture coordinates when the record had some (u v
  // per corner) or the file has some elsewhere (none for these corners then).
  template <class Source>
  void add_face(std::uint64_t i, const Source& in) {
    MeshAttributes& attributes = mesh_.attributes;
    const std::size_t corners_before = mesh_.corners.size();
    if (!texcoord_values_.empty()) {
      if (texcoord_values_.size() != 2 * face_.size()) {
        in.fail("face " + std::to_string(i) + ": texcoord list of " +
                std::to_string(texcoord_values_.size()) + " values for " +
                std::to_string(face_.size()) + " corners (expected 2 per corner, or none)");
      }
      if (attributes.texcoords.size() + face_.size() >= kNoAttribute) {
        in.fail("more than 2^32 - 2 texture coordinates");
      }
      for (std::size_t k = 0; k < face_.size(); ++k) {
        push_attribute(attributes.corner_texcoord,
                       static_cast<std::uint32_t>(attributes.texcoords.size()), kNoAttribute,
                       corners_before + k);
        attributes.texcoords.push_back({texcoord_values_[2 * k], texcoord_values_[2 * k + 1], 0});
      }
    } else if (!attributes.corner_texcoord.empty()) {
      attributes.corner_texcoord.insert(attributes.corner_texcoord.end(), face_.size(),
                                        kNoAttribute);
    }
    texcoord_values_.clear();
    mesh_.add_face(face_);
  }

  // The layouts most tools write (write_mesh too), in the host's byte order, read by whole
  // records with fixed-size copies instead of a switch per value, with the same checks and
  // messages as read_records. Vertices of just x, y, z of one floating type; false (nothing read)
  // for any other layout.
  bool read_float_vertices(const Element& element, ply::BinarySource<false>& in) {
    const auto& properties = element.properties;
    if (element.role != Role::vertex || properties.size() != 3) return false;
    for (int axis = 0; axis < 3; ++axis) {
      if (properties[axis].use != Use::coordinate || properties[axis].slot != axis ||
          properties[axis].type != properties[0].type) {
        return false;
      }
    }
    if (properties[0].type != ScalarType::float32 && properties[0].type != ScalarType::float64) {
      return false;
    }
    const std::size_t size = ply::size_of(properties[0].type);
    const char* const bytes = in.bytes().data();
    std::size_t& pos = in.pos();
    for (std::uint64_t i = 0; i < element.count; ++i) {
      in.begin_record(element, i);
      in.need(3 * size);
      std::array<double, 3> p;
      if (size == 8) {
        std::memcpy(p.data(), bytes + pos, 24);
      } else {
        float xyz[3];
        std::memcpy(xyz, bytes + pos, 12);
        p = {xyz[0], xyz[1], xyz[2]};
      }
      for (int axis = 0; axis < 3; ++axis) {
        if (!std::isfinite(p[axis])) {
          pos += axis * size;
          in.fail(ply::record_name(element, i) + ": non-finite " + properties[axis].name);
        }
      }
      pos += 3 * size;
      mesh_.positions.push_back(p);
    }
    return true;
  }

  // Faces of just a uchar-counted list of int or uint, in the host's byte order; false (nothing
  // read) for any other layout. Runs of triangles go through append_triangles.
  bool read_int_faces(const Element& element, ply::BinarySource<false>& in) {
    const auto& properties = element.properties;
    if (element.role != Role::face || properties.size() != 1 || properties[0].use != Use::corners ||
        properties[0].count_type != ScalarType::uint8 ||
        (properties[0].type != ScalarType::int32 && properties[0].type != ScalarType::uint32)) {
      return false;
    }
    const bool is_signed = properties[0].type == ScalarType::int32;
    const char* const bytes = in.bytes().data();
    std::size_t& pos = in.pos();
    for (std::uint64_t i = 0; i < element.count; ++i) {
      if (mesh_.all_triangles()) {
        i = append_triangles(element.count, i, pos, is_signed);
        if (i == element.count) break;
      }
      in.begin_record(element, i);
      in.need(1);
      const std::size_t items = static_cast<unsigned char>(bytes[pos]);
      pos += 1;
      check_corner_count(i, items, in);
      in.need(4 * items);
      face_.resize(items);
      std::memcpy(face_.data(), bytes + pos, 4 * items);
      for (VertexId& corner : face_) {
        if (corner >= vertex_count_ || (is_signed && corner > 0x7FFFFFFFu)) {
          const std::int64_t index =
              is_signed ? std::int64_t{static_cast<std::int32_t>(corner)} : std::int64_t{corner};
          checked_index(element, i, index, in);
        }
      }
      pos += 4 * items;
      if (items == 3 && mesh_.all_triangles()) {
        // A triangle among triangles is appended here, without add_face's scratch copy
        // (check_corner_count has checked that the corners fit).
        mesh_.corners.insert(mesh_.corners.end(), face_.begin(), face_.end());
        continue;
      }
      mesh_.add_face(face_);
    }
    return true;
  }

  // Appends faces i, i + 1, ... of `count` while each is a triangle whose three 32-bit corners
  // are in range and fit, in a loop of its own; returns the first face it did not take, for
  // read_int_faces to read or refuse with its error. On a large triangle mesh nearly every face
  // is taken here, one count byte and three corners each, without a check or copy per corner.
  std::uint64_t append_triangles(std::uint64_t count, std::uint64_t i, std::size_t& pos,
                                 bool is_signed) {
    constexpr std::size_t kRecord = 13;  // the count byte and three corners
    // A signed index above 0x7FFFFFFF is negative: out of range whatever the vertex count.
    const std::uint64_t limit =
        is_signed ? std::min<std::uint64_t>(vertex_count_, 0x80000000u) : vertex_count_;
    const std::uint64_t whole = (bytes_.size() - pos) / kRecord;
    const std::uint64_t fit = (std::uint64_t{0xFFFFFFFFu} - mesh_.corners.size()) / 3;
    const std::uint64_t last = i + std::min(std::min(count - i, whole), fit);
    const char* record = bytes_.data() + pos;
    for (; i < last; ++i, record += kRecord) {
      if (record[0] != 3) break;
      VertexId corner[3];
      std::memcpy(corner, record + 1, sizeof corner);
      if (corner[0] >= limit || corner[1] >= limit || corner[2] >= limit) break;
      mesh_.corners.push_back(corner[0]);
      mesh_.corners.push_back(corner[1]);
      mesh_.corners.push_back(corner[2]);
    }
    pos = static_cast<std::size_t>(record - bytes_.data());
    return i;
  }

  std::string_view bytes_;
  const std::string& source_;
  std::vector<std::string>& dropped_;
  text::Lines lines_;
  PolygonMesh mesh_;
  std::uint64_t vertex_count_ = 0;
  std::vector<VertexId> face_;           // the corners of the face being read, reused
  std::vector<double> texcoord_values_;  // its texcoord list, u v per corner
  std::uint64_t strip_turns_ = 0;        // triangles of tristrips repeating a vertex, left out
};

}  // namespace

PolygonMesh parse_ply(std::string_view bytes, const std::string& source,
                      std::vector<std::string>& dropped, std::pmr::memory_resource* memory) {
  return PlyReader(bytes, source, dropped, memory).read();
}

}  // namespace petersen
