#pragma once
// Faces that repeat an earlier face: the same vertices, in any order or orientation. A file that
// holds every triangle twice makes every edge an edge of four faces, so that nothing pairs; these
// find the copies and drop them (as MeshLab's "Remove Duplicate Faces" does).

#include <span>
#include <vector>

#include "petersen/mesh/mesh.hpp"

namespace petersen {

/// The faces whose corners are, as a multiset, those of an earlier face (either orientation, any
/// first corner: {a, b, c} and {c, b, a} are one face; a triangle and a quad never are), in
/// ascending order; the first face of each kind is never among them. Corners need not be in
/// range. O(C + F log F) for C corners and F faces.
std::vector<FaceId> duplicate_faces(const PolygonMesh& mesh);
/// The same judgement among the faces `among` alone (any order, each once): those that repeat an
/// earlier face of `among`, ascending. A caller that knows where copies can be (a triangle's copy
/// shares all its edges, so both have only edges of three or more faces, or of just the two) saves
/// the sort of the rest. O(A log A + their corners).
std::vector<FaceId> duplicate_faces(const PolygonMesh& mesh, std::span<const FaceId> among);

struct DroppedFaces {
  PolygonMesh mesh;
  std::vector<FaceId> dropped;  ///< the input's faces left out, ascending
};

/// The mesh without the faces duplicate_faces names: the first of each kind is kept, in input
/// order, with its corner attributes (texture coordinate and normal indices) and face attributes
/// (material, group, object, smoothing group, face properties); positions, vertex properties and
/// the tables the attributes index are kept whole. O(C + F log F).
DroppedFaces drop_duplicate_faces(const PolygonMesh& mesh);

}  // namespace petersen
