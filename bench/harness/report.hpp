#pragma once
// The bench's tables: the terminal table in the paper's layout (Tables 4.3 and 4.4, with the
// paper's figures beside ours where it has them), the Table 4.2 check of every input, CSV and
// Markdown.

#include <ostream>
#include <string>
#include <vector>

#include "runner.hpp"

namespace petersen::bench {

/// One line per input: V, E, F, genus, and for family members the paper's Table 4.2 row and our
/// relative deviation from it.
void print_inputs(std::ostream& out, const std::vector<InputResult>& results);

/// Columns (a)–(e), the ratio to the BFS floor, peak memory, counters and runs, per input and
/// contestant; the paper's (a)–(e) beside PS and LRS rows of A1–A5 and B1–B5.
void print_table(std::ostream& out, const std::vector<InputResult>& results);

/// One CSV row per input and contestant, every measure and the paper's figures.
void write_csv(const std::string& path, const std::vector<InputResult>& results);

/// The inputs and the results as Markdown tables (for bench/RESULTS.md).
void write_markdown(std::ostream& out, const std::vector<InputResult>& results);

/// Whether a family member's genus differs from Table 4.2 or its triangle count is off by more
/// than 2 %; the reason is written to `out`.
bool off_table_42(std::ostream& out, const InputResult& result);

}  // namespace petersen::bench
