// The cut step (partition.hpp): the open edges of all parts merged by vertex pair.

#include <algorithm>

#include "petersen/partition/partition.hpp"

namespace petersen {

namespace {

// A record whose triangle may not be paired across its edge: pair_part gives a degenerate
// triangle's record one of the edge's ends as its apex.
bool unpairable(const OpenEdge& r) {
  return r.apex == r.low || r.apex == r.high;
}

}  // namespace

CutPairing pair_open_edges(std::vector<OpenEdge> records) {
  std::sort(records.begin(), records.end(), [](const OpenEdge& x, const OpenEdge& y) {
    return x.low != y.low ? x.low < y.low : x.high != y.high ? x.high < y.high : x.face < y.face;
  });
  CutPairing cut;
  for (std::size_t i = 0, j; i < records.size(); i = j) {
    for (j = i + 1; j < records.size() && records[j].low == records[i].low &&
                    records[j].high == records[i].high;
         ++j) {
    }
    if (j - i == 1) {
      ++cut.boundary_edges;
    } else if (j - i > 2) {
      ++cut.non_manifold_edges;
    } else if (records[i].apex == records[i + 1].apex || unpairable(records[i]) ||
               unpairable(records[i + 1])) {
      ++cut.duplicate_edges;
    } else {
      cut.adjacencies.push_back(
          {records[i].face, records[i + 1].face, records[i].low, records[i].high});
    }
  }
  std::sort(cut.adjacencies.begin(), cut.adjacencies.end(),
            [](const CutAdjacency& x, const CutAdjacency& y) {
              return x.first != y.first ? x.first < y.first : x.second < y.second;
            });
  return cut;
}

}  // namespace petersen
