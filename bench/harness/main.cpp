// petersen_bench: the paper's experiment (§4) on this machine — every contestant on the same dual
// graphs, in forked children with a time cap, medians over repeated runs, tables and plots.

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "memory_pool.hpp"
#include "plots.hpp"
#include "report.hpp"

namespace {

std::vector<std::string> split(const std::string& list) {
  std::vector<std::string> items;
  std::stringstream stream(list);
  for (std::string item; std::getline(stream, item, ',');)
    if (!item.empty()) items.push_back(item);
  return items;
}

}  // namespace

int main(int argc, char** argv) {
  petersen::bench::install_memory_pool();
  using namespace petersen::bench;
  CLI::App app{"petersen_bench: the paper's §4 experiment, our figures beside the paper's"};
  bool full = false, no_meshes = false;
  std::string meshes = PETERSEN_SHARED_MESHES, families, only, out = "bench/out";
  int doubling = -1;
  RunnerOptions options;
  double budget = -1;
  std::uint64_t max_triangles = ~std::uint64_t{0};
  std::uint32_t frink_max_nodes = 20000;
  app.add_flag("--full", full,
               "everything: A1-A5, B1-B5, a 7-step doubling series (defaults: 10 runs, cap 60 s); "
               "otherwise the quick set: shared meshes, A5, B5");
  app.add_option("--meshes", meshes, "folder of shared meshes")->capture_default_str();
  app.add_flag("--no-meshes", no_meshes, "leave out the shared meshes");
  app.add_option("--families", families, "family members, e.g. A5,B5 (overrides the set's)");
  app.add_option("--doubling", doubling, "steps of the doubling series (65,536 triangles x 2^k)");
  app.add_option("--only", only, "contestants to run, e.g. bfs,auto-local,lemon (default: all)");
  app.add_option("--runs", options.runs, "runs per contestant and input (median reported)");
  app.add_option("--cap", options.cap_seconds, "seconds per run before it is killed ('> cap')");
  app.add_option("--budget", budget, "no more repeats once a contestant's runs add up to this (s)");
  app.add_option("--min-run-seconds", options.min_run_seconds,
                 "a run quicker than this repeats its call in its process until the calls add up "
                 "to it, and reports their median (0: one call per run)")
      ->capture_default_str();
  app.add_option("--seed", options.seed, "seed of the first run (run r uses seed + r)");
  app.add_option("--max-triangles", max_triangles, "skip larger inputs");
  app.add_option("--frink-max-nodes", frink_max_nodes, "largest graph for the O(n^2) frink oracle")
      ->capture_default_str();
  app.add_option("--out", out, "output folder for results.csv, results.md, table.txt, plots")
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  if (!app.count("--runs")) options.runs = full ? 10 : 5;
  if (!app.count("--cap")) options.cap_seconds = full ? 60 : 10;
  options.budget_seconds = budget >= 0 ? budget : options.cap_seconds;
  if (doubling < 0) doubling = full ? 7 : 0;

  std::vector<InputSpec> inputs;
  if (!no_meshes) inputs = shared_mesh_inputs(meshes);
  std::vector<int> a_members = {5}, b_members = {5};
  if (full) a_members = b_members = {5, 4, 3, 2, 1};
  if (app.count("--families")) {
    a_members.clear();
    b_members.clear();
    for (const std::string& name : split(families)) {
      if (name.size() != 2 || (name[0] != 'A' && name[0] != 'B') || name[1] < '1' ||
          name[1] > '5') {
        std::cerr << "unknown family member '" << name << "' (A1…A5, B1…B5)\n";
        return 2;
      }
      (name[0] == 'A' ? a_members : b_members).push_back(name[1] - '0');
    }
    for (auto* members : {&a_members, &b_members}) std::sort(members->rbegin(), members->rend());
  }
  for (auto& spec : family_inputs('A', a_members)) inputs.push_back(std::move(spec));
  for (auto& spec : family_inputs('B', b_members)) inputs.push_back(std::move(spec));
  for (auto& spec : doubling_inputs(static_cast<std::uint32_t>(doubling)))
    inputs.push_back(std::move(spec));
  std::erase_if(inputs, [&](const InputSpec& s) { return s.expected_triangles > max_triangles; });

  std::vector<Contestant> contestants = all_contestants(frink_max_nodes);
  if (!only.empty()) {
    const std::vector<std::string> wanted = split(only);
    std::erase_if(contestants, [&](const Contestant& c) {
      return std::find(wanted.begin(), wanted.end(), c.name) == wanted.end();
    });
  }

  std::filesystem::create_directories(out);
  Runner runner(std::move(contestants), options);
  std::vector<InputResult> results;
  bool mismatch = false;
  for (const InputSpec& spec : inputs) {
    std::cerr << "input " << spec.name << " (" << spec.note << ")\n";
    try {
      const auto start = std::chrono::steady_clock::now();
      const petersen::PolygonMesh mesh = spec.load();
      if (mesh.face_count() > max_triangles) continue;
      const std::chrono::duration<double> loading = std::chrono::steady_clock::now() - start;
      InputResult result = runner.run(spec, mesh, loading.count());
      if (spec.expected_genus && result.facts.genus != std::int64_t(*spec.expected_genus)) {
        std::cerr << "GENUS MISMATCH: " << spec.name << " has genus " << result.facts.genus
                  << ", its generator promised " << *spec.expected_genus << "\n";
        mismatch = true;
      }
      mismatch |= off_table_42(std::cerr, result);
      results.push_back(std::move(result));
    } catch (const std::exception& e) {
      std::cerr << "INPUT FAILED: " << spec.name << ": " << e.what() << "\n";
      mismatch = true;
    }
  }

  std::ostringstream table;
  print_inputs(table, results);
  table << "\n";
  print_table(table, results);
  std::cout << table.str();
  std::ofstream(out + "/table.txt") << table.str();
  write_csv(out + "/results.csv", results);
  {
    std::ofstream md(out + "/results.md");
    md << "Command: `";
    for (int i = 0; i < argc; ++i) md << (i ? " " : "") << argv[i];
    md << "` — runs " << options.runs << ", cap " << options.cap_seconds << " s, seed "
       << options.seed << ". Times in seconds (medians); (a) initial pairing, (b) % paired, (c) "
       << "unpaired, (d) augmentation, (e) total matching time; ×BFS = (e) over the BFS floor's "
          "(e); peak MiB = growth of the child's resident high-water mark; runs \"5 x12\" = 5 "
          "runs, each the median of 12 calls in one process (--min-run-seconds "
       << options.min_run_seconds << ").\n\n";
    write_markdown(md, results);
  }
  const bool plotted = write_plots(out, results);
  std::cerr << "wrote " << out << "/{table.txt,results.csv,results.md" << (plotted ? ",*.png" : "")
            << "}\n";
  if (runner.any_failure()) std::cerr << "SOME RUNS FAILED (see the table)\n";
  return runner.any_failure() || mismatch ? 1 : 0;
}
