#pragma once
// CLI11 validators for the values the library would refuse, so that a bad flag fails at once,
// named by CLI11 ("--sharp-angle: ..."), before any file is read.

#include <CLI/CLI.hpp>
#include <string>

namespace petersen::cli {

/// A finite number in [low, high]. CLI::Range lets "nan" through (every comparison with NaN is
/// false), and CLI11 reads "nan" and "inf" as numbers.
CLI::Validator finite_in(double low, double high);

/// A path whose folder exists (the current one for a bare name), so that an output that cannot be
/// written is refused before the work rather than after it.
CLI::Validator in_existing_folder();

}  // namespace petersen::cli
