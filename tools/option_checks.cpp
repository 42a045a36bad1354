#include "option_checks.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>

namespace petersen::cli {

namespace {

// The number as written in the message: "12.5", not "12.500000".
std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

}  // namespace

CLI::Validator finite_in(double low, double high) {
  const std::string range = "[" + number_text(low) + ", " + number_text(high) + "]";
  return CLI::Validator(
      [low, high, range](std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (end == text.c_str() || *end != '\0') return "not a number: " + text;
        if (!(std::isfinite(value) && value >= low && value <= high)) {
          return "must be a finite number in " + range + ", not " + text;
        }
        return {};
      },
      "FLOAT in " + range);
}

CLI::Validator in_existing_folder() {
  return CLI::Validator(
      [](std::string& path) -> std::string {
        const std::filesystem::path folder = std::filesystem::path(path).parent_path();
        std::error_code error;
        if (folder.empty() || std::filesystem::is_directory(folder, error)) return {};
        return "no such folder to write into: " + folder.string();
      },
      "");
}

CLI::Validator one_of(std::vector<std::string> names, std::string note) {
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
  auto lower = [](std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return text;
  };
  return CLI::Validator(
      [names, list, note, lower](std::string& text) -> std::string {
        for (const std::string& name : names) {
          if (lower(name) == lower(text)) {
            text = name;
            return {};
          }
        }
        return "unknown value " + text + ": one of " + list + note;
      },
      "{" + list + "}");
}

}  // namespace petersen::cli
