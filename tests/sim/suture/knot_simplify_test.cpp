#include "microsim/sim/suture/knot_simplify.h"

#include <gtest/gtest.h>

#include <string>

namespace microsim::sim::suture {
namespace {

// a Gauss word from text: "1o 2u A ..." = crossing 1 over, crossing 2 under, an anchor
struct Word {
  std::vector<GaussEntry> entries;
  std::vector<KnotCrossing> crossings;
};

Word wordOf(const std::string& text, const std::vector<int>& signs) {
  Word w;
  w.crossings.resize(signs.size());
  for (std::size_t k = 0; k < signs.size(); ++k) {
    w.crossings[k].sign = signs[k];
  }
  double at = 0.0;
  for (std::size_t k = 0; k < text.size();) {
    if (text[k] == ' ') {
      ++k;
      continue;
    }
    if (text[k] == 'A') {
      w.entries.push_back({-1, false, at});
      ++k;
    } else {
      const int c = text[k] - '1';
      w.entries.push_back({c, text[k + 1] == 'o', at});
      k += 2;
    }
    at += 1.0;
  }
  return w;
}

TEST(KnotSimplify, KinkGoes) {
  Word w = wordOf("1o 1u", {1});
  const ReidemeisterCount n = simplifyGaussWord(w.entries, w.crossings);
  EXPECT_EQ(n.kinks, 1);
  EXPECT_TRUE(w.entries.empty());
}

TEST(KnotSimplify, NestedKinksGoOneByOne) {
  Word w = wordOf("1o 2o 3u 3o 2u 1u", {1, -1, 1});
  const ReidemeisterCount n = simplifyGaussWord(w.entries, w.crossings);
  EXPECT_EQ(n.kinks, 3);
  EXPECT_EQ(crossingCount(w.entries), 0);
}

TEST(KnotSimplify, TheEndsAreHeld) {
  // two strands twisted about the stitch: the first and last passages are not neighbours
  Word twist = wordOf("2o 1u A 1o 2u", {1, 1});
  simplifyGaussWord(twist.entries, twist.crossings);
  EXPECT_EQ(crossingCount(twist.entries), 2);
}

TEST(KnotSimplify, OverlayGoesButAClaspStays) {
  // a strand lying over another: both crossings over, then both under, opposite signs
  Word lying = wordOf("1o 2o 1u 2u", {1, -1});
  const ReidemeisterCount n = simplifyGaussWord(lying.entries, lying.crossings);
  EXPECT_EQ(n.overlays + n.kinks, 1);
  EXPECT_EQ(crossingCount(lying.entries), 0);

  // a clasp, over then under, round an anchor: nothing slides off
  Word clasp = wordOf("1o 2u A 1u 2o", {1, 1});
  simplifyGaussWord(clasp.entries, clasp.crossings);
  EXPECT_EQ(crossingCount(clasp.entries), 2);
}

TEST(KnotSimplify, TrefoilStays) {
  Word w = wordOf("1o 2u 3o 1u 2o 3u", {1, 1, 1});
  const ReidemeisterCount n = simplifyGaussWord(w.entries, w.crossings);
  EXPECT_EQ(n.kinks + n.overlays, 0);
  EXPECT_EQ(crossingCount(w.entries), 3);
}

TEST(KnotSimplify, AnchorKeepsALoopRoundTheStitch) {
  Word w = wordOf("1o A 1u", {1});
  simplifyGaussWord(w.entries, w.crossings);
  EXPECT_EQ(crossingCount(w.entries), 1);
  // the same loop without the anchor untwists
  Word loose = wordOf("1o 1u", {1});
  simplifyGaussWord(loose.entries, loose.crossings);
  EXPECT_EQ(crossingCount(loose.entries), 0);
}

}  // namespace
}  // namespace microsim::sim::suture
