#pragma once
// The summary of one `petersen quad` run, printed for people and written as JSON for scripts.

#include <cstdio>
#include <string>

#include "petersen/quadrangulate/quadrangulate.hpp"

namespace petersen::cli {

struct RunReport {
  std::string input, output;
  QuadOptions options;
  double load_seconds = 0, write_seconds = 0, total_seconds = 0;
  QuadStats quad;  ///< the front door's figures
};

void print_summary(std::FILE* out, const RunReport& report);
void write_json(std::FILE* out, const RunReport& report);

}  // namespace petersen::cli
