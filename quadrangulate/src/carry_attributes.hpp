#pragma once
// A mesh's attributes carried to a mesh made from it: the pairs' quads and, for all_quad, the
// pieces of split faces, whose new corners and vertices get interpolated values.

#include <array>
#include <cstdint>
#include <span>

#include "petersen/mesh/mesh.hpp"

namespace petersen::quad_detail {

/// How a corner (or a new vertex) of the new mesh is made from corners (vertices) of the mesh
/// before: the average of up to four of them, kNoAttribute after the last. One is a copy, two an
/// edge's midpoint, four a quad's centre.
using Blend = std::array<std::uint32_t, 4>;

/// A value computed in double (a blend) as a field of `type` holds it: integers rounded, float32
/// rounded to float, so that a mesh holds what its writer will write (a float PLY's new
/// positions and properties read back as they are in memory).
double held_as(ScalarType type, double value);

/// The attributes of a mesh made from a mesh with attributes `before` and `vertices_before`
/// vertices: face f takes the face attributes of before's face face_of[f]; corner c the corner
/// attributes blended by corner_from[c]; vertex v the vertex properties of before's vertex v,
/// or, from vertices_before on, those blended by new_vertices[v - vertices_before]. face_of and
/// corner_from may be empty where `before` has no face or no corner attributes. Blended texture
/// coordinates and normals (renormalised) are appended, one entry per distinct new value; a
/// blend of corners one of which has no value has none; vertex properties are held_as their type.
/// The arrays are allocated from `memory`. O(C + F + V) plus O(n log n) for n new values.
MeshAttributes derived_attributes(const MeshAttributes& before, std::size_t vertices_before,
                                  std::span<const FaceId> face_of,
                                  std::span<const Blend> corner_from,
                                  std::span<const Blend> new_vertices,
                                  std::pmr::memory_resource* memory);

}  // namespace petersen::quad_detail
