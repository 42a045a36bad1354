// The quality table: for one mesh, every way of pairing its triangles judged by the same
// measure (quad_corner_deviation): sg, ps and lrs (shape-blind), --objective quality, the threshold
// mode at 40 degrees, LEMON's MaxWeightedPerfectMatching on the same costs (closed meshes), and
// any outside result (Blender's Tris to Quads) read back from its file.
//
// Usage:
//   petersen_quality_bench --obj IN OUT          write IN as OBJ (for Blender's fast importer)
//   petersen_quality_bench MESH [--svg FILE] [--external LABEL FILE SECONDS]...
// Prints one Markdown row per method: paired % of the triangles, worst-corner median and 95th
// percentile, non-convex % of the quads, seconds (petersen: the whole front door, in process;
// LEMON: its matching alone; external: what the caller measured). --svg draws the distributions of
// the quads' worst corners, one line per method, in 5-degree bins.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "dual_costs.hpp"
#include "petersen/dualize/dual.hpp"
#include "petersen/dualize/quad_quality.hpp"
#include "petersen/io/read_mesh.hpp"
#include "petersen/io/write_mesh.hpp"
#include "petersen/lemon_peer/lemon_peer.hpp"
#include "petersen/matching/min_cost_matching.hpp"
#include "petersen/quadrangulate/quadrangulate.hpp"

namespace {

using namespace petersen;

struct Row {
  std::string method;
  double paired_percent = 0;
  QualityFigures figures;
  double seconds = 0;
  std::string note;
  std::vector<double> costs;  // of the quads made from two triangles, for the plot
};

double seconds_of(const std::function<void()>& run) {
  const auto start = std::chrono::steady_clock::now();
  run();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Row row_of(std::string method, std::uint64_t triangles, std::uint64_t pairs,
           std::vector<double> costs, double seconds, std::string note) {
  Row row{std::move(method),
          triangles ? 200.0 * double(pairs) / double(triangles) : 0,
          {},
          seconds,
          std::move(note),
          costs};
  row.figures = quality_figures(std::move(costs));
  return row;
}

Row by_petersen(const PolygonMesh& mesh, std::string method, const QuadOptions& options) {
  QuadResult result;
  const double seconds = seconds_of([&] { result = quadrangulate(mesh, options); });
  const QuadStats& s = result.stats;
  std::string note = s.maximum_certified ? "maximum certified" : "";
  if (s.optimality_certified) note += ", minimum certified";
  std::vector<double> costs;
  const auto& p = result.mesh.positions;
  for (FaceId o = 0; o < result.mesh.face_count(); ++o) {
    // Every quad made of two triangles, lrs's included: one whose triangle a flip made names no
    // input face for it (kNoFace), and skipping those left lrs's worst quads out of its row (the
    // bunny read a median of 54.3° instead of the 67.0° its summary prints). Only an input
    // polygon kept as it is (its own face, no partner) is not a pair's quad.
    const auto [f, g] = result.sources[o];
    if (result.mesh.arity(o) != 4) continue;
    if (f != kNoFace && g == kNoFace && mesh.arity(f) == 4) continue;
    const auto c = result.mesh.face(o);
    costs.push_back(quad_corner_deviation(p[c[0]], p[c[1]], p[c[2]], p[c[3]]));
  }
  return row_of(std::move(method), s.triangles, s.pairs, std::move(costs), seconds,
                std::move(note));
}

// LEMON's minimum-cost perfect matching of the dual, on the costs --objective quality uses.
Row by_lemon(const PolygonMesh& mesh) {
  const Dual dual = build_dual(mesh);
  const CubicGraph& g = dual.graph;
  const std::pmr::vector<double> degrees = bench::dual_edge_costs(mesh, dual);
  const std::pmr::vector<Cost> costs = scale_costs(degrees);
  std::vector<std::uint32_t> mate(g.node_count());
  std::int64_t total = 0;
  bool perfect = false;
  const double seconds = seconds_of([&] {
    perfect = lemon_peer::min_cost_perfect_matching(
        g.node_count(), g.edge_ends().data(), g.edge_count(), costs.data(), mate.data(), total);
  });
  std::vector<double> quads;
  for (NodeId v = 0; v < g.node_count(); ++v) {
    if (perfect && g.endpoints(mate[v])[0] == v) quads.push_back(degrees[mate[v]]);
  }
  const std::uint64_t pairs = quads.size();
  return row_of("LEMON weighted", g.node_count(), pairs, std::move(quads), seconds,
                "matching only; total " + std::to_string(double(total) / kDefaultCostScale));
}

Row by_file(std::string label, const std::string& file, std::uint64_t triangles, double seconds) {
  const PolygonMesh out = read_mesh(file);
  std::vector<double> costs = quad_costs(out);
  const std::uint64_t quads = costs.size();  // before the move below
  return row_of(std::move(label), triangles, quads, std::move(costs), seconds, "read back");
}

// The distributions as an SVG line chart: x the worst corner (0-180 degrees, 5-degree bins, the
// last bin everything above 175), y the share of each method's quads.
void write_svg(const std::string& path, const std::string& title, const std::vector<Row>& rows) {
  constexpr int kBins = 36;
  constexpr double kW = 720, kH = 360, kLeft = 60, kTop = 40, kPlotW = 480, kPlotH = 260;
  const char* colours[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                           "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};
  std::vector<std::vector<double>> shares;
  double top = 0;
  for (const Row& row : rows) {
    std::vector<double> bins(kBins, 0);
    for (double c : row.costs) bins[std::min(kBins - 1, static_cast<int>(c / 5))] += 1;
    for (double& b : bins) b /= std::max<double>(1, row.costs.size());
    top = std::max(top, *std::max_element(bins.begin(), bins.end()));
    shares.push_back(std::move(bins));
  }
  top = std::max(top, 1e-9);
  std::ofstream svg(path);
  svg << "<svg xmlns='http://www.w3.org/2000/svg' width='" << kW << "' height='" << kH
      << "' font-family='sans-serif' font-size='12'>\n<rect width='100%' height='100%' "
         "fill='white'/>\n<text x='"
      << kLeft << "' y='20' font-size='14'>" << title
      << ": share of quads by worst-corner deviation (degrees)</text>\n";
  svg << "<line x1='" << kLeft << "' y1='" << kTop + kPlotH << "' x2='" << kLeft + kPlotW
      << "' y2='" << kTop + kPlotH << "' stroke='black'/>\n<line x1='" << kLeft << "' y1='" << kTop
      << "' x2='" << kLeft << "' y2='" << kTop + kPlotH << "' stroke='black'/>\n";
  for (int d = 0; d <= 180; d += 30) {
    const double x = kLeft + kPlotW * d / 180.0;
    svg << "<text x='" << x - 8 << "' y='" << kTop + kPlotH + 16 << "'>" << d << "</text>\n";
  }
  for (int k = 0; k <= 4; ++k) {
    const double y = kTop + kPlotH - kPlotH * k / 4.0;
    char label[32];
    std::snprintf(label, sizeof label, "%.0f%%", 100 * top * k / 4);
    svg << "<text x='" << kLeft - 40 << "' y='" << y + 4 << "'>" << label << "</text>\n";
  }
  // A reference line at 90 degrees: quads beyond it are non-convex.
  svg << "<line x1='" << kLeft + kPlotW / 2 << "' y1='" << kTop << "' x2='" << kLeft + kPlotW / 2
      << "' y2='" << kTop + kPlotH << "' stroke='#bbb' stroke-dasharray='4 4'/>\n";
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const char* colour = colours[r % std::size(colours)];
    svg << "<polyline fill='none' stroke-width='1.5' stroke='" << colour << "' points='";
    for (int b = 0; b < kBins; ++b) {
      svg << kLeft + kPlotW * (b + 0.5) / kBins << ','
          << kTop + kPlotH - kPlotH * shares[r][b] / top << ' ';
    }
    svg << "'/>\n<text x='" << kLeft + kPlotW + 15 << "' y='" << kTop + 14 + 18 * r << "' fill='"
        << colour << "'>" << rows[r].method << "</text>\n";
  }
  svg << "</svg>\n";
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.size() == 3 && args[0] == "--obj") {
    write_mesh(args[2], read_mesh(args[1]));
    return 0;
  }
  if (args.empty()) {
    std::fprintf(stderr,
                 "usage: petersen_quality_bench MESH [--svg FILE] "
                 "[--external LABEL FILE SECONDS]... | --obj IN OUT\n");
    return 2;
  }
  const std::string file = args[0];
  std::string svg;
  struct External {
    std::string label, file;
    double seconds;
  };
  std::vector<External> externals;
  for (std::size_t i = 1; i < args.size(); ++i) {
    if (args[i] == "--svg" && i + 1 < args.size()) {
      svg = args[++i];
    } else if (args[i] == "--external" && i + 3 < args.size()) {
      externals.push_back({args[i + 1], args[i + 2], std::stod(args[i + 3])});
      i += 3;
    } else {
      std::fprintf(stderr, "unknown argument %s\n", args[i].c_str());
      return 2;
    }
  }
  const PolygonMesh mesh = read_mesh(file);
  std::uint64_t triangles = 0;
  for (FaceId f = 0; f < mesh.face_count(); ++f) triangles += mesh.arity(f) == 3;
  const std::string name = std::filesystem::path(file).filename().string();
  std::vector<Row> rows;
  rows.push_back(
      by_petersen(mesh, "sg", {.objective = Objective::pairs, .algorithm = Algorithm::sg}));
  rows.push_back(by_petersen(mesh, "auto",
                             {.objective = Objective::pairs, .algorithm = Algorithm::automatic}));
  rows.push_back(by_petersen(mesh, "lrs", {.objective = Objective::pairs, .algorithm = kLrs}));
  rows.push_back(by_petersen(mesh, "quality", {.objective = Objective::quality}));
  rows.push_back(by_petersen(mesh, "quality, max 40",
                             {.objective = Objective::quality, .max_corner_deviation = 40.0}));
  try {
    rows.push_back(by_lemon(mesh));
  } catch (const MeshError& e) {
    std::fprintf(stderr, "%s: no LEMON row, the dual needs a closed triangle mesh: %s\n",
                 name.c_str(), e.what());
  }
  for (const External& e : externals)
    rows.push_back(by_file(e.label, e.file, triangles, e.seconds));
  for (const Row& r : rows) {
    std::printf(
        "| %s | %s | %.2f | %.2f | %.2f | %.2f | %.3f | %s |\n", name.c_str(), r.method.c_str(),
        r.paired_percent, r.figures.median, r.figures.p95,
        r.figures.quads ? 100.0 * double(r.figures.nonconvex) / double(r.figures.quads) : 0.0,
        r.seconds, r.note.c_str());
    std::fflush(stdout);
  }
  if (!svg.empty()) write_svg(svg, name, rows);
  return 0;
}
