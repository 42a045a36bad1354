#pragma once
// CLI11 validators for the values the library would refuse, so that a bad flag fails at once,
// named by CLI11 ("--sharp-angle: ..."), before any file is read.

#include <CLI/CLI.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace petersen::cli {

/// A finite number in [low, high]. CLI::Range lets "nan" through (every comparison with NaN is
/// false), and CLI11 reads "nan" and "inf" as numbers.
CLI::Validator finite_in(double low, double high);

/// A path whose folder exists (the current one for a bare name), so that an output that cannot be
/// written is refused before the work rather than after it.
CLI::Validator in_existing_folder();

/// One of `names`, in any case (the value becomes the name as listed: the names differ in more
/// than case); any other value is refused with the list and `note`. The help shows the list.
CLI::Validator one_of(std::vector<std::string> names, std::string note = "");

/// The names `to_string` gives an enum's values, numbered from 0 up to the first it calls "?":
/// the list a library's parse_* accepts, so that a value added there is offered here too.
template <class Enum>
std::vector<std::string> names_of() {
  std::vector<std::string> names;
  for (int value = 0;; ++value) {
    const std::string_view name = to_string(static_cast<Enum>(value));
    if (name == "?") return names;
    names.emplace_back(name);
  }
}

}  // namespace petersen::cli
