#include "triangulation.hpp"

#include <stdexcept>
#include <string>

#include "petersen/dualize/pairable_graph.hpp"
#include "petersen/mesh/mesh_report.hpp"
#include "spatial_order.hpp"

namespace petersen::lrs {

namespace {

constexpr SurfaceRequirements kSurface{.allow_pinched_vertices = false,
                                       .allow_several_components = false};

// The surface lrs needs: triangles only, closed, connected, no pinched vertex. Throws MeshError
// naming the first face that is not a triangle, or the surface's fault. O(C log d).
void require_closed_triangle_surface(const PolygonMesh& mesh) {
  for (FaceId f = 0; !mesh.all_triangles() && f < mesh.face_count(); ++f) {
    if (mesh.arity(f) != 3) {
      throw MeshError("face " + std::to_string(f) + " has " + std::to_string(mesh.arity(f)) +
                      " corners; only triangles are supported here");
    }
  }
  require_closed_surface(mesh, kSurface);
}

bool corners_in_range(const PolygonMesh& mesh) {
  for (VertexId v : mesh.corners)
    if (v >= mesh.positions.size()) return false;
  return true;
}

}  // namespace

Triangulation Triangulation::from_mesh(const PolygonMesh& mesh, Numbering numbering) {
  if (numbering == Numbering::as_given) {
    require_closed_triangle_surface(mesh);
    return build(mesh);
  }
  // The check, too, runs faster on the ordered copy. Renumbering changes no property it tests,
  // so when the copy fails, the input fails as well: it is checked then, for an error that names
  // the input's elements. Corners out of range cannot be ordered: the input's check names them.
  if (!mesh.all_triangles() || !corners_in_range(mesh)) require_closed_triangle_surface(mesh);
  SpatialMesh ordered = spatially_ordered(mesh);
  try {
    require_closed_triangle_surface(ordered.mesh);
  } catch (const MeshError&) {
    require_closed_triangle_surface(mesh);
    throw;
  }
  Triangulation tri = build(ordered.mesh);
  tri.input_vertex_ = std::move(ordered.input_vertex);
  return tri;
}

Triangulation Triangulation::build(const PolygonMesh& mesh) {
  // On a closed, consistently oriented simplicial surface every side is pairable: the pairable
  // graph is the dual, its edges numbered by (min, max) vertex.
  const PairableGraph dual = build_pairable_graph(mesh);
  if (!dual.cubic) {
    throw MeshError("two triangles with the same three vertices (not a simplicial surface)");
  }
  const std::uint32_t edges = dual.edge_count();
  const auto faces = static_cast<std::uint32_t>(mesh.face_count());

  Triangulation tri;
  tri.links_ = Links(2 * std::size_t{edges});  // every halfedge is written below
  tri.edge_alive_.assign(edges, 1);
  tri.out_.assign(mesh.positions.size(), kNoHalfedge);
  tri.degree_.assign(mesh.positions.size(), 0);
  tri.face_capacity_ = faces;

  // Halfedge 3t+k of the mesh (edge k of triangle t) becomes 2e+s when it is side s of edge e,
  // side 0 the smaller of the two halfedge ids.
  std::vector<Halfedge> ours(3 * std::size_t{faces});
  for (std::size_t slot = 0; slot < ours.size(); ++slot) {
    const EdgeId e = dual.node_edges[slot];
    const NodeId t = static_cast<NodeId>(slot / 3);
    const NodeId other =
        dual.edge_ends[2 * std::size_t{e}] ^ dual.edge_ends[2 * std::size_t{e} + 1] ^ t;
    std::size_t other_slot = 3 * std::size_t{other};
    while (dual.node_edges[other_slot] != e) ++other_slot;
    ours[slot] = 2 * e + (slot < other_slot ? 0u : 1u);
  }
  for (FaceId t = 0; t < faces; ++t) {
    const auto corners = mesh.face(t);
    for (std::uint32_t k = 0; k < 3; ++k) {
      const Halfedge h = ours[3 * std::size_t{t} + k];
      const VertexId v = corners[k];
      tri.links_[h] = {v, ours[3 * std::size_t{t} + (k + 1) % 3]};
      tri.out_[v] = h;
      ++tri.degree_[v];
    }
  }
  for (VertexId v = 0; v < tri.out_.size(); ++v) tri.live_vertices_ += tri.out_[v] != kNoHalfedge;
  tri.live_edges_ = edges;
  tri.live_faces_ = faces;
  return tri;
}

PolygonMesh Triangulation::to_mesh(const Positions& positions) const {
  PolygonMesh mesh;
  mesh.positions = positions;
  mesh.corners.reserve(3 * std::size_t{live_faces_});
  for (Halfedge h = 0; h < 2 * edge_capacity(); ++h) {
    if (!edge_alive(edge(h)) || !smallest_of_face(h)) continue;
    for (const Halfedge corner : {h, next(h), prev(h)}) {
      mesh.corners.push_back(input_vertex(origin(corner)));
    }
  }
  return mesh;
}

std::string Triangulation::check() const {
  const auto at = [](const char* what, std::uint64_t id) {
    return std::string(what) + " " + std::to_string(id);
  };
  std::uint32_t edges = 0, faces = 0;
  std::vector<std::uint32_t> outgoing(out_.size(), 0);
  for (EdgeId e = 0; e < edge_capacity(); ++e) {
    if (!edge_alive(e)) continue;
    ++edges;
    for (Halfedge h = 2 * e; h < 2 * e + 2; ++h) {
      const Halfedge n = next(h);
      if (!edge_alive(edge(n)) || next(next(n)) != h) return at("face cycle not 3 at halfedge", h);
      if (origin(n) != destination(h)) return at("origin mismatch at halfedge", h);
      if (origin(h) == destination(h)) return at("loop at halfedge", h);
      if (!vertex_alive(origin(h))) return at("dead origin at halfedge", h);
      faces += smallest_of_face(h);
      ++outgoing[origin(h)];
    }
  }
  if (edges != live_edges_) return at("live edge count off, counted", edges);
  if (faces != live_faces_) return at("live face count off, counted", faces);
  std::uint32_t vertices = 0;
  VertexMarks marks(vertex_capacity());
  for (VertexId v = 0; v < vertex_capacity(); ++v) {
    if (!vertex_alive(v)) continue;
    ++vertices;
    const Halfedge first = out(v);
    if (!edge_alive(edge(first)) || origin(first) != v) return at("out() wrong at vertex", v);
    marks.clear();
    std::uint32_t around = 0;
    Halfedge h = first;
    do {
      if (marks.marked(destination(h))) return at("two edges to one neighbour at vertex", v);
      marks.mark(destination(h));
      ++around;
      h = rotate(h);
    } while (h != first && around <= outgoing[v]);
    if (around != outgoing[v]) return at("pinched (link not one cycle) at vertex", v);
    if (around != degree(v)) return at("degree off at vertex", v);
    if (around < 3) return at("degree below 3 at vertex", v);
  }
  if (vertices != live_vertices_) return at("live vertex count off, counted", vertices);
  return {};
}

}  // namespace petersen::lrs
