#include "plots.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>

namespace petersen::bench {

namespace {

struct Point {
  double triangles, seconds;
};

void plot_lines(std::ofstream& gp, const std::vector<std::string>& names, const std::string& prefix,
                int column, const char* style) {
  gp << "plot ";
  for (std::size_t i = 0; i < names.size(); ++i) {
    gp << (i ? ", \\\n     " : "") << "'" << prefix << names[i] << ".dat' using 1:" << column
       << " with " << style << " title '" << names[i] << "'";
  }
  gp << "\n";
}

}  // namespace

bool write_plots(const std::string& directory, const std::vector<InputResult>& results) {
  std::map<std::string, std::vector<Point>> all, doubling;
  std::vector<std::string> names;
  for (const InputResult& r : results) {
    for (const Cell& cell : r.cells) {
      if (cell.status != Cell::Status::ok) continue;
      if (std::find(names.begin(), names.end(), cell.contestant) == names.end())
        names.push_back(cell.contestant);
      const Point p{double(r.facts.triangles), cell.median.total_seconds()};
      all[cell.contestant].push_back(p);
      if (r.spec.group == "doubling") doubling[cell.contestant].push_back(p);
    }
  }
  auto by_size = [](const Point& a, const Point& b) { return a.triangles < b.triangles; };
  for (auto& [name, points] : all) {
    std::sort(points.begin(), points.end(), by_size);
    std::ofstream data(directory + "/total-" + name + ".dat");
    data << "# triangles total_seconds\n";
    for (const Point& p : points) data << p.triangles << " " << p.seconds << "\n";
  }
  std::vector<std::string> growing;
  for (auto& [name, points] : doubling) {
    std::sort(points.begin(), points.end(), by_size);
    growing.push_back(name);
    std::ofstream data(directory + "/growth-" + name + ".dat");
    data << "# n seconds/n seconds/(n log2 n) seconds/(n log2^2 n), in nanoseconds\n";
    for (const Point& p : points) {
      const double n = p.triangles, lg = std::log2(n), ns = p.seconds * 1e9;
      data << n << " " << ns / n << " " << ns / (n * lg) << " " << ns / (n * lg * lg) << "\n";
    }
  }

  std::ofstream gp(directory + "/plots.gp");
  gp << "set terminal pngcairo size 1100,750 noenhanced\nset key outside right\nset grid\n"
     << "set output 'total-vs-triangles.png'\nset logscale xy\nset xlabel 'triangles'\n"
     << "set ylabel 'matching time (s), median'\n"
     << "set title 'Total matching time (e) against triangles, every input'\n";
  plot_lines(gp, names, "total-", 2, "points");
  if (!growing.empty()) {
    const char* titles[3] = {"time / n", "time / (n log2 n)", "time / (n log2^2 n)"};
    const char* files[3] = {"growth-n.png", "growth-nlogn.png", "growth-nlog2n.png"};
    for (int k = 0; k < 3; ++k) {
      gp << "set output '" << files[k] << "'\nset logscale x\nset logscale y\n"
         << "set xlabel 'triangles (doubling series)'\nset ylabel '" << titles[k] << " (ns)'\n"
         << "set title 'Growth: " << titles[k] << "'\n";
      plot_lines(gp, growing, "growth-", k + 2, "linespoints");
    }
  }
  gp.close();
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) return false;
  return std::system(("cd '" + directory + "' && gnuplot plots.gp").c_str()) == 0;
}

}  // namespace petersen::bench
