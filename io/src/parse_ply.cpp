// PLY: a text header declaring elements and their properties, then the data in ascii (one record
// per line) or binary (little or big endian). Kept: vertex x, y, z, the face index list, every
// other scalar property of a vertex or face (a PropertyColumn with its declared type; a float
// written in ascii is rounded to float, as a binary file would hold it) and MeshLab's per-corner
// "texcoord" face list (u v per corner, or empty). Other lists and other elements are read past
// according to their declared type and reported as dropped.

#include <bit>
#include <cstring>
#include <vector>

#include "parsers.hpp"
#include "text_scan.hpp"

namespace petersen {

namespace {

enum class Type : std::uint8_t { i8, u8, i16, u16, i32, u32, f32, f64 };

bool parse_type(std::string_view name, Type& type) {
  static constexpr std::pair<std::string_view, Type> names[] = {
      {"char", Type::i8},   {"int8", Type::i8},     {"uchar", Type::u8},   {"uint8", Type::u8},
      {"short", Type::i16}, {"int16", Type::i16},   {"ushort", Type::u16}, {"uint16", Type::u16},
      {"int", Type::i32},   {"int32", Type::i32},   {"uint", Type::u32},   {"uint32", Type::u32},
      {"float", Type::f32}, {"float32", Type::f32}, {"double", Type::f64}, {"float64", Type::f64},
  };
  for (const auto& [n, t] : names) {
    if (n == name) {
      type = t;
      return true;
    }
  }
  return false;
}

std::size_t size_of(Type type) {
  switch (type) {
    case Type::i8:
    case Type::u8:
      return 1;
    case Type::i16:
    case Type::u16:
      return 2;
    case Type::i32:
    case Type::u32:
    case Type::f32:
      return 4;
    case Type::f64:
      return 8;
  }
  return 0;
}

bool is_integer(Type type) {
  return type != Type::f32 && type != Type::f64;
}

struct Property {
  std::string name;
  Type type = Type::f32;  // the item type for a list
  bool is_list = false;
  Type count_type = Type::u8;
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
  std::size_t line = 0;  // where the header declared it
};

enum class Encoding { ascii, little, big };

ScalarType scalar_type(Type type) {
  return static_cast<ScalarType>(static_cast<std::uint8_t>(type));
}
static_assert(static_cast<int>(Type::f64) == static_cast<int>(ScalarType::float64));

// Whether a whole number read from ascii fits the declared integer type.
bool fits(Type type, std::int64_t value) {
  switch (type) {
    case Type::i8:
      return value >= -128 && value <= 127;
    case Type::u8:
      return value >= 0 && value <= 255;
    case Type::i16:
      return value >= -32768 && value <= 32767;
    case Type::u16:
      return value >= 0 && value <= 65535;
    case Type::i32:
      return value >= -2147483648ll && value <= 2147483647ll;
    case Type::u32:
      return value >= 0 && value <= 4294967295ll;
    default:
      return true;
  }
}

// What the reader keeps: the slots of x, y, z in the vertex element, of the face's corner and
// texcoord lists, and for every other vertex or face property the column it goes to (-1: none).
struct Layout {
  int xyz[3] = {-1, -1, -1};
  int face_list = -1;
  int texcoord_list = -1;
  std::vector<int> vertex_column, face_column;
};

// Reads binary scalars with a bounds check on every read, so truncation is always caught.
struct BinaryCursor {
  std::string_view bytes;
  std::size_t pos;
  bool big_endian;

  bool has(std::size_t n) const { return bytes.size() - pos >= n; }

  template <typename T>
  T load() {
    T value;
    if constexpr (sizeof(T) == 1) {
      std::memcpy(&value, bytes.data() + pos, 1);
    } else {
      using U =
          std::conditional_t<sizeof(T) == 2, std::uint16_t,
                             std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>;
      U raw;
      std::memcpy(&raw, bytes.data() + pos, sizeof(T));
      if (big_endian != (std::endian::native == std::endian::big)) raw = byteswap(raw);
      std::memcpy(&value, &raw, sizeof(T));
    }
    pos += sizeof(T);
    return value;
  }
  template <typename U>
  static U byteswap(U raw) {
    U out = 0;
    for (std::size_t i = 0; i < sizeof(U); ++i) out = U((out << 8) | ((raw >> (8 * i)) & 0xFF));
    return out;
  }
  // The caller has checked has(size_of(type)).
  double real(Type type) {
    switch (type) {
      case Type::f32:
        return load<float>();
      case Type::f64:
        return load<double>();
      default:
        return static_cast<double>(integer(type));
    }
  }
  std::int64_t integer(Type type) {
    switch (type) {
      case Type::i8:
        return load<std::int8_t>();
      case Type::u8:
        return load<std::uint8_t>();
      case Type::i16:
        return load<std::int16_t>();
      case Type::u16:
        return load<std::uint16_t>();
      case Type::i32:
        return load<std::int32_t>();
      case Type::u32:
        return load<std::uint32_t>();
      default:
        return 0;  // float types are refused for counts and indices in the header
    }
  }
};

class PlyParser {
 public:
  PlyParser(std::string_view bytes, const std::string& source, FaceKinds kinds,
            std::vector<std::string>& dropped)
      : bytes_(bytes),
        source_(source),
        kinds_(kinds),
        dropped_(dropped),
        lines_{bytes},
        at_{source, lines_} {}

  PolygonMesh parse() {
    read_header();
    for (const Element& element : elements_) {
      check_fits(element);
      if (encoding_ == Encoding::ascii) {
        read_ascii(element);
      } else {
        read_binary(element);
      }
    }
    return std::move(mesh_);
  }

 private:
  void read_header() {
    std::string_view line, token;
    if (!lines_.next(line)) throw FileError(source_, 0, "empty file");
    if (line != "ply") at_.fail("not a PLY file: the first line is not 'ply'");
    bool have_format = false;
    for (;;) {
      if (!lines_.next(line)) at_.fail("truncated header: no end_header");
      text::Tokens tokens{line};
      if (!tokens.next(token) || token == "comment" || token == "obj_info") continue;
      if (token == "end_header") break;
      if (token == "format") {
        tokens.next(token);
        if (token == "ascii") {
          encoding_ = Encoding::ascii;
        } else if (token == "binary_little_endian") {
          encoding_ = Encoding::little;
        } else if (token == "binary_big_endian") {
          encoding_ = Encoding::big;
        } else {
          at_.fail("unknown PLY format " + text::Located::quote(token));
        }
        have_format = true;
      } else if (token == "element") {
        Element element;
        std::string_view count_text;
        tokens.next(token);
        tokens.next(count_text);
        std::int64_t count = 0;
        if (token.empty() || !text::parse_integer(count_text, count) || count < 0) {
          at_.fail("expected 'element NAME COUNT'");
        }
        element.name = std::string(token);
        element.count = static_cast<std::uint64_t>(count);
        element.line = lines_.line;
        elements_.push_back(std::move(element));
      } else if (token == "property") {
        if (elements_.empty()) at_.fail("property before any element");
        elements_.back().properties.push_back(read_property(tokens));
      } else {
        at_.fail("unknown header keyword " + text::Located::quote(token));
      }
    }
    if (!have_format) at_.fail("header has no format line");
    find_layout();
  }

  Property read_property(text::Tokens& tokens) {
    Property property;
    std::string_view token;
    tokens.next(token);
    if (token == "list") {
      property.is_list = true;
      tokens.next(token);
      if (!parse_type(token, property.count_type) || !is_integer(property.count_type)) {
        at_.fail("bad list count type " + text::Located::quote(token));
      }
      tokens.next(token);
    }
    if (!parse_type(token, property.type)) at_.fail("unknown type " + text::Located::quote(token));
    if (!tokens.next(token)) at_.fail("property without a name");
    property.name = std::string(token);
    return property;
  }

  void find_layout() {
    const Element* vertex = nullptr;
    const Element* face = nullptr;
    for (const Element& element : elements_) {
      const Element*& slot = element.name == "vertex" ? vertex : face;
      if (element.name != "vertex" && element.name != "face") continue;
      if (slot) fail_header(element, "second '" + element.name + "' element");
      slot = &element;
    }
    if (!vertex) at_.fail("header declares no vertex element");
    if (!face) at_.fail("header declares no face element");
    if (vertex->count > 0xFFFFFFFFu) fail_header(*vertex, "more than 2^32 - 1 vertices");
    if (face->count > 0xFFFFFFFFu) fail_header(*face, "more than 2^32 - 1 faces");
    vertex_count_ = vertex->count;
    static constexpr const char* axes[3] = {"x", "y", "z"};
    for (int axis = 0; axis < 3; ++axis) {
      for (std::size_t i = 0; i < vertex->properties.size(); ++i) {
        if (vertex->properties[i].name == axes[axis] && !vertex->properties[i].is_list) {
          layout_.xyz[axis] = static_cast<int>(i);
        }
      }
      if (layout_.xyz[axis] < 0) {
        fail_header(*vertex, std::string("vertex element has no scalar property ") + axes[axis]);
      }
    }
    for (std::size_t i = 0; i < face->properties.size(); ++i) {
      const Property& p = face->properties[i];
      if (p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index")) {
        if (!is_integer(p.type)) fail_header(*face, "face indices must have an integer type");
        layout_.face_list = static_cast<int>(i);
      }
      if (p.is_list && p.name == "texcoord") layout_.texcoord_list = static_cast<int>(i);
    }
    if (layout_.face_list < 0) fail_header(*face, "face element has no vertex_indices list");
    keep_properties(*vertex, true, layout_.vertex_column, mesh_.attributes.vertex_properties);
    keep_properties(*face, false, layout_.face_column, mesh_.attributes.face_properties);
    for (const Element& element : elements_) {
      if (&element != vertex && &element != face) {
        dropped_.push_back("element '" + element.name + "' (" + std::to_string(element.count) +
                           " records)");
      }
    }
    // Written back as float when all three were; anything else is written as double, which
    // holds every type exactly. Only binary files: ascii positions keep their digits.
    bool all_float = encoding_ != Encoding::ascii;
    for (int axis : layout_.xyz)
      all_float = all_float && vertex->properties[axis].type == Type::f32;
    mesh_.attributes.position_type = all_float ? ScalarType::float32 : ScalarType::float64;
  }

  // Maps each property of the element that is not a slot of the layout to a new column, or
  // drops it (a list, or an x, y, z declared twice).
  void keep_properties(const Element& element, bool is_vertex, std::vector<int>& column_of,
                       std::vector<PropertyColumn>& columns) {
    column_of.assign(element.properties.size(), -1);
    for (std::size_t k = 0; k < element.properties.size(); ++k) {
      const Property& p = element.properties[k];
      const int slot = static_cast<int>(k);
      if (is_vertex ? (slot == layout_.xyz[0] || slot == layout_.xyz[1] || slot == layout_.xyz[2])
                    : (slot == layout_.face_list || slot == layout_.texcoord_list)) {
        continue;
      }
      const bool duplicate_axis = is_vertex && (p.name == "x" || p.name == "y" || p.name == "z");
      if (p.is_list || duplicate_axis) {
        dropped_.push_back(element.name + " " + (p.is_list ? "list " : "") + "property '" + p.name +
                           "'" + (duplicate_axis ? " (declared again)" : ""));
        continue;
      }
      column_of[k] = static_cast<int>(columns.size());
      columns.push_back({p.name, scalar_type(p.type), {}});
    }
  }

  [[noreturn]] void fail_header(const Element& element, const std::string& what) const {
    throw FileError(source_, element.line, what);
  }

  // Refuses counts the rest of the file cannot hold before anything is reserved: a binary record
  // takes at least its scalars and list counts, an ascii one at least two bytes per property.
  void check_fits(const Element& element) {
    std::size_t min_bytes = 0;
    for (const Property& p : element.properties) {
      min_bytes += encoding_ == Encoding::ascii ? 2 : size_of(p.is_list ? p.count_type : p.type);
    }
    if (encoding_ == Encoding::ascii) min_bytes = std::max<std::size_t>(min_bytes, 1);
    const std::size_t remaining = bytes_.size() - lines_.pos;
    if (min_bytes > 0 && element.count > (remaining + 1) / min_bytes) {
      fail_header(element, "element '" + element.name + "' declares " +
                               std::to_string(element.count) +
                               " records, more than the remaining " + std::to_string(remaining) +
                               " bytes can hold");
    }
    if (element.name == "vertex") {
      mesh_.positions.reserve(element.count);
      for (PropertyColumn& column : mesh_.attributes.vertex_properties) {
        column.values.reserve(element.count);
      }
    }
    // Triangles are the common case; a face record holds at least one byte per corner.
    if (element.name == "face") {
      mesh_.corners.reserve(std::min(3 * element.count, remaining));
      for (PropertyColumn& column : mesh_.attributes.face_properties) {
        column.values.reserve(element.count);
      }
    }
  }

  std::string record_name(const Element& element, std::uint64_t i) const {
    return element.name + " " + std::to_string(i);
  }

  // The face's corner count and corners are checked the same way in both encodings.
  void check_corner_count(std::uint64_t i, std::int64_t corners, const auto& fail) const {
    if (!corner_count_ok(static_cast<std::uint64_t>(corners), kinds_)) {
      fail(corner_count_error(i, static_cast<std::uint64_t>(corners)));
    }
    if (!corners_fit(mesh_, static_cast<std::uint64_t>(corners))) {
      fail("more than 2^32 - 1 face corners");
    }
  }
  VertexId checked_index(const Element& element, std::uint64_t i, std::int64_t index,
                         const auto& fail) const {
    if (index < 0 || static_cast<std::uint64_t>(index) >= vertex_count_) {
      fail(record_name(element, i) + ": vertex index " + std::to_string(index) + " out of range (" +
           std::to_string(vertex_count_) + " vertices)");
    }
    return static_cast<VertexId>(index);
  }

  // Where the element's properties go: per property, the column (-1: none); no kept element has
  // an empty list.
  struct Kept {
    const std::vector<int>* column_of = nullptr;
    std::vector<PropertyColumn>* columns = nullptr;

    bool keeps(std::size_t k) const { return column_of && (*column_of)[k] >= 0; }
    void add(std::size_t k, double value) const {
      (*columns)[(*column_of)[k]].values.push_back(value);
    }
  };
  Kept kept(const Element& element) {
    if (element.name == "vertex") {
      return {&layout_.vertex_column, &mesh_.attributes.vertex_properties};
    }
    if (element.name == "face") return {&layout_.face_column, &mesh_.attributes.face_properties};
    return {};
  }

  // Ends a face record: its corners, and their texture coordinates when the record had some (u v
  // per corner) or the file has some elsewhere (none for these corners then).
  void add_face(std::uint64_t i, const auto& fail) {
    MeshAttributes& attributes = mesh_.attributes;
    const std::size_t corners_before = mesh_.corners.size();
    if (!texcoord_values_.empty()) {
      if (texcoord_values_.size() != 2 * face_.size()) {
        fail("face " + std::to_string(i) + ": texcoord list of " +
             std::to_string(texcoord_values_.size()) + " values for " +
             std::to_string(face_.size()) + " corners (expected 2 per corner, or none)");
      }
      if (attributes.texcoords.size() + face_.size() >= kNoAttribute) {
        fail("more than 2^32 - 2 texture coordinates");
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

  void read_ascii(const Element& element) {
    const bool is_vertex = element.name == "vertex", is_face = element.name == "face";
    const Kept columns = kept(element);
    auto fail = [&](const std::string& what) { at_.fail(what); };
    std::string_view line, token;
    for (std::uint64_t i = 0; i < element.count; ++i) {
      // One record per line; blank lines between records are skipped.
      text::Tokens tokens;
      for (;;) {
        if (!lines_.next(line)) {
          at_.fail("truncated: expected " + std::to_string(element.count) + " " + element.name +
                   " records, found " + std::to_string(i));
        }
        tokens.rest = line;
        if (text::Tokens{line}.next(token)) break;
      }
      std::array<double, 3> p{};
      face_.clear();
      for (std::size_t k = 0; k < element.properties.size(); ++k) {
        const Property& property = element.properties[k];
        auto next = [&] {
          if (!tokens.next(token)) fail(record_name(element, i) + ": too few values");
        };
        if (!property.is_list) {
          next();
          double value = 0;
          std::int64_t whole = 0;
          if (!(is_integer(property.type) ? text::parse_integer(token, whole)
                                          : text::parse_real(token, value))) {
            fail(record_name(element, i) + ": bad value " + text::Located::quote(token) +
                 " for property " + property.name);
          }
          if (is_integer(property.type)) value = static_cast<double>(whole);
          if (is_vertex) {
            for (int axis = 0; axis < 3; ++axis) {
              if (layout_.xyz[axis] == int(k)) p[axis] = value;
            }
          }
          if (columns.keeps(k)) {
            if (is_integer(property.type) && !fits(property.type, whole)) {
              fail(record_name(element, i) + ": value " + std::to_string(whole) +
                   " out of range for the type of property " + property.name);
            }
            // A float property holds what a binary file of the same header would.
            if (property.type == Type::f32) value = static_cast<float>(value);
            columns.add(k, value);
          }
          continue;
        }
        next();
        std::int64_t items = 0;
        if (!text::parse_integer(token, items) || items < 0) {
          fail(record_name(element, i) + ": bad list length " + text::Located::quote(token));
        }
        const bool corners = is_face && layout_.face_list == int(k);
        const bool texcoords = is_face && layout_.texcoord_list == int(k);
        if (corners) check_corner_count(i, items, fail);
        for (std::int64_t j = 0; j < items; ++j) {
          next();
          std::int64_t index = 0;
          double value = 0;
          if (!(is_integer(property.type) ? text::parse_integer(token, index)
                                          : text::parse_real(token, value))) {
            fail(record_name(element, i) + ": bad list value " + text::Located::quote(token));
          }
          if (corners) face_.push_back(checked_index(element, i, index, fail));
          if (texcoords) {
            if (is_integer(property.type)) value = static_cast<double>(index);
            if (property.type == Type::f32) value = static_cast<float>(value);
            texcoord_values_.push_back(value);
          }
        }
      }
      if (is_vertex) mesh_.positions.push_back(p);
      if (is_face) add_face(i, fail);
    }
  }

  // Appends faces i, i + 1, ... of `count` while each is a triangle whose three 32-bit corners
  // are in range and fit, in a loop of its own; returns the first face it did not take, for the
  // general loop to read or refuse with its error. armadillo-sub2's 1.38M faces, each a count
  // byte and three corners, went through the general loop's per-face checks, scratch copy and
  // insert (about 2.8 % of a whole `quad` run's CPU samples, perf).
  std::uint64_t append_triangles(std::uint64_t count, std::uint64_t i, BinaryCursor& in,
                                 bool is_signed) {
    constexpr std::size_t kRecord = 13;  // the count byte and three corners
    // A signed index above 0x7FFFFFFF is negative: out of range whatever the vertex count.
    const std::uint64_t limit =
        is_signed ? std::min<std::uint64_t>(vertex_count_, 0x80000000u) : vertex_count_;
    const std::uint64_t whole = (bytes_.size() - in.pos) / kRecord;
    const std::uint64_t fit = (std::uint64_t{0xFFFFFFFFu} - mesh_.corners.size()) / 3;
    const std::uint64_t last = i + std::min(std::min(count - i, whole), fit);
    const char* record = bytes_.data() + in.pos;
    for (; i < last; ++i, record += kRecord) {
      if (record[0] != 3) break;
      VertexId corner[3];
      std::memcpy(corner, record + 1, sizeof corner);
      if (corner[0] >= limit || corner[1] >= limit || corner[2] >= limit) break;
      mesh_.corners.push_back(corner[0]);
      mesh_.corners.push_back(corner[1]);
      mesh_.corners.push_back(corner[2]);
    }
    in.pos = static_cast<std::size_t>(record - bytes_.data());
    return i;
  }

  // The layouts most tools write (write_mesh too), in the host's byte order: vertices of just x,
  // y, z of one floating type, faces of just a uchar-counted list of int or uint. Read with
  // fixed-size copies instead of a switch per value, with the same checks and messages as the
  // general loop. False (nothing read) for any other layout.
  bool read_common_layout(const Element& element, BinaryCursor& in, std::uint64_t& i,
                          const auto& fail, const auto& need) {
    if ((encoding_ == Encoding::big) != (std::endian::native == std::endian::big)) return false;
    const auto& properties = element.properties;
    if (element.name == "vertex" && properties.size() == 3 && layout_.xyz[0] == 0 &&
        layout_.xyz[1] == 1 && layout_.xyz[2] == 2 && properties[0].type == properties[1].type &&
        properties[1].type == properties[2].type &&
        (properties[0].type == Type::f32 || properties[0].type == Type::f64)) {
      const std::size_t size = size_of(properties[0].type);
      for (; i < element.count; ++i) {
        need(3 * size);
        std::array<double, 3> p;
        if (size == 8) {
          std::memcpy(p.data(), bytes_.data() + in.pos, 24);
        } else {
          float xyz[3];
          std::memcpy(xyz, bytes_.data() + in.pos, 12);
          p = {xyz[0], xyz[1], xyz[2]};
        }
        for (int axis = 0; axis < 3; ++axis) {
          if (!std::isfinite(p[axis])) {
            in.pos += axis * size;
            fail(record_name(element, i) + ": non-finite " + properties[axis].name);
          }
        }
        in.pos += 3 * size;
        mesh_.positions.push_back(p);
      }
      return true;
    }
    if (element.name == "face" && properties.size() == 1 && layout_.face_list == 0 &&
        properties[0].count_type == Type::u8 &&
        (properties[0].type == Type::i32 || properties[0].type == Type::u32)) {
      const bool is_signed = properties[0].type == Type::i32;
      for (; i < element.count; ++i) {
        if (mesh_.all_triangles()) {
          i = append_triangles(element.count, i, in, is_signed);
          if (i == element.count) break;
        }
        need(1);
        const std::size_t items = static_cast<unsigned char>(bytes_[in.pos]);
        in.pos += 1;
        check_corner_count(i, static_cast<std::int64_t>(items), fail);
        need(4 * items);
        face_.resize(items);
        std::memcpy(face_.data(), bytes_.data() + in.pos, 4 * items);
        for (VertexId& corner : face_) {
          if (corner >= vertex_count_ || (is_signed && corner > 0x7FFFFFFFu)) {
            const std::int64_t index =
                is_signed ? std::int64_t{static_cast<std::int32_t>(corner)} : std::int64_t{corner};
            checked_index(element, i, index, fail);
          }
        }
        in.pos += 4 * items;
        if (items == 3 && mesh_.all_triangles()) {
          // A triangle among triangles, appended here (check_corner_count has checked that the
          // corners fit): armadillo-sub2's faces took 314M instructions with add_face, 267M
          // without (callgrind).
          mesh_.corners.insert(mesh_.corners.end(), face_.begin(), face_.end());
          continue;
        }
        mesh_.add_face(face_);
      }
      return true;
    }
    return false;
  }

  void read_binary(const Element& element) {
    const bool is_vertex = element.name == "vertex", is_face = element.name == "face";
    BinaryCursor in{bytes_, lines_.pos, encoding_ == Encoding::big};
    std::uint64_t i = 0;
    auto fail = [&](const std::string& what) {
      throw FileError(source_, 0, what + " (byte " + std::to_string(in.pos) + ")");
    };
    auto need = [&](std::size_t n) {
      if (!in.has(n)) {
        fail("truncated in " + record_name(element, i) + " of " + std::to_string(element.count));
      }
    };
    if (read_common_layout(element, in, i, fail, need)) {
      lines_.pos = in.pos;
      return;
    }
    const Kept columns = kept(element);
    for (; i < element.count && !element.properties.empty(); ++i) {
      std::array<double, 3> p{};
      face_.clear();
      for (std::size_t k = 0; k < element.properties.size(); ++k) {
        const Property& property = element.properties[k];
        const std::size_t item = size_of(property.type);
        if (!property.is_list) {
          need(item);
          if (is_vertex &&
              (layout_.xyz[0] == int(k) || layout_.xyz[1] == int(k) || layout_.xyz[2] == int(k))) {
            const double value = in.real(property.type);
            if (!std::isfinite(value)) {
              fail(record_name(element, i) + ": non-finite " + property.name);
            }
            for (int axis = 0; axis < 3; ++axis) {
              if (layout_.xyz[axis] == int(k)) p[axis] = value;
            }
          } else if (columns.keeps(k)) {
            // Kept as read, NaN included: a property is not a coordinate.
            columns.add(k, in.real(property.type));
          } else {
            in.pos += item;
          }
          continue;
        }
        need(size_of(property.count_type));
        const std::int64_t items = in.integer(property.count_type);
        if (items < 0) fail(record_name(element, i) + ": negative list length");
        // Compared by division: items * item may not fit in 64 bits.
        if (static_cast<std::uint64_t>(items) > (bytes_.size() - in.pos) / item) {
          fail("truncated in " + record_name(element, i) + " of " + std::to_string(element.count) +
               ": its list of " + std::to_string(items) + " values runs past the end");
        }
        if (is_face && layout_.face_list == int(k)) {
          check_corner_count(i, items, fail);
          for (std::int64_t j = 0; j < items; ++j) {
            face_.push_back(checked_index(element, i, in.integer(property.type), fail));
          }
        } else if (is_face && layout_.texcoord_list == int(k)) {
          for (std::int64_t j = 0; j < items; ++j)
            texcoord_values_.push_back(in.real(property.type));
        } else {
          in.pos += static_cast<std::size_t>(items) * item;
        }
      }
      if (is_vertex) mesh_.positions.push_back(p);
      if (is_face) add_face(i, fail);
    }
    lines_.pos = in.pos;
  }

  std::string_view bytes_;
  const std::string& source_;
  FaceKinds kinds_;
  std::vector<std::string>& dropped_;
  text::Lines lines_;
  text::Located at_;
  Encoding encoding_ = Encoding::ascii;
  std::vector<Element> elements_;
  Layout layout_;
  PolygonMesh mesh_;
  std::vector<VertexId> face_;           // the corners of the face being read, reused
  std::vector<double> texcoord_values_;  // its texcoord list, u v per corner
  std::uint64_t vertex_count_ = 0;
};

}  // namespace

PolygonMesh parse_ply(std::string_view bytes, const std::string& source, FaceKinds kinds,
                      std::vector<std::string>& dropped) {
  return PlyParser(bytes, source, kinds, dropped).parse();
}

}  // namespace petersen
