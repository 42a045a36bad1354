#include "report.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>

#include "paper_figures.hpp"

namespace petersen::bench {

namespace {

std::string format(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

std::string grouped(std::uint64_t value) {
  std::string digits = std::to_string(value), text;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) text += ',';
    text += digits[i];
  }
  return text;
}

std::string deviation(std::uint64_t ours, std::uint64_t paper) {
  return format("%+.2f%%", 100.0 * (double(ours) - double(paper)) / double(paper));
}

// The paper's Table 4.4 row beside one of our rows: PS beside both PS variants, LRS beside LRS.
std::optional<PaperRun> paper_beside(const InputResult& result, const Cell& cell) {
  if (cell.paper_name.empty()) return std::nullopt;
  return paper_run(result.spec.name, cell.paper_name);
}

// Columns (a)–(e) of a cell as text; one-step algorithms have no (b)–(d).
struct Columns {
  std::string a, b, c, d, e, ratio, peak, counters;
};

Columns columns(const Cell& cell) {
  if (cell.status != Cell::Status::ok) return {"", "", "", "", cell.message, "", "", ""};
  const Measures& m = cell.median;
  Columns c;
  c.a = format("%.4f", m.initial_seconds);
  if (m.two_phase) {
    c.b = format("%.4f%%", cell.paired_percent);
    c.c = grouped(m.unpaired);
    c.d = format("%.4f", m.augment_seconds);
  }
  c.e = format("%.4f", m.total_seconds());
  c.ratio = cell.ratio_to_floor > 0 ? format("%.1f", cell.ratio_to_floor) : "";
  c.peak = format("%.1f", cell.peak_mib);
  if (m.augmenting_paths) c.counters += "paths " + grouped(m.augmenting_paths);
  if (m.reductions)
    c.counters += (c.counters.empty() ? "" : ", ") + ("reductions " + grouped(m.reductions));
  if (m.flips) c.counters += (c.counters.empty() ? "" : ", ") + ("flips " + grouped(m.flips));
  if (m.labels) c.counters += (c.counters.empty() ? "" : ", ") + ("labels " + grouped(m.labels));
  return c;
}

std::string paper_columns(const PaperRun& p, const char* separator) {
  return format("%.4f", p.initial_seconds) + separator + format("%.4f%%", p.paired_percent) +
         separator + format("%.1f", p.unpaired) + separator + format("%.4f", p.augment_seconds) +
         separator + format("%.4f", p.total_seconds);
}

}  // namespace

bool off_table_42(std::ostream& out, const InputResult& result) {
  const std::optional<PaperMesh> paper = paper_mesh(result.spec.name);
  if (!paper || (result.spec.group != "A" && result.spec.group != "B")) return false;
  const MeshFacts& f = result.facts;
  const double off =
      std::abs(double(f.triangles) - double(paper->triangles)) / double(paper->triangles);
  if (f.genus != std::int64_t(paper->genus) || off > 0.02) {
    out << "TABLE 4.2 MISMATCH: " << result.spec.name << " has genus " << f.genus << " and "
        << f.triangles << " triangles; the paper's has genus " << paper->genus << " and "
        << paper->triangles << "\n";
    return true;
  }
  return false;
}

void print_inputs(std::ostream& out, const std::vector<InputResult>& results) {
  char line[512];
  std::snprintf(line, sizeof line, "%-22s %12s %12s %12s %6s %7s %7s  %s\n", "Input", "V", "E", "F",
                "genus", "load s", "dual s", "Table 4.2 (paper) and our deviation / how made");
  out << line;
  for (const InputResult& r : results) {
    const MeshFacts& f = r.facts;
    std::string beside = r.spec.note;
    if (const auto paper = paper_mesh(r.spec.name); paper && r.spec.group != "mesh") {
      beside = "paper V " + grouped(paper->vertices) + " (" +
               deviation(f.vertices, paper->vertices) + "), E " + grouped(paper->edges) + " (" +
               deviation(f.edges, paper->edges) + "), F " + grouped(paper->triangles) + " (" +
               deviation(f.triangles, paper->triangles) + "), genus " +
               std::to_string(paper->genus) + "; " + r.spec.note;
    }
    std::snprintf(line, sizeof line, "%-22s %12s %12s %12s %6lld %7.3f %7.3f  ",
                  r.spec.name.c_str(), grouped(f.vertices).c_str(), grouped(f.edges).c_str(),
                  grouped(f.triangles).c_str(), static_cast<long long>(f.genus), r.load_seconds,
                  r.dual_seconds);
    out << line << beside << "\n";
  }
}

// The runs, and the calls per run when they were repeated (RunnerOptions::min_run_seconds).
std::string runs_text(const Cell& cell) {
  if (cell.runs == 0) return "";
  std::string text = std::to_string(cell.runs);
  if (cell.median.repeats > 1) text += " x" + std::to_string(cell.median.repeats);
  return text;
}

void print_table(std::ostream& out, const std::vector<InputResult>& results) {
  char line[1024];
  const char* header = "%-16s %-14s %10s %10s %9s %10s %10s %8s %9s %8s  %s\n";
  std::snprintf(line, sizeof line, header, "Triang.", "Alg.", "(a)", "(b)", "(c)", "(d)", "(e)",
                "xBFS", "peak MiB", "runs", "counters | paper's (a) (b) (c) (d) (e)");
  out << line;
  for (const InputResult& r : results) {
    for (const Cell& cell : r.cells) {
      const Columns c = columns(cell);
      std::string tail = c.counters;
      if (const auto paper = paper_beside(r, cell))
        tail += " | paper " + std::string(paper->algorithm) + ": " + paper_columns(*paper, " ");
      if (cell.status != Cell::Status::ok) {
        std::snprintf(line, sizeof line, "%-16s %-14s %s\n", r.spec.name.c_str(),
                      cell.contestant.c_str(), cell.message.c_str());
        out << line;
        continue;
      }
      std::snprintf(line, sizeof line, header, r.spec.name.c_str(), cell.contestant.c_str(),
                    c.a.c_str(), c.b.c_str(), c.c.c_str(), c.d.c_str(), c.e.c_str(),
                    c.ratio.c_str(), c.peak.c_str(), runs_text(cell).c_str(), tail.c_str());
      out << line;
    }
    out << "\n";
  }
}

void write_csv(const std::string& path, const std::vector<InputResult>& results) {
  std::ofstream out(path);
  out << "input,group,vertices,edges,triangles,genus,contestant,status,runs,repeats,initial_s,"
         "paired_percent,unpaired,augment_s,total_s,ratio_to_bfs,peak_mib,augmenting_paths,"
         "reductions,flips,labels,paper_initial_s,paper_paired_percent,paper_unpaired,"
         "paper_augment_s,paper_total_s\n";
  for (const InputResult& r : results) {
    for (const Cell& cell : r.cells) {
      const Measures& m = cell.median;
      const bool ok = cell.status == Cell::Status::ok;
      out << r.spec.name << "," << r.spec.group << "," << r.facts.vertices << "," << r.facts.edges
          << "," << r.facts.triangles << "," << r.facts.genus << "," << cell.contestant << ","
          << (ok ? "ok" : "\"" + cell.message + "\"") << "," << cell.runs << ","
          << (ok ? cell.median.repeats : 0) << ",";
      if (ok) {
        out << m.initial_seconds << ",";
        if (m.two_phase)
          out << cell.paired_percent << "," << m.unpaired << "," << m.augment_seconds;
        else
          out << ",,";
        out << "," << m.total_seconds() << "," << cell.ratio_to_floor << "," << cell.peak_mib << ","
            << m.augmenting_paths << "," << m.reductions << "," << m.flips << "," << m.labels;
      } else {
        out << ",,,,,,,,,,";
      }
      if (const auto paper = paper_beside(r, cell))
        out << "," << paper_columns(*paper, ",");
      else
        out << ",,,,";
      out << "\n";
    }
  }
}

void write_markdown(std::ostream& out, const std::vector<InputResult>& results) {
  out << "| input | V | E | F | genus | dual build s | Table 4.2 (paper) | how made |\n"
         "|---|---:|---:|---:|---:|---:|---|---|\n";
  for (const InputResult& r : results) {
    const MeshFacts& f = r.facts;
    std::string paper_text;
    if (const auto paper = paper_mesh(r.spec.name); paper && r.spec.group != "mesh") {
      paper_text = "V " + grouped(paper->vertices) + ", E " + grouped(paper->edges) + ", F " +
                   grouped(paper->triangles) + " (ours " +
                   deviation(f.triangles, paper->triangles) + "), genus " +
                   std::to_string(paper->genus);
    }
    out << "| " << r.spec.name << " | " << grouped(f.vertices) << " | " << grouped(f.edges) << " | "
        << grouped(f.triangles) << " | " << f.genus << " | " << format("%.3f", r.dual_seconds)
        << " | " << paper_text << " | " << r.spec.note << " |\n";
  }
  out << "\n| triangulation | alg. | (a) | (b) | (c) | (d) | (e) | ×BFS | peak MiB | runs | "
         "counters "
         "| paper's (a) / (b) / (c) / (d) / (e) |\n"
         "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---|---|\n";
  for (const InputResult& r : results) {
    for (const Cell& cell : r.cells) {
      const Columns c = columns(cell);
      std::string paper_text;
      if (const auto paper = paper_beside(r, cell))
        paper_text = std::string(paper->algorithm) + ": " + paper_columns(*paper, " / ");
      out << "| " << r.spec.name << " | " << cell.contestant << " | " << c.a << " | " << c.b
          << " | " << c.c << " | " << c.d << " | " << c.e << " | " << c.ratio << " | " << c.peak
          << " | " << runs_text(cell) << " | " << c.counters << " | " << paper_text << " |\n";
    }
  }
}

}  // namespace petersen::bench
