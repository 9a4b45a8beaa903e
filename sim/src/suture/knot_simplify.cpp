#include "microsim/sim/suture/knot_simplify.h"

#include <algorithm>

namespace microsim::sim::suture {

namespace {

// for each crossing, the positions of its two passages in the word (−1 when gone)
void locatePassages(const std::vector<GaussEntry>& word, std::size_t crossings,
                    std::vector<int>& first, std::vector<int>& second) {
  first.assign(crossings, -1);
  second.assign(crossings, -1);
  for (std::size_t k = 0; k < word.size(); ++k) {
    const int c = word[k].crossing;
    if (c < 0) {
      continue;
    }
    auto& slot = first[static_cast<std::size_t>(c)] < 0 ? first : second;
    slot[static_cast<std::size_t>(c)] = static_cast<int>(k);
  }
}

// two word positions that follow one another (never across the held ends)
bool consecutivePassages(int a, int b) { return a + 1 == b || b + 1 == a; }

void eraseCrossings(std::vector<GaussEntry>& word, int c1, int c2) {
  std::erase_if(word, [&](const GaussEntry& e) {
    return e.crossing >= 0 && (e.crossing == c1 || e.crossing == c2);
  });
}

}  // namespace

ReidemeisterCount simplifyGaussWord(std::vector<GaussEntry>& word,
                                    const std::vector<KnotCrossing>& crossings) {
  ReidemeisterCount count;
  std::vector<int> first;
  std::vector<int> second;
  bool moved = true;
  while (moved && word.size() >= 2) {
    moved = false;
    locatePassages(word, crossings.size(), first, second);

    // RI: a crossing passed twice in a row
    for (std::size_t c = 0; c < crossings.size(); ++c) {
      if (first[c] >= 0 && second[c] >= 0 && consecutivePassages(first[c], second[c])) {
        eraseCrossings(word, static_cast<int>(c), static_cast<int>(c));
        ++count.kinks;
        moved = true;
        break;
      }
    }
    if (moved) {
      continue;
    }

    // RII: two crossings passed together twice, on top both times or below both times
    const std::size_t n = word.size();
    for (std::size_t k = 0; k + 1 < n && !moved; ++k) {
      const GaussEntry& a = word[k];
      const GaussEntry& b = word[k + 1];
      if (a.crossing < 0 || b.crossing < 0 || a.crossing == b.crossing || a.over != b.over) {
        continue;
      }
      const auto ca = static_cast<std::size_t>(a.crossing);
      const auto cb = static_cast<std::size_t>(b.crossing);
      if (crossings[ca].sign == crossings[cb].sign) {
        continue;
      }
      const int otherA = first[ca] == static_cast<int>(k) ? second[ca] : first[ca];
      const int otherB = first[cb] == static_cast<int>(k + 1) ? second[cb] : first[cb];
      if (otherA >= 0 && otherB >= 0 && consecutivePassages(otherA, otherB)) {
        eraseCrossings(word, a.crossing, b.crossing);
        ++count.overlays;
        moved = true;
      }
    }
  }
  return count;
}

int crossingCount(const std::vector<GaussEntry>& word) {
  return static_cast<int>(std::count_if(word.begin(), word.end(),
                                        [](const GaussEntry& e) { return e.crossing >= 0; })) /
         2;
}

}  // namespace microsim::sim::suture
