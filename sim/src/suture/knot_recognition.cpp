#include "microsim/sim/suture/knot_recognition.h"

#include "microsim/sim/suture/knot_simplify.h"

#include <algorithm>
#include <cmath>

namespace microsim::sim::suture {

namespace {

// a crossing taken out of the word as part of a throw or block, with its two passages
struct TakenCrossing {
  int sign = 0;
  bool firstOver = false;  // the earlier passage (in curve order) is on top
  double firstAt = 0.0;
  double secondAt = 0.0;
};

// the point at curve parameter s (clamped to the thread: the extensions are not thread)
Vec3 knotPointAt(const Points& x, double s) {
  const double last = static_cast<double>(x.cols() - 1);
  s = std::clamp(s, 0.0, last);
  const auto i = static_cast<Eigen::Index>(std::min(std::floor(s), last - 1.0));
  const double t = s - static_cast<double>(i);
  return (1.0 - t) * x.col(i) + t * x.col(i + 1);
}

// chord / arc of the thread between parameters a ≤ b (1 for a straight stretch)
double knotStraightness(const Points& x, double a, double b) {
  const double last = static_cast<double>(x.cols() - 1);
  a = std::clamp(a, 0.0, last);
  b = std::clamp(b, 0.0, last);
  if (b <= a) {
    return 1.0;
  }
  double arc = 0.0;
  Vec3 previous = knotPointAt(x, a);
  for (auto i = static_cast<Eigen::Index>(std::floor(a)) + 1; static_cast<double>(i) < b; ++i) {
    const Vec3 p = x.col(i);
    arc += (p - previous).norm();
    previous = p;
  }
  const Vec3 end = knotPointAt(x, b);
  arc += (end - previous).norm();
  return arc > 0.0 ? (end - knotPointAt(x, a)).norm() / arc : 1.0;
}

// one strand straight through the crossings, the other wound round it
bool isHitch(const Points& x, const std::vector<TakenCrossing>& taken, const KnotRecognitionDef& def) {
  double firstLow = 1e300;
  double firstHigh = -1e300;
  double secondLow = 1e300;
  double secondHigh = -1e300;
  for (const TakenCrossing& t : taken) {
    firstLow = std::min(firstLow, t.firstAt);
    firstHigh = std::max(firstHigh, t.firstAt);
    secondLow = std::min(secondLow, t.secondAt);
    secondHigh = std::max(secondHigh, t.secondAt);
  }
  // the two stretches may overlap in a block; then there are not two strands to compare
  if (firstHigh >= secondLow) {
    return false;
  }
  const double pad = def.shapePadding;
  const double first = knotStraightness(x, firstLow - pad, firstHigh + pad);
  const double second = knotStraightness(x, secondLow - pad, secondHigh + pad);
  return (first >= def.straightness && second <= def.wrapped) ||
         (second >= def.straightness && first <= def.wrapped);
}

KnotThrow makeThrow(ThrowForm form, const std::vector<TakenCrossing>& taken, int wraps) {
  KnotThrow t;
  t.form = form;
  t.handedness = taken.front().sign > 0 ? Handedness::Right : Handedness::Left;
  t.wraps = wraps;
  t.crossings = static_cast<int>(taken.size());
  double sum = 0.0;
  t.first = taken.front().firstAt;
  t.last = taken.front().secondAt;
  for (const TakenCrossing& c : taken) {
    sum += c.firstAt + c.secondAt;
    t.first = std::min({t.first, c.firstAt, c.secondAt});
    t.last = std::max({t.last, c.firstAt, c.secondAt});
  }
  t.position = sum / (2.0 * static_cast<double>(taken.size()));
  return t;
}

bool oneSignByTurns(const std::vector<TakenCrossing>& taken) {
  for (std::size_t k = 1; k < taken.size(); ++k) {
    if (taken[k].sign != taken[0].sign || taken[k].firstOver == taken[k - 1].firstOver) {
      return false;
    }
  }
  return true;
}

// over and under by turns along the block's own passages (the overhand's alternation)
bool alternatesAlongWord(const std::vector<GaussEntry>& block) {
  for (std::size_t k = 1; k < block.size(); ++k) {
    if (block[k].over == block[k - 1].over) {
      return false;
    }
  }
  return true;
}

KnotType nameKnot(const std::vector<KnotThrow>& throws, int unexplained) {
  if (unexplained > 0) {
    return KnotType::Unknown;
  }
  if (throws.empty()) {
    return KnotType::None;
  }
  if (std::any_of(throws.begin(), throws.end(),
                  [](const KnotThrow& t) { return t.form == ThrowForm::Hitch; })) {
    return KnotType::SlipKnot;
  }
  if (throws.size() == 1) {
    return KnotType::SingleThrow;
  }
  for (std::size_t k = 1; k < throws.size(); ++k) {
    if (throws[k].handedness == throws[k - 1].handedness) {
      return KnotType::Granny;
    }
  }
  const auto doubles = std::count_if(throws.begin(), throws.end(),
                                     [](const KnotThrow& t) { return t.wraps == 2; });
  const auto singles = std::count_if(throws.begin(), throws.end(),
                                     [](const KnotThrow& t) { return t.wraps == 1; });
  const auto all = static_cast<std::ptrdiff_t>(throws.size());
  if (singles == all) {
    return KnotType::Square;
  }
  if (doubles == 1 && singles == all - 1 && (throws.front().wraps == 2 || throws.back().wraps == 2)) {
    return KnotType::Surgeons;
  }
  return KnotType::Unknown;
}

}  // namespace

KnotReading readKnotDiagram(const Points& x, const KnotDiagram& diagram, const KnotRecognitionDef& def) {
  KnotReading reading;
  reading.direction = diagram.direction;
  reading.quality = diagram.quality;
  reading.rawCrossings = static_cast<int>(diagram.crossings.size());

  // the stitch: drop crossings with the stretch held in the tissue, keep its ends as anchors
  std::vector<GaussEntry> word = diagram.word;
  double anchorLow = 1e300;
  double anchorHigh = -1e300;
  for (const GaussEntry& e : word) {
    if (e.crossing < 0) {
      anchorLow = std::min(anchorLow, e.at);
      anchorHigh = std::max(anchorHigh, e.at);
    }
  }
  const bool anchored = anchorLow <= anchorHigh;
  if (anchored) {
    std::vector<std::uint8_t> held(diagram.crossings.size(), 0);
    for (const GaussEntry& e : word) {
      if (e.crossing >= 0 && e.at > anchorLow && e.at < anchorHigh) {
        held[static_cast<std::size_t>(e.crossing)] = 1;
      }
    }
    std::erase_if(word, [&](const GaussEntry& e) {
      return e.crossing >= 0 ? held[static_cast<std::size_t>(e.crossing)] != 0
                             : (e.at != anchorLow && e.at != anchorHigh);
    });
  }
  simplifyGaussWord(word, diagram.crossings);
  reading.crossings = crossingCount(word);
  if (reading.crossings > def.maxCrossings) {
    reading.unexplained = reading.crossings;
    reading.type = KnotType::Unknown;
    return reading;
  }

  std::vector<TakenCrossing> twists;
  std::vector<std::uint8_t> taken(word.size(), 0);
  const auto passagesOf = [&](int crossing, std::size_t& i, std::size_t& j) {
    bool found = false;
    for (std::size_t k = 0; k < word.size(); ++k) {
      if (word[k].crossing == crossing) {
        (found ? j : i) = k;
        if (found) {
          return;
        }
        found = true;
      }
    }
  };
  const auto takeCrossing = [&](std::size_t i, std::size_t j) {
    const GaussEntry& a = word[i];
    TakenCrossing t;
    t.sign = diagram.crossings[static_cast<std::size_t>(a.crossing)].sign;
    t.firstOver = a.over;
    t.firstAt = a.at;
    t.secondAt = word[j].at;
    taken[i] = 1;
    taken[j] = 1;
    return t;
  };

  // half twists round the stitch, innermost first
  if (anchored) {
    for (bool found = true; found;) {
      found = false;
      std::size_t bestI = 0;
      std::size_t bestJ = 0;
      for (std::size_t i = 0; i < word.size(); ++i) {
        if (taken[i] || word[i].crossing < 0) {
          continue;
        }
        std::size_t a = 0;
        std::size_t b = 0;
        passagesOf(word[i].crossing, a, b);
        if (a != i) {
          continue;
        }
        bool onlyAnchors = true;
        bool enclosesAnchor = false;
        for (std::size_t k = a + 1; k < b && onlyAnchors; ++k) {
          enclosesAnchor = enclosesAnchor || word[k].crossing < 0;
          onlyAnchors = taken[k] || word[k].crossing < 0;
        }
        if (onlyAnchors && enclosesAnchor && (!found || b - a < bestJ - bestI)) {
          found = true;
          bestI = a;
          bestJ = b;
        }
      }
      if (found) {
        twists.push_back(takeCrossing(bestI, bestJ));
      }
    }
  }

  // half twists of one sign, over and under by turns, make one throw
  std::vector<KnotThrow> throws;
  for (std::size_t k = 0; k < twists.size();) {
    std::size_t end = k + 1;
    while (end < twists.size() && twists[end].sign == twists[k].sign &&
           twists[end].firstOver != twists[end - 1].firstOver) {
      ++end;
    }
    const std::vector<TakenCrossing> run(twists.begin() + static_cast<std::ptrdiff_t>(k),
                                         twists.begin() + static_cast<std::ptrdiff_t>(end));
    if (run.size() >= 2) {
      const ThrowForm form = isHitch(x, run, def) ? ThrowForm::Hitch : ThrowForm::Twist;
      throws.push_back(makeThrow(form, run, static_cast<int>(run.size() / 2)));
    }
    k = end;
  }

  // what is left: the shortest closed stretches of the word, one by one
  std::vector<KnotThrow> blocks;
  for (;;) {
    std::vector<std::size_t> open;
    for (std::size_t k = 0; k < word.size(); ++k) {
      if (!taken[k] && word[k].crossing >= 0) {
        open.push_back(k);
      }
    }
    if (open.empty()) {
      break;
    }
    // for each passage, the index (in `open`) of its partner
    std::vector<std::size_t> partner(open.size(), 0);
    for (std::size_t k = 0; k < open.size(); ++k) {
      for (std::size_t l = 0; l < open.size(); ++l) {
        if (l != k && word[open[l]].crossing == word[open[k]].crossing) {
          partner[k] = l;
        }
      }
    }
    std::size_t bestFrom = 0;
    std::size_t bestTo = open.size() - 1;
    for (std::size_t from = 0; from < open.size(); ++from) {
      std::size_t to = partner[from];
      if (to < from) {
        continue;
      }
      bool closed = true;
      for (std::size_t k = from + 1; k < to && closed; ++k) {
        closed = partner[k] >= from;
        to = std::max(to, partner[k]);
      }
      if (closed && to - from < bestTo - bestFrom) {
        bestFrom = from;
        bestTo = to;
      }
    }
    std::vector<GaussEntry> block;
    std::vector<TakenCrossing> crossingsOfBlock;
    for (std::size_t k = bestFrom; k <= bestTo; ++k) {
      block.push_back(word[open[k]]);
      if (partner[k] > k) {
        crossingsOfBlock.push_back(takeCrossing(open[k], open[partner[k]]));
      }
    }
    const auto n = static_cast<int>(crossingsOfBlock.size());
    const bool oneSign = std::all_of(crossingsOfBlock.begin(), crossingsOfBlock.end(),
                                     [&](const TakenCrossing& t) { return t.sign == crossingsOfBlock[0].sign; });
    if (n >= 3 && n % 2 == 1 && oneSign && alternatesAlongWord(block)) {
      blocks.push_back(makeThrow(ThrowForm::Overhand, crossingsOfBlock, (n - 1) / 2));
    } else if (n >= 2 && oneSignByTurns(crossingsOfBlock) && isHitch(x, crossingsOfBlock, def)) {
      blocks.push_back(makeThrow(ThrowForm::Hitch, crossingsOfBlock, n / 2));
    } else {
      reading.unexplained += n;
    }
  }

  // blocks nearest the stitch first, else along the thread
  const double centre = anchored ? 0.5 * (anchorLow + anchorHigh) : 0.0;
  std::stable_sort(blocks.begin(), blocks.end(), [&](const KnotThrow& l, const KnotThrow& r) {
    return std::abs(l.position - centre) < std::abs(r.position - centre);
  });
  throws.insert(throws.end(), blocks.begin(), blocks.end());
  reading.throws = std::move(throws);
  reading.type = nameKnot(reading.throws, reading.unexplained);
  return reading;
}

bool sameKnotReading(const KnotReading& a, const KnotReading& b) {
  if (a.type != b.type || a.throws.size() != b.throws.size()) {
    return false;
  }
  for (std::size_t k = 0; k < a.throws.size(); ++k) {
    const KnotThrow& s = a.throws[k];
    const KnotThrow& t = b.throws[k];
    if (s.form != t.form || s.handedness != t.handedness || s.wraps != t.wraps) {
      return false;
    }
  }
  return true;
}

KnotReading recogniseKnot(const Points& x, std::span<const int> anchors,
                          const KnotRecognitionDef& def, const Vec3* hint) {
  // a clear picture from the last reading's direction needs no search
  if (hint != nullptr) {
    const KnotDiagram diagram = projectKnot(x, anchors, *hint);
    if (diagram.quality >= def.clearQuality && diagram.closureCrossings == 0) {
      return readKnotDiagram(x, diagram, def);
    }
  }
  const std::vector<Vec3> directions = def.directions.empty() ? knotViewDirections(x) : def.directions;
  std::vector<KnotReading> clear;
  KnotReading clearest;
  double clearestScore = -1e300;
  for (const Vec3& d : directions) {
    const KnotDiagram diagram = projectKnot(x, anchors, d);
    KnotReading reading = readKnotDiagram(x, diagram, def);
    if (diagram.quality >= def.clearQuality && diagram.closureCrossings == 0) {
      clear.push_back(reading);
    }
    const double score = diagram.quality - (diagram.closureCrossings > 0 ? 0.5 : 0.0);
    if (score > clearestScore) {
      clearestScore = score;
      clearest = std::move(reading);
    }
  }
  if (clear.empty()) {
    return clearest;  // no clear picture: the least unclear one
  }
  // a picture RI and RII could not clear (it needs RIII) says less than one they could: where
  // some pictures are fully explained, only they vote
  if (std::any_of(clear.begin(), clear.end(), [](const KnotReading& r) { return r.unexplained == 0; })) {
    std::erase_if(clear, [](const KnotReading& r) { return r.unexplained > 0; });
  }
  // the clear pictures vote: a twist's half turns and the tails' crossings depend on where one
  // looks from, the knot the most of them show does not; ties go to the clearer picture
  std::size_t winner = 0;
  int winnerVotes = 0;
  for (std::size_t k = 0; k < clear.size(); ++k) {
    const auto votes = static_cast<int>(std::count_if(clear.begin(), clear.end(), [&](const KnotReading& r) {
      return sameKnotReading(r, clear[k]);
    }));
    if (votes > winnerVotes || (votes == winnerVotes && clear[k].quality > clear[winner].quality)) {
      winner = k;
      winnerVotes = votes;
    }
  }
  return clear[winner];
}

}  // namespace microsim::sim::suture
