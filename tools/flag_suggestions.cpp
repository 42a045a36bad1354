#include "flag_suggestions.hpp"

#include <algorithm>
#include <string>
#include <vector>

namespace petersen::cli {

namespace {

// Edit distance counting a swap of two neighbours as one edit ("qaud" is 1 from "quad"): the
// optimal string alignment distance, O(|a|·|b|) on names of a few letters.
std::size_t edit_distance(const std::string& a, const std::string& b) {
  const std::size_t w = b.size() + 1;
  std::vector<std::size_t> d((a.size() + 1) * w);
  for (std::size_t i = 0; i <= a.size(); ++i) d[i * w] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      d[i * w + j] = std::min({d[(i - 1) * w + j] + 1, d[i * w + j - 1] + 1,
                               d[(i - 1) * w + j - 1] + (a[i - 1] != b[j - 1])});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        d[i * w + j] = std::min(d[i * w + j], d[(i - 2) * w + j - 2] + 1);
      }
    }
  }
  return d.back();
}

// The names within a third of the typed word's length (at least 1) of it, closest first, or
// those it is the start of ("--all" for "--all-quad").
std::vector<std::string> closest(const std::string& typed, const std::vector<std::string>& names) {
  const std::size_t limit = std::max<std::size_t>(1, typed.size() / 3);
  std::vector<std::pair<std::size_t, std::string>> near;
  for (const std::string& name : names) {
    const std::size_t d = edit_distance(typed, name);
    if (d <= limit || (typed.size() >= 3 && name.rfind(typed, 0) == 0)) near.emplace_back(d, name);
  }
  std::stable_sort(near.begin(), near.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<std::string> out;
  for (const auto& item : near) out.push_back(item.second);
  return out;
}

void suggest(const std::string& typed, const std::vector<std::string>& names, const char* what,
             std::FILE* out) {
  const std::vector<std::string> near = closest(typed, names);
  if (near.empty()) return;
  std::string list;
  for (std::size_t i = 0; i < near.size() && i < 3; ++i) {
    list += (i == 0                                           ? ""
             : i + 1 == std::min<std::size_t>(near.size(), 3) ? " or "
                                                              : ", ") +
            near[i];
  }
  std::fprintf(out, "petersen: %s is no %s; did you mean %s?\n", typed.c_str(), what, list.c_str());
}

std::vector<std::string> flag_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* option : app.get_options()) {
    for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
  }
  return names;
}

}  // namespace

void print_suggestions(const CLI::App& app, const std::vector<std::string>& args, std::FILE* out) {
  const CLI::App* given = nullptr;
  for (const CLI::App* sub : app.get_subcommands({})) {
    if (sub->parsed()) given = sub;
  }
  if (given == nullptr) {  // the first word was meant as a subcommand
    std::vector<std::string> subcommands;
    for (const CLI::App* sub : app.get_subcommands({})) subcommands.push_back(sub->get_name());
    for (const std::string& arg : args) {
      if (arg.rfind('-', 0) == 0) continue;
      suggest(arg, subcommands, "subcommand", out);
      break;
    }
    return;
  }
  const std::vector<std::string> flags = flag_names(*given);
  for (const std::string& arg : given->remaining()) {
    if (arg.rfind("--", 0) == 0) suggest(arg.substr(0, arg.find('=')), flags, "flag", out);
  }
}

}  // namespace petersen::cli
