#include "petersen/dualize/cross_field.hpp"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "petersen/mesh/vec3.hpp"

namespace petersen {

namespace {

using Complex = std::complex<double>;

// A triangle's tangent frame: first axis along side 0, second axis the normal crossed with it.
struct Frame {
  vec3::Vec3 x{}, y{};
  bool valid = false;
};

Frame frame_of(const PolygonMesh& mesh, std::span<const VertexId> t) {
  const auto& p = mesh.positions;
  const vec3::Vec3 side = vec3::sub(p[t[1]], p[t[0]]);
  const vec3::Vec3 normal = vec3::cross(side, vec3::sub(p[t[2]], p[t[0]]));
  const double side_length = std::sqrt(vec3::dot(side, side));
  const double normal_length = std::sqrt(vec3::dot(normal, normal));
  // Relative to the side's scale, so that a tiny but well-shaped triangle keeps its frame.
  if (!(side_length > 0) || !(normal_length > 1e-12 * side_length * side_length)) return {};
  Frame frame;
  frame.x = vec3::unit(side);
  frame.y = vec3::cross(vec3::unit(normal), frame.x);
  frame.valid = true;
  return frame;
}

// The angle of side k (corner k to corner k + 1) in the triangle's frame.
double side_angle(const PolygonMesh& mesh, std::span<const VertexId> t, const Frame& frame, int k) {
  const vec3::Vec3 d = vec3::sub(mesh.positions[t[(k + 1) % 3]], mesh.positions[t[k]]);
  return std::atan2(vec3::dot(d, frame.y), vec3::dot(d, frame.x));
}

// Per node: whether it has a frame, and the fourth powers of its sides' directions, e^{4iα_k}
// (0 without a frame).
struct SideDirections {
  std::vector<std::uint8_t> valid;
  std::vector<std::array<Complex, 3>> power;  // e^{4iα_k}, k = 0, 1, 2
};

SideDirections side_directions(const PairableGraph& graph, const PolygonMesh& mesh) {
  SideDirections sides;
  sides.valid.resize(graph.node_count);
  sides.power.resize(graph.node_count);
  for (NodeId t = 0; t < graph.node_count; ++t) {
    const auto corners = mesh.face(graph.face_of(t));
    const Frame frame = frame_of(mesh, corners);
    sides.valid[t] = frame.valid;
    if (!frame.valid) continue;
    for (int k = 0; k < 3; ++k)
      sides.power[t][k] = std::polar(1.0, 4 * side_angle(mesh, corners, frame, k));
  }
  return sides;
}

// Which side of node t the pairable edge e crosses.
int side_of(const PairableGraph& graph, NodeId t, EdgeId e) {
  const EdgeId* edges = &graph.node_edges[3 * std::size_t{t}];
  return edges[0] == e ? 0 : edges[1] == e ? 1 : 2;
}

}  // namespace

CrossField cross_field(const PairableGraph& graph, const PolygonMesh& mesh,
                       const CrossFieldOptions& options) {
  if (!(options.alignment > 0) || !std::isfinite(options.alignment)) {
    throw std::invalid_argument("cross field: alignment must be positive and finite, not " +
                                std::to_string(options.alignment));
  }
  const std::uint32_t n = graph.node_count;
  SideDirections sides = side_directions(graph, mesh);
  const double lambda = options.alignment;
  // The system (L + λI) u = λ q: L the connection Laplacian, one row per node.
  Eigen::VectorXcd target(n);
  std::vector<double> diagonal(n, lambda);
  std::vector<Eigen::Triplet<Complex>> entries;
  entries.reserve(std::size_t{n} + 2 * std::size_t{graph.edge_count()});
  for (NodeId t = 0; t < n; ++t) {
    Complex q = 0;
    double weight = 0;
    for (int k = 0; k < 3 && sides.valid[t]; ++k) {
      const double w = graph.node_edges[3 * std::size_t{t} + k] == kNoEdge ? kFeatureSideWeight : 1;
      q += w * sides.power[t][k];
      weight += w;
    }
    // A right isosceles triangle's mean is 1/3 (two sides agree, the diagonal cancels one):
    // scaled so that it says 1, the most any triangle says.
    q = weight > 0 ? 3.0 * q / weight : Complex{0};
    if (std::abs(q) > 1) q /= std::abs(q);
    target[t] = lambda * q;
  }
  for (EdgeId e = 0; e < graph.edge_count(); ++e) {
    const NodeId s = graph.edge_ends[2 * std::size_t{e}],
                 t = graph.edge_ends[2 * std::size_t{e} + 1];
    if (!sides.valid[s] || !sides.valid[t]) continue;
    // The shared edge's direction is side i of s and side j of t (opposite or equal ways: a half
    // turn is a whole turn in the fourth power), so a cross at angle β in t's frame is at
    // β + α_s − α_t in s's: r_st = e^{4i(α_s − α_t)}.
    const Complex r =
        sides.power[s][side_of(graph, s, e)] * std::conj(sides.power[t][side_of(graph, t, e)]);
    entries.emplace_back(s, t, -r);
    entries.emplace_back(t, s, -std::conj(r));
    diagonal[s] += 1;
    diagonal[t] += 1;
  }
  for (NodeId t = 0; t < n; ++t) entries.emplace_back(t, t, Complex{diagonal[t]});
  Eigen::SparseMatrix<Complex> system(n, n);
  system.setFromTriplets(entries.begin(), entries.end());
  entries = {};

  Eigen::ConjugateGradient<Eigen::SparseMatrix<Complex>, Eigen::Lower | Eigen::Upper> solver;
  solver.setTolerance(options.tolerance);
  solver.setMaxIterations(static_cast<Eigen::Index>(options.max_iterations));
  solver.compute(system);
  // Started from the targets themselves (u = q): where the field is already smooth, it is done.
  Eigen::VectorXcd start = target / lambda;
  const Eigen::VectorXcd u = solver.solveWithGuess(target, start);
  CrossField field;
  field.cross.assign(u.data(), u.data() + n);
  field.side_power = std::move(sides.power);
  field.iterations = static_cast<std::uint32_t>(solver.iterations());
  field.residual = solver.error();
  return field;
}

std::pmr::vector<double> side_alignment(const CrossField& field) {
  const std::size_t n = field.cross.size();
  std::pmr::vector<double> alignment(3 * n, 0.0);
  for (std::size_t t = 0; t < n; ++t) {
    const Complex u = field.cross[t];
    const double confidence = std::min(1.0, std::abs(u));
    if (field.side_power[t][0] == Complex{0} || confidence == 0) continue;  // no frame, no cross
    const Complex towards = u / std::abs(u);
    for (int k = 0; k < 3; ++k) {
      // cos 4δ for δ the angle to the nearest of the cross's four directions, δ in [0, 45°].
      const double cosine =
          std::clamp(std::real(field.side_power[t][k] * std::conj(towards)), -1.0, 1.0);
      const double degrees = std::acos(cosine) / 4 * (180 / std::numbers::pi);
      alignment[3 * t + k] = confidence * (45 - degrees);
    }
  }
  return alignment;
}

std::pmr::vector<double> pairable_edge_flow(const PairableGraph& graph,
                                            std::span<const double> alignment) {
  std::pmr::vector<double> flow(graph.edge_count());
  for (EdgeId e = 0; e < graph.edge_count(); ++e) {
    const NodeId s = graph.edge_ends[2 * std::size_t{e}],
                 t = graph.edge_ends[2 * std::size_t{e} + 1];
    flow[e] = alignment[3 * std::size_t{s} + side_of(graph, s, e)] +
              alignment[3 * std::size_t{t} + side_of(graph, t, e)];
  }
  return flow;
}

}  // namespace petersen
