#include "carry_attributes.hpp"
#include "cut_into_quads.hpp"
#include "petersen/dualize/quad_quality.hpp"
#include "petersen/mesh/edge_groups.hpp"
#include "petersen/quadrangulate/stages.hpp"
#include "split_plan.hpp"

namespace petersen::quad_detail {

namespace {

// Whether some face must change: one that is not a quad and that keep_polygons does not keep.
bool has_work(const PolygonMesh& mesh, const std::vector<FaceKind>& kinds, bool keep_polygons) {
  if (mesh.all_triangles()) return mesh.face_count() > 0;
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    const std::uint32_t n = mesh.arity(f);
    if (n != 4 && !(keep_polygons && kinds[f] == FaceKind::kept && n != 3)) return true;
  }
  return false;
}

// One midpoint per planned edge, shared by all of its halfedges; returns midpoint per halfedge.
std::vector<VertexId> add_midpoints(PolygonMesh& mesh, const PolygonHalfedges& half,
                                    const SplitPlan& plan, std::vector<Blend>* new_vertices) {
  std::vector<VertexId> midpoint(half.count(), kNoNode);
  for (std::uint32_t e = 0; e < plan.edge_count(); ++e) {
    const std::uint32_t h = plan.halfedges[plan.edge_start[e]];
    const std::array<double, 3> a = mesh.positions[half.from(h)], b = mesh.positions[half.to(h)];
    mesh.positions.push_back({(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2});
    if (new_vertices != nullptr) {
      new_vertices->push_back({half.from(h), half.to(h), kNoAttribute, kNoAttribute});
    }
    const auto m = static_cast<VertexId>(mesh.positions.size() - 1);
    for (std::uint32_t i = plan.edge_start[e]; i < plan.edge_start[e + 1]; ++i) {
      midpoint[plan.halfedges[i]] = m;
    }
  }
  return midpoint;
}

void record_split_quality(QuadStats& stats, const PolygonMesh& out,
                          std::span<const FaceId> pieces) {
  std::vector<double> costs;
  costs.reserve(pieces.size());
  const auto& p = out.positions;
  for (FaceId o : pieces) {
    const auto c = out.face(o);
    costs.push_back(quad_corner_deviation(p[c[0]], p[c[1]], p[c[2]], p[c[3]]));
  }
  const QualityFigures figures = quality_figures_in_place(costs);
  stats.split_quads = pieces.size();
  stats.split_quality_median = figures.median;
  stats.split_quality_p95 = figures.p95;
}

}  // namespace

}  // namespace petersen::quad_detail

namespace petersen {

void split_leftovers(QuadResult& result, const std::vector<FaceKind>& kinds,
                     const QuadOptions& options) {
  using namespace quad_detail;  // the plan, the cuts and the attributes' blends
  QuadStats& stats = result.stats;
  PolygonMesh& mesh = result.mesh;
  if (!has_work(mesh, kinds, options.keep_polygons)) {
    stats.all_quad_certified = true;  // nothing to split: zero midpoints, trivially fewest
    // Every face is a quad or a polygon keep_polygons keeps: the other quads repeating a vertex
    // are the degenerate faces plan_splits would have kept.
    for (FaceId f = 0; f < mesh.face_count(); ++f) {
      const bool kept_polygon = options.keep_polygons && kinds[f] == FaceKind::kept;
      stats.degenerate_faces += kinds[f] != FaceKind::pair && !kept_polygon && mesh.arity(f) == 4 &&
                                repeats_a_vertex(mesh.face(f));
    }
    return;
  }
  const PolygonHalfedges half(mesh);
  const EdgeGroups groups = half.group();
  const SplitPlan plan = plan_splits(mesh, half, groups, kinds, result.sources,
                                     options.keep_polygons, options.threads);
  const std::size_t input_vertices = mesh.positions.size();
  // With attributes: what each new vertex is made from.
  const bool carry = !mesh.attributes.empty();
  std::vector<Blend> new_vertices;
  std::vector<Blend>* const blends = carry ? &new_vertices : nullptr;
  const std::vector<VertexId> midpoint = add_midpoints(mesh, half, plan, blends);
  QuadPieces cut = cut_into_quads(mesh, half, groups, midpoint, plan.kept, result.sources, blends,
                                  {.centres_where_better = options.objective != Objective::pairs});

  PolygonMesh& out = cut.mesh;
  if (carry) {
    out.attributes = derived_attributes(mesh.attributes, input_vertices, cut.face_of,
                                        cut.corner_from, new_vertices, out.memory());
  }
  out.attributes.position_type = mesh.attributes.position_type;
  // A float PLY is written back as float: the new vertices are held as floats, so that the result
  // is what the file will hold (a midpoint of two floats needs up to 25 bits).
  for (std::size_t v = input_vertices; v < mesh.positions.size(); ++v) {
    for (double& x : mesh.positions[v]) x = held_as(out.attributes.position_type, x);
  }
  out.positions = std::move(mesh.positions);
  stats.split_edges = plan.edge_count();
  stats.degenerate_faces = plan.degenerate_faces;
  stats.centre_vertices = cut.centres;
  stats.added_vertices = stats.split_edges + stats.centre_vertices;
  stats.added_vertices_minimum = plan.minimum;
  stats.all_quad_certified =
      plan.join_certified && plan.non_manifold_splits == 0 && !plan.non_manifold_beside_odd;
  record_split_quality(stats, out, cut.pieces);
  result.mesh = std::move(out);
  result.sources = std::move(cut.sources);
}

}  // namespace petersen
