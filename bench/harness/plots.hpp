#pragma once
// Plots through gnuplot: total matching time against triangles (log–log, every input), and the
// growth curves of the doubling series normalised by n, n log n and n log² n.

#include <string>
#include <vector>

#include "runner.hpp"

namespace petersen::bench {

/// Writes the data files and plots.gp into `directory`, then runs gnuplot there if it is on the
/// PATH (PNG via pngcairo). Returns whether the PNGs were drawn.
bool write_plots(const std::string& directory, const std::vector<InputResult>& results);

}  // namespace petersen::bench
