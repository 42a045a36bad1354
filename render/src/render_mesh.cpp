#include "petersen/render/render_mesh.hpp"

#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <numeric>

#include "petersen/dualize/quad_quality.hpp"
#include "petersen/mesh/vec3.hpp"

namespace petersen {

namespace {

using vec3::cross, vec3::dot, vec3::sub, vec3::unit;
using Vec = vec3::Vec3;

bool ends_with(std::string s, const std::string& suffix) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

void set_colour(cairo_t* cr, const Rgb& c, double shade = 1) {
  cairo_set_source_rgb(cr, c.r * shade, c.g * shade, c.b * shade);
}

// The screen: orthographic projection onto the plane orthogonal to the view, fitted into a box.
struct Camera {
  Vec right, up, view;
  double scale = 1, offset_x = 0, offset_y = 0;
  std::array<double, 2> project(const Vec& p) const {
    return {offset_x + scale * dot(p, right), offset_y - scale * dot(p, up)};
  }
};

Camera fit_camera(const PolygonMesh& mesh, const Vec& view, double x0, double y0, double w,
                  double h) {
  Camera cam;
  cam.view = view;
  const Vec up0 = std::abs(view[2]) < 0.9 ? Vec{0, 0, 1} : Vec{0, 1, 0};
  cam.right = unit(cross(view, up0));
  cam.up = cross(cam.right, view);
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (VertexId v : mesh.corners) {
    const double s[2] = {dot(mesh.positions[v], cam.right), dot(mesh.positions[v], cam.up)};
    for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], s[k]), hi[k] = std::max(hi[k], s[k]);
  }
  const double span_x = std::max(hi[0] - lo[0], 1e-300), span_y = std::max(hi[1] - lo[1], 1e-300);
  cam.scale = 0.95 * std::min(w / span_x, h / span_y);
  cam.offset_x = x0 + w / 2 - cam.scale * (lo[0] + hi[0]) / 2;
  cam.offset_y = y0 + h / 2 + cam.scale * (lo[1] + hi[1]) / 2;
  return cam;
}

void draw_text(cairo_t* cr, double x, double y, const std::string& text) {
  cairo_move_to(cr, x, y);
  cairo_show_text(cr, text.c_str());
}

// The colour bar of the quad costs, 0° at the bottom up to `top` degrees (90, or the worst quad's
// cost rounded up to 30° when a quad is non-convex, so that the bar covers every colour drawn;
// the convex 0° to 90° then keep two thirds of its height), then the swatches of the other faces.
void draw_legend(cairo_t* cr, double x, double y, double height, double top_degrees, bool triangles,
                 bool polygons, bool added) {
  const double bar_h = std::max(40.0, height - 90), w = 18;
  cairo_set_font_size(cr, 11);
  set_colour(cr, {0, 0, 0});
  draw_text(cr, x, y + 10, "worst corner");
  const double top = y + 26;
  const int degrees = int(top_degrees);
  const double convex_h = degrees > 90 ? bar_h * 2 / 3 : bar_h;
  auto at = [&](double deg) {  // the height of `deg` on the bar, from the picture's top
    return deg <= 90 ? top + bar_h - convex_h * deg / 90
                     : top + (bar_h - convex_h) * (top_degrees - deg) / (top_degrees - 90);
  };
  for (int i = 0; i < degrees; ++i) {  // one band per degree
    set_colour(cr, quality_colour(i + 0.5));
    cairo_rectangle(cr, x, at(i + 1), w, at(i) - at(i + 1) + 0.5);
    cairo_fill(cr);
  }
  set_colour(cr, {0, 0, 0});
  for (int deg = 0; deg <= 90; deg += 30) {
    draw_text(cr, x + w + 4, at(deg) + 4, std::to_string(deg) + "\xc2\xb0");
  }
  if (degrees > 90) {
    draw_text(cr, x + w + 4, at(degrees) + 4, std::to_string(degrees) + "\xc2\xb0");
    draw_text(cr, x + w + 4, (at(90) + at(degrees)) / 2 + 4, "non-convex");
  }
  double swatch_y = top + bar_h + 14;
  auto swatch = [&](const Rgb& colour, const char* label) {
    set_colour(cr, colour);
    cairo_rectangle(cr, x, swatch_y, w, 12);
    cairo_fill(cr);
    set_colour(cr, {0, 0, 0});
    draw_text(cr, x + w + 4, swatch_y + 10, label);
    swatch_y += 18;
  };
  if (triangles) swatch(kTriangleColour, "triangle");
  if (polygons) swatch(kPolygonColour, "polygon");
  if (added) swatch(kAddedVertexColour, "added vertex");
}

}  // namespace

Rgb quality_colour(double degrees) {
  struct Stop {
    double at;
    Rgb colour;
  };
  static constexpr Stop stops[] = {{0, {0.19, 0.36, 0.78}},
                                   {30, {0.55, 0.75, 0.95}},
                                   {60, {0.96, 0.7, 0.55}},
                                   {90, {0.8, 0.1, 0.1}}};
  if (std::isnan(degrees)) return {0.2, 0.0, 0.0};
  if (degrees > 90) {  // non-convex: dark red darkening to the degenerate 270°
    const double t = std::min(1.0, (degrees - 90) / 180);
    return {0.5 - 0.3 * t, 0.0, 0.0};
  }
  if (degrees <= 0) return stops[0].colour;
  int i = 0;
  while (degrees > stops[i + 1].at) ++i;
  const double t = (degrees - stops[i].at) / (stops[i + 1].at - stops[i].at);
  const Rgb &a = stops[i].colour, &b = stops[i + 1].colour;
  return {a.r + t * (b.r - a.r), a.g + t * (b.g - a.g), a.b + t * (b.b - a.b)};
}

bool is_picture_path(const std::string& path) {
  return ends_with(path, ".png") || ends_with(path, ".svg");
}

std::array<double, 3> view_direction(const PolygonMesh& mesh, const RenderOptions& options) {
  if (options.view) {
    const Vec v = *options.view;
    if (!(dot(v, v) > 0) || !std::isfinite(dot(v, v))) {
      throw MeshError("render: the view direction must be a finite non-zero vector");
    }
    return unit(v);
  }
  Vec lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  for (VertexId v : mesh.corners) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], mesh.positions[v][k]);
      hi[k] = std::max(hi[k], mesh.positions[v][k]);
    }
  }
  int thin = 2;
  for (int k = 0; k < 3; ++k) {
    if (hi[k] - lo[k] < hi[thin] - lo[thin]) thin = k;
  }
  Vec view{0.25, 0.2, 0.25};  // the tilt: about 20° off the thinnest axis
  view[thin] = -1;
  return unit(view);
}

void render_mesh(const PolygonMesh& mesh, const std::string& path, const RenderOptions& options) {
  const bool svg = ends_with(path, ".svg");
  if (!is_picture_path(path)) {
    throw MeshError(path + ": a picture must be .png or .svg");
  }
  if (options.width < 200 || options.height < 200 || options.width > 16384 ||
      options.height > 16384) {
    throw MeshError(path + ": the picture must be 200 to 16384 pixels a side");
  }
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    for (VertexId v : mesh.face(f)) {
      if (v >= mesh.positions.size()) {
        throw MeshError(path + ": face " + std::to_string(f) + " names vertex " +
                        std::to_string(v) + " of " + std::to_string(mesh.positions.size()));
      }
    }
  }
  const Vec view = view_direction(mesh, options);
  bool has_quads = false, has_triangles = false, has_polygons = false, has_added = false;
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    const auto arity = mesh.arity(f);
    has_quads |= arity == 4, has_triangles |= arity == 3, has_polygons |= arity > 4;
  }
  for (VertexId v : mesh.corners) has_added |= v >= options.first_added_vertex;

  const double W = options.width, H = options.height;
  const double caption_h = options.caption.empty() ? 0 : 12 + 16.0 * options.caption.size();
  const double legend_w = has_quads ? 130 : 0;
  const double box_w = W - 20 - legend_w, box_h = std::max(40.0, H - 20 - caption_h);
  const Camera cam = fit_camera(mesh, view, 10, 10, box_w, box_h);

  std::unique_ptr<cairo_surface_t, void (*)(cairo_surface_t*)> surface(
      svg ? cairo_svg_surface_create(path.c_str(), W, H)
          : cairo_image_surface_create(CAIRO_FORMAT_ARGB32, int(W), int(H)),
      &cairo_surface_destroy);
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS) {
    throw MeshError(path + ": cannot create the picture: " +
                    cairo_status_to_string(cairo_surface_status(surface.get())));
  }
  std::unique_ptr<cairo_t, void (*)(cairo_t*)> context(cairo_create(surface.get()), &cairo_destroy);
  cairo_t* cr = context.get();
  set_colour(cr, kBackground);
  cairo_paint(cr);

  // Far faces first (painter's algorithm), by the depth of their centroid along the view.
  std::vector<double> depth(mesh.face_count());
  std::vector<FaceId> order(mesh.face_count());
  double edge_px = 0;
  std::uint64_t edges = 0;
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    const auto face = mesh.face(f);
    double d = 0;
    for (std::size_t c = 0; c < face.size(); ++c) {
      d += dot(mesh.positions[face[c]], view);
      const Vec e = sub(mesh.positions[face[(c + 1) % face.size()]], mesh.positions[face[c]]);
      edge_px += cam.scale * std::sqrt(std::max(0.0, dot(e, e) - dot(e, view) * dot(e, view)));
      ++edges;
    }
    depth[f] = d / double(face.size());
  }
  std::iota(order.begin(), order.end(), FaceId{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](FaceId a, FaceId b) { return depth[a] > depth[b]; });
  // Lines as thin as the faces are small, so that a dense mesh still shows its shading.
  const double mean_edge = edges ? edge_px / double(edges) : 1;
  const double line_width = std::clamp(mean_edge / 14, 0.2, 1.2);
  const double line_alpha = mean_edge < 5 ? 0.35 : 0.75;
  double worst_quad = 0;  // for the colour bar's range
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_width(cr, line_width);
  for (FaceId f : order) {
    const auto face = mesh.face(f);
    const Vec normal = vec3::newell_normal(mesh.positions, face);
    const double length = std::sqrt(dot(normal, normal));
    const double cosine = length > 0 ? std::abs(dot(normal, view)) / length : 0;
    Rgb colour = kPolygonColour;
    if (face.size() == 4) {
      const double cost = quad_corner_deviation(mesh.positions[face[0]], mesh.positions[face[1]],
                                                mesh.positions[face[2]], mesh.positions[face[3]]);
      colour = quality_colour(cost);
      worst_quad = std::max(worst_quad, std::isnan(cost) ? 270.0 : cost);
    } else if (face.size() == 3) {
      colour = has_quads ? kTriangleColour : kPlainColour;
    }
    for (std::size_t c = 0; c < face.size(); ++c) {
      const auto s = cam.project(mesh.positions[face[c]]);
      c == 0 ? cairo_move_to(cr, s[0], s[1]) : cairo_line_to(cr, s[0], s[1]);
    }
    cairo_close_path(cr);
    set_colour(cr, colour, 0.35 + 0.65 * std::min(1.0, cosine));
    cairo_fill_preserve(cr);
    cairo_set_source_rgba(cr, 0.1, 0.1, 0.1, line_alpha);
    cairo_stroke(cr);
  }
  if (has_added) {
    set_colour(cr, kAddedVertexColour);
    const double radius = std::clamp(mean_edge / 6, 1.5, 4.0);
    for (VertexId v = options.first_added_vertex; v < mesh.positions.size(); ++v) {
      const auto s = cam.project(mesh.positions[v]);
      cairo_new_sub_path(cr);
      cairo_arc(cr, s[0], s[1], radius, 0, 2 * std::numbers::pi);
    }
    cairo_fill(cr);
  }
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  if (has_quads) {
    const double top = worst_quad <= 90 ? 90 : std::min(270.0, 30 * std::ceil(worst_quad / 30));
    draw_legend(cr, W - legend_w + 8, 10, box_h, top, has_triangles, has_polygons, has_added);
  }
  cairo_set_font_size(cr, 12);
  set_colour(cr, {0, 0, 0});
  for (std::size_t i = 0; i < options.caption.size(); ++i) {
    draw_text(cr, 10, H - caption_h + 16 * (i + 1), options.caption[i]);
  }
  context.reset();
  cairo_surface_flush(surface.get());
  const cairo_status_t status =
      svg ? (cairo_surface_finish(surface.get()), cairo_surface_status(surface.get()))
          : cairo_surface_write_to_png(surface.get(), path.c_str());
  if (status != CAIRO_STATUS_SUCCESS) {
    throw MeshError(path + ": cannot write the picture: " + cairo_status_to_string(status));
  }
}

}  // namespace petersen
