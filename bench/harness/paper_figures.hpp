#pragma once
// The paper's own figures (§4, Tables 4.2 and 4.4), printed beside ours; never used as results.

#include <cstdint>
#include <optional>
#include <string_view>

namespace petersen::bench {

/// A row of the paper's Table 4.2: the Euler characteristics of a member of family A or B.
struct PaperMesh {
  std::string_view name;
  std::uint64_t vertices, edges, triangles, genus;
};

inline constexpr PaperMesh kPaperTable42[] = {
    {"A1", 2'097'150, 6'291'444, 4'194'296, 0},  {"A2", 991'416, 2'974'242, 1'982'828, 0},
    {"A3", 745'697, 2'237'085, 1'491'390, 0},    {"A4", 418'073, 1'254'213, 836'142, 0},
    {"A5", 172'354, 517'056, 344'704, 0},        {"B1", 2'104'150, 6'333'444, 4'222'296, 3500},
    {"B2", 994'979, 3'005'931, 2'003'954, 3500}, {"B3", 748'496, 2'266'482, 1'510'988, 3500},
    {"B4", 419'852, 1'280'550, 853'700, 3500},   {"B5", 173'370, 541'104, 360'736, 3500},
};

/// A row of the paper's Table 4.4: columns (a)–(e) for PS (mean of ten runs) or LRS (one run),
/// on a 2.4 GHz Core 2 Duo (2014).
struct PaperRun {
  std::string_view mesh, algorithm;
  double initial_seconds, paired_percent, unpaired, augment_seconds, total_seconds;
};

inline constexpr PaperRun kPaperTable44[] = {
    {"A1", "PS", 5.91165300, 99.9968, 136.0, 7.19208100, 13.10373400},
    {"A1", "LRS", 11.98554000, 99.9999, 4.0, 0.19302800, 12.17856800},
    {"A2", "PS", 2.78087300, 99.9987, 621.2, 14.66607000, 17.44694300},
    {"A2", "LRS", 5.74721000, 99.9998, 4.0, 0.08340600, 5.83061600},
    {"A3", "PS", 2.04989300, 99.9532, 697.6, 12.00453700, 14.05443000},
    {"A3", "LRS", 4.42929000, 99.9997, 4.0, 0.06262800, 4.49191800},
    {"A4", "PS", 1.12364900, 99.9124, 732.8, 7.17269700, 8.29634600},
    {"A4", "LRS", 2.38205500, 99.9995, 4.0, 0.03486000, 2.41691500},
    {"A5", "PS", 0.46565590, 99.7887, 728.4, 3.80944600, 4.275101900},
    {"A5", "LRS", 0.89576500, 99.9988, 4.0, 0.01407000, 0.90983500},
    {"B1", "PS", 5.85876900, 99.9944, 238.0, 14.53781100, 20.39658000},
    {"B1", "LRS", 14.41705000, 99.0842, 38'668.0, 1'380.94000000, 1'395.35705000},
    {"B2", "PS", 2.71100000, 99.9727, 547.8, 9.80479000, 12.51579000},
    {"B2", "LRS", 7.71557000, 98.1895, 36'282.0, 690.56300000, 698.27857000},
    {"B3", "PS", 2.04157000, 99.9710, 438.8, 7.20557700, 9.24714700},
    {"B3", "LRS", 5.90831000, 97.6365, 35'712.0, 541.48100000, 547.38931000},
    {"B4", "PS", 1.14761700, 99.9476, 447.4, 4.03661000, 5.18422700},
    {"B4", "LRS", 3.54605400, 95.9082, 34'932.0, 350.78800000, 354.33405400},
    {"B5", "PS", 0.48588230, 99.8876, 405.4, 2.06146300, 2.54734530},
    {"B5", "LRS", 1.85803100, 90.4856, 34'322.0, 208.72100000, 210.57903100},
};

/// The paper's Table 4.2 row of a family member, if `name` is one (A1…A5, B1…B5).
inline std::optional<PaperMesh> paper_mesh(std::string_view name) {
  for (const PaperMesh& row : kPaperTable42)
    if (row.name == name) return row;
  return std::nullopt;
}

/// The paper's Table 4.4 row for a member and algorithm ("PS" or "LRS"), if it has one.
inline std::optional<PaperRun> paper_run(std::string_view mesh, std::string_view algorithm) {
  for (const PaperRun& row : kPaperTable44)
    if (row.mesh == mesh && row.algorithm == algorithm) return row;
  return std::nullopt;
}

}  // namespace petersen::bench
