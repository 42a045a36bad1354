#pragma once
// "Did you mean": the closest names to what CLI11 could not place (a misspelt flag or
// subcommand), printed beside CLI11's own message.

#include <CLI/CLI.hpp>
#include <cstdio>
#include <string>
#include <vector>

namespace petersen::cli {

/// After a failed parse of `app`: for each argument left over that starts with '-', the closest
/// flags of the subcommand it was given to; for a word left over where a subcommand was due, the
/// closest subcommands (`args`: the command line, argv[1] on, for the word CLI11 stopped at when
/// no subcommand matched). One line on `out` per argument that has a close name; none otherwise.
void print_suggestions(const CLI::App& app, const std::vector<std::string>& args, std::FILE* out);

}  // namespace petersen::cli
