#include "cut_into_quads.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_set>

#include "petersen/dualize/quad_quality.hpp"

namespace petersen::quad_detail {

namespace {

using Point = std::array<double, 3>;

// A corner of a face after the splits, by its place in the face before: its corner k, the
// midpoint of its side k (from corner k to k + 1), or its centre.
struct Place {
  enum class Kind : std::uint8_t { corner, side, centre };
  std::uint32_t k = 0;
  Kind kind = Kind::corner;
};

// How a face of s ≥ 6 sides is cut: a fan from corner `start`, or s/2 quads around a centre with
// spokes to the corners start, start + 2, ...
struct Cut {
  enum class Kind : std::uint8_t { none, fan, centre };
  Kind kind = Kind::none;
  std::uint32_t start = 0;
  double worst = std::numeric_limits<double>::infinity();
};

constexpr VertexId kCentreVertex = kNoNode - 1;  // the centre while it is only a candidate
constexpr std::uint32_t kMaxFanRoots = 32;       // fans tried on one face

std::uint64_t edge_key(VertexId a, VertexId b) {
  return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
}

class FaceCutter {
 public:
  FaceCutter(PolygonMesh& mesh, const PolygonHalfedges& half, const EdgeGroups& groups,
             std::span<const VertexId> midpoint, std::span<const std::array<FaceId, 2>> sources,
             std::vector<Blend>* new_vertices, const CutIntoQuadsOptions& options)
      : mesh_(mesh),
        half_(half),
        groups_(groups),
        midpoint_(midpoint),
        sources_(sources),
        new_vertices_(new_vertices),
        options_(options),
        out_{.mesh = PolygonMesh(mesh.memory()),
             .sources = std::pmr::vector<std::array<FaceId, 2>>(mesh.memory())} {}

  QuadPieces cut_all(std::span<const std::uint8_t> kept) && {
    out_.mesh.corners.reserve(mesh_.corners.size() + 2 * midpoint_.size() / 3);
    for (FaceId f = 0; f < kept.size(); ++f) {
      collect_polygon(f);
      const std::uint32_t n = mesh_.arity(f), s = static_cast<std::uint32_t>(polygon_.size());
      if (kept[f] || (s == 4 && n == 4)) {
        add_face(f, polygon_, places_, false);
      } else if (s % 2 == 1) {
        throw std::logic_error("cut_into_quads: face " + std::to_string(f) + " has odd sides");
      } else if (s == 4) {
        add_face(f, polygon_, places_, true);
      } else {
        cut_polygon(f, choose_cut(f));
      }
    }
    return std::move(out_);
  }

 private:
  bool carry() const { return new_vertices_ != nullptr; }

  void collect_polygon(FaceId f) {
    polygon_.clear();
    places_.clear();
    const auto corners = mesh_.face(f);
    const std::uint32_t first = half_.first(f);
    for (std::uint32_t k = 0; k < corners.size(); ++k) {
      polygon_.push_back(corners[k]);
      places_.push_back({k, Place::Kind::corner});
      if (midpoint_[first + k] != kNoNode) {
        polygon_.push_back(midpoint_[first + k]);
        places_.push_back({k, Place::Kind::side});
      }
    }
  }

  const Point& position(VertexId v) const {
    return v == kCentreVertex ? centre_ : mesh_.positions[v];
  }

  double cost(VertexId a, VertexId b, VertexId c, VertexId d) const {
    return quad_corner_deviation(position(a), position(b), position(c), position(d));
  }

  // Whether a diagonal from a to b would be a new edge: neither an edge of the mesh nor a
  // diagonal another face already drew (either would give an edge three faces).
  bool is_free(VertexId a, VertexId b) const {
    if (drawn_.count(edge_key(a, b)) != 0) return false;
    const VertexId low = std::min(a, b), high = std::max(a, b);
    if (low + 1 >= groups_.start.size()) return true;
    const auto* begin = groups_.entries.data() + groups_.start[low];
    const auto* end = groups_.entries.data() + groups_.start[low + 1];
    const auto* it = std::lower_bound(begin, end, std::array<std::uint32_t, 2>{high, 0});
    return it == end || (*it)[0] != high;
  }

  VertexId at(std::uint32_t i) const { return polygon_[i % polygon_.size()]; }

  // The fan from corner r: quads (r, r+2i+1, r+2i+2, r+2i+3); infinite when a diagonal is taken.
  double fan_worst(std::uint32_t r) const {
    const std::uint32_t s = static_cast<std::uint32_t>(polygon_.size());
    double worst = 0;
    for (std::uint32_t i = 0; i + 2 <= s / 2; ++i) {
      if (i + 2 < s / 2 && !is_free(at(r), at(r + 2 * i + 3))) {
        return std::numeric_limits<double>::infinity();
      }
      worst = std::max(worst, cost(at(r), at(r + 2 * i + 1), at(r + 2 * i + 2), at(r + 2 * i + 3)));
    }
    return worst;
  }

  // The corners a centre of face f blends: all of them up to four, else four spread around it.
  Blend centre_corners(FaceId f) const {
    const std::uint32_t n = mesh_.arity(f), first = half_.first(f);
    Blend corners{kNoAttribute, kNoAttribute, kNoAttribute, kNoAttribute};
    const std::uint32_t count = std::min<std::uint32_t>(n, 4);
    for (std::uint32_t i = 0; i < count; ++i) corners[i] = first + i * n / count;
    return corners;
  }

  Point centre_of(FaceId f) const {
    Point sum{0, 0, 0};
    double count = 0;
    for (std::uint32_t corner : centre_corners(f)) {
      if (corner == kNoAttribute) break;
      for (int d = 0; d < 3; ++d) sum[d] += mesh_.positions[mesh_.corners[corner]][d];
      ++count;
    }
    for (double& x : sum) x /= count;
    return sum;
  }

  double centre_worst(std::uint32_t t) const {
    double worst = 0;
    for (std::uint32_t j = t; j < polygon_.size(); j += 2) {
      worst = std::max(worst, cost(at(j), at(j + 1), at(j + 2), kCentreVertex));
    }
    return worst;
  }

  // A quad crossed straight through: its two midpoints three places apart; the first's index.
  std::uint32_t straight_crossing(FaceId f) const {
    if (mesh_.arity(f) != 4 || polygon_.size() != 6) return kNoNode;
    for (std::uint32_t i = 0; i < 3; ++i) {
      if (places_[i].kind == Place::Kind::side && places_[i + 3].kind == Place::Kind::side) {
        return i;
      }
    }
    return kNoNode;
  }

  Cut choose_cut(FaceId f) {
    const std::uint32_t s = static_cast<std::uint32_t>(polygon_.size());
    Cut best;
    if (const std::uint32_t i = straight_crossing(f); i != kNoNode && is_free(at(i), at(i + 3))) {
      return {Cut::Kind::fan, i, 0};
    }
    // Every corner of a small face; kMaxFanRoots spread around a large one, so that a face of
    // s sides costs O(s), not O(s²).
    const std::uint32_t roots = std::min(s, kMaxFanRoots);
    for (std::uint32_t i = 0; i < roots; ++i) {
      const std::uint32_t r = static_cast<std::uint32_t>(std::uint64_t{i} * s / roots);
      const double worst = fan_worst(r);
      if (worst < best.worst) best = {Cut::Kind::fan, r, worst};
    }
    const bool crossed = s > mesh_.arity(f);
    const bool try_centre = best.kind == Cut::Kind::none ||
                            (options_.centres_where_better && crossed && mesh_.arity(f) == 4);
    if (try_centre) {
      centre_ = centre_of(f);
      for (std::uint32_t t = 0; t < 2; ++t) {
        const double worst = centre_worst(t);
        if (worst < best.worst || best.kind == Cut::Kind::none)
          best = {Cut::Kind::centre, t, worst};
      }
    }
    return best;
  }

  void cut_polygon(FaceId f, const Cut& cut) {
    const std::uint32_t s = static_cast<std::uint32_t>(polygon_.size());
    const std::uint32_t r = cut.start;
    auto piece = [&](std::array<std::uint32_t, 4> index, VertexId centre) {
      std::array<VertexId, 4> corners;
      std::array<Place, 4> places;
      for (int c = 0; c < 4; ++c) {
        const bool is_centre = index[c] == kNoNode;
        corners[c] = is_centre ? centre : at(index[c]);
        places[c] = is_centre ? Place{0, Place::Kind::centre} : places_[index[c] % s];
      }
      add_face(f, corners, places, true);
    };
    if (cut.kind == Cut::Kind::fan) {
      for (std::uint32_t i = 0; i + 2 <= s / 2; ++i) {
        piece({r, r + 2 * i + 1, r + 2 * i + 2, r + 2 * i + 3}, kNoNode);
        if (i + 2 < s / 2) drawn_.insert(edge_key(at(r), at(r + 2 * i + 3)));
      }
      return;
    }
    const VertexId centre = add_centre(f);
    for (std::uint32_t j = r; j < s; j += 2) piece({j, j + 1, j + 2, kNoNode}, centre);
  }

  VertexId add_centre(FaceId f) {
    mesh_.positions.push_back(centre_of(f));
    if (carry()) {
      Blend vertices = centre_corners(f);
      for (std::uint32_t& corner : vertices)
        if (corner != kNoAttribute) corner = mesh_.corners[corner];
      new_vertices_->push_back(vertices);
    }
    ++out_.centres;
    return static_cast<VertexId>(mesh_.positions.size() - 1);
  }

  void add_face(FaceId f, std::span<const VertexId> corners, std::span<const Place> places,
                bool piece) {
    if (piece) out_.pieces.push_back(static_cast<FaceId>(out_.mesh.face_count()));
    out_.mesh.add_face(corners);
    out_.sources.push_back(sources_[f]);
    if (!carry()) return;
    out_.face_of.push_back(f);
    const std::uint32_t first = half_.first(f), n = mesh_.arity(f);
    for (const Place& place : places) {
      switch (place.kind) {
        case Place::Kind::corner:
          out_.corner_from.push_back({first + place.k, kNoAttribute, kNoAttribute, kNoAttribute});
          break;
        case Place::Kind::side:
          out_.corner_from.push_back(
              {first + place.k, first + (place.k + 1) % n, kNoAttribute, kNoAttribute});
          break;
        case Place::Kind::centre:
          out_.corner_from.push_back(centre_corners(f));
          break;
      }
    }
  }

  PolygonMesh& mesh_;
  const PolygonHalfedges& half_;
  const EdgeGroups& groups_;
  std::span<const VertexId> midpoint_;
  std::span<const std::array<FaceId, 2>> sources_;
  std::vector<Blend>* new_vertices_;  // null without attributes
  const CutIntoQuadsOptions& options_;
  QuadPieces out_;
  std::unordered_set<std::uint64_t> drawn_;  // diagonals drawn so far
  std::vector<VertexId> polygon_;            // the face being cut, midpoints in
  std::vector<Place> places_;
  Point centre_{};  // the candidate centre of the face being cut
};

}  // namespace

QuadPieces cut_into_quads(PolygonMesh& mesh, const PolygonHalfedges& half, const EdgeGroups& groups,
                          std::span<const VertexId> midpoint, std::span<const std::uint8_t> kept,
                          std::span<const std::array<FaceId, 2>> sources,
                          std::vector<Blend>* new_vertices, const CutIntoQuadsOptions& options) {
  return FaceCutter(mesh, half, groups, midpoint, sources, new_vertices, options).cut_all(kept);
}

}  // namespace petersen::quad_detail
