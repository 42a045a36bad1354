#pragma once
// A picture of a polygon mesh, PNG or SVG (cairo): a shaded orthographic view, face edges drawn,
// quads coloured by their worst-corner deviation (quad_quality.hpp) with a colour bar that spans
// every cost drawn (0 to 90°, or on to the worst non-convex quad's), triangles
// beside quads and vertices added by all_quad highlighted, lines of figures in a caption.

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "petersen/mesh/mesh.hpp"

namespace petersen {

struct Rgb {
  double r = 0, g = 0, b = 0;
};

/// A quad's colour for its cost in degrees: blue at 0°, light blue at 30°, salmon at 60°, red at
/// 90°, linear between; above 90° (non-convex) dark red, darkening up to 270° (degenerate).
Rgb quality_colour(double degrees);

inline constexpr Rgb kTriangleColour{1.0, 0.85, 0.0};  ///< triangles of a mesh with quads
inline constexpr Rgb kPolygonColour{0.55, 0.8, 0.55};  ///< faces of five or more corners
inline constexpr Rgb kPlainColour{0.8, 0.8, 0.8};      ///< triangles of a mesh without quads
inline constexpr Rgb kAddedVertexColour{0.85, 0.1, 0.6};
inline constexpr Rgb kBackground{1.0, 1.0, 1.0};

struct RenderOptions {
  std::uint32_t width = 800, height = 800;  ///< of the whole picture, caption and bar included
  /// The direction the eye looks along; when absent, along the mesh's thinnest bounding-box axis,
  /// tilted by about 20° towards the other two so that depth shows.
  std::optional<std::array<double, 3>> view;
  /// Vertices from this id on are drawn as dots (all_quad's additions: the input's vertex count).
  VertexId first_added_vertex = std::numeric_limits<VertexId>::max();
  std::vector<std::string> caption;  ///< lines printed under the picture
};

/// Whether render_mesh can write this path: it ends in .png or .svg (case-insensitive).
bool is_picture_path(const std::string& path);

/// The view direction render_mesh uses for these options (unit length). O(V).
std::array<double, 3> view_direction(const PolygonMesh& mesh, const RenderOptions& options);

/// Draws the mesh into `path`, PNG or SVG by its extension (.png, .svg, case-insensitive).
/// Faces are painter-sorted by the depth of their centroid, lit from the eye (both sides alike,
/// since orientation may be inconsistent): colour × (0.35 + 0.65 |cos|) where cos is between the
/// face normal (Newell's) and the view. A flat face seen head-on shows its colour exactly. Throws
/// MeshError naming the path for another extension, an empty view direction, a corner out of
/// range, or a file cairo cannot write. O(F log F + corners).
void render_mesh(const PolygonMesh& mesh, const std::string& path,
                 const RenderOptions& options = {});

}  // namespace petersen
