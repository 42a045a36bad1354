#include "petersen/mesh/duplicate_faces.hpp"

#include <algorithm>
#include <cstdint>

namespace petersen {

namespace {

// A hash of a face's corners that does not depend on their order (a sum of mixed corners): equal
// for faces with the same corners.
std::uint64_t multiset_hash(std::span<const VertexId> corners) {
  std::uint64_t sum = corners.size();
  for (VertexId v : corners) {
    std::uint64_t x = v + 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    sum += x ^ (x >> 31);
  }
  return sum;
}

// The entries of a per-face (or, with per_corner, per-corner) array for the faces not dropped.
template <typename Values>
Values kept_entries(const Values& values, const PolygonMesh& mesh,
                    const std::vector<std::uint8_t>& dropped, bool per_corner) {
  Values out;
  if (values.empty()) return out;
  for (FaceId f = 0; f < dropped.size(); ++f) {
    if (dropped[f]) continue;
    if (!per_corner) {
      out.push_back(values[f]);
      continue;
    }
    const auto first = values.begin() + (mesh.face(f).data() - mesh.corners.data());
    out.insert(out.end(), first, first + mesh.arity(f));
  }
  return out;
}

// The faces of `order` ({hash, face} for each face looked at) that repeat an earlier one.
std::vector<FaceId> copies_in(const PolygonMesh& mesh,
                              std::vector<std::pair<std::uint64_t, FaceId>>& order) {
  std::sort(order.begin(), order.end());
  // Within a run of equal hashes (almost always one kind of face), each face is compared with the
  // first faces of the kinds seen so far in the run; the run's faces are in ascending order, so
  // the first of each kind is kept.
  std::vector<FaceId> copies;
  std::vector<std::vector<VertexId>> kinds;  // the sorted corners of each kind in the run
  std::vector<VertexId> key;
  for (std::size_t i = 0, j = 0; i < order.size(); i = j) {
    while (j < order.size() && order[j].first == order[i].first) ++j;
    if (j - i == 1) continue;
    kinds.clear();
    for (std::size_t k = i; k < j; ++k) {
      const auto c = mesh.face(order[k].second);
      key.assign(c.begin(), c.end());
      std::sort(key.begin(), key.end());
      const bool seen = std::find(kinds.begin(), kinds.end(), key) != kinds.end();
      if (seen) {
        copies.push_back(order[k].second);
      } else {
        kinds.push_back(key);
      }
    }
  }
  std::sort(copies.begin(), copies.end());
  return copies;
}

}  // namespace

std::vector<FaceId> duplicate_faces(const PolygonMesh& mesh) {
  const auto faces = static_cast<FaceId>(mesh.face_count());
  std::vector<std::pair<std::uint64_t, FaceId>> order(faces);
  for (FaceId f = 0; f < faces; ++f) order[f] = {multiset_hash(mesh.face(f)), f};
  return copies_in(mesh, order);
}

std::vector<FaceId> duplicate_faces(const PolygonMesh& mesh, std::span<const FaceId> among) {
  std::vector<std::pair<std::uint64_t, FaceId>> order(among.size());
  for (std::size_t i = 0; i < among.size(); ++i) {
    order[i] = {multiset_hash(mesh.face(among[i])), among[i]};
  }
  return copies_in(mesh, order);
}

DroppedFaces drop_duplicate_faces(const PolygonMesh& mesh) {
  DroppedFaces result;
  result.dropped = duplicate_faces(mesh);
  std::vector<std::uint8_t> dropped(mesh.face_count(), 0);
  for (FaceId f : result.dropped) dropped[f] = 1;
  PolygonMesh& out = result.mesh;
  out.positions = mesh.positions;
  const MeshAttributes& in = mesh.attributes;
  MeshAttributes& a = out.attributes;
  a = in;  // the tables, names, vertex properties and position type, whole
  a.corner_texcoord = kept_entries(in.corner_texcoord, mesh, dropped, true);
  a.corner_normal = kept_entries(in.corner_normal, mesh, dropped, true);
  a.face_material = kept_entries(in.face_material, mesh, dropped, false);
  a.face_group = kept_entries(in.face_group, mesh, dropped, false);
  a.face_object = kept_entries(in.face_object, mesh, dropped, false);
  a.face_smoothing = kept_entries(in.face_smoothing, mesh, dropped, false);
  for (std::size_t k = 0; k < in.face_properties.size(); ++k) {
    a.face_properties[k].values = kept_entries(in.face_properties[k].values, mesh, dropped, false);
  }
  for (FaceId f = 0; f < dropped.size(); ++f) {
    if (!dropped[f]) out.add_face(mesh.face(f));
  }
  return result;
}

}  // namespace petersen
