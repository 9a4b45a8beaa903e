// The knots and cut tails an attempt's events report, as the rubrics weigh them: which knots
// lock, a slip taking the security away from the knot it follows, cuts that leave a tail on a
// stitch against trimming loose thread, and the same through computeMetrics and a shipped rubric.
#include "microsim/assessment/scoring/knot_metrics.h"
#include "microsim/assessment/scoring/metrics.h"
#include "microsim/assessment/scoring/rubric.h"
#include "microsim/assessment/scoring/score.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <variant>
#include <vector>

namespace microsim::assessment {
namespace {

using K = sim::SceneEventKind;
using sim::suture::KnotType;

sim::SceneEvent knotTightened(KnotType type, int throws) {
  sim::SceneEvent e;
  e.kind = K::KnotTightened;
  e.count = throws;
  e.value = 900.0;
  e.knot.type = type;
  return e;
}

sim::SceneEvent knotSlipped() {
  sim::SceneEvent e;
  e.kind = K::KnotSlipped;
  e.count = 1;
  return e;
}

sim::SceneEvent threadCut(double cutEndMm) {
  sim::SceneEvent e;
  e.kind = K::ThreadCut;
  e.hand = 1;
  e.value = cutEndMm;
  return e;
}

TEST(KnotMetrics, SquareAndSurgeonsKnotsLockAndTheOthersDoNot) {
  EXPECT_TRUE(knotTypeLocks(KnotType::Square));
  EXPECT_TRUE(knotTypeLocks(KnotType::Surgeons));
  for (KnotType t : {KnotType::None, KnotType::SingleThrow, KnotType::Granny, KnotType::SlipKnot,
                     KnotType::Unknown})
    EXPECT_FALSE(knotTypeLocks(t));
}

TEST(KnotMetrics, AnAttemptWithoutKnotsOrCutsHasNoThrowsAndNoCutEnd) {
  const KnotSummary s = knotSummary({});
  EXPECT_EQ(s.tightened, 0);
  EXPECT_EQ(s.secure, 0);
  EXPECT_EQ(s.slipped, 0);
  EXPECT_EQ(s.cuts, 0);
  EXPECT_TRUE(std::isnan(s.meanThrows));
  EXPECT_TRUE(std::isnan(s.meanCutEndMm));
  EXPECT_TRUE(std::isnan(s.longestCutEndMm));
}

TEST(KnotMetrics, ASlipTakesTheSecurityOfTheKnotItFollows) {
  // a surgeon's knot that holds, a granny that slips, a square knot that slips, a square
  // knot of one throw (it cannot lock), a surgeon's knot tightened last that holds
  const KnotSummary s =
      knotSummary({knotTightened(KnotType::Surgeons, 2), knotTightened(KnotType::Granny, 2), knotSlipped(),
                   knotTightened(KnotType::Square, 2), knotSlipped(), knotTightened(KnotType::Square, 1),
                   knotTightened(KnotType::Surgeons, 3)});
  EXPECT_EQ(s.tightened, 5);
  EXPECT_EQ(s.secure, 2);
  EXPECT_EQ(s.slipped, 2);
  EXPECT_DOUBLE_EQ(s.meanThrows, (2.0 + 2.0 + 2.0 + 1.0 + 3.0) / 5.0);
}

TEST(KnotMetrics, OnlyCutsThatLeaveATailOnAStitchAreCutEnds) {
  const KnotSummary s = knotSummary({threadCut(0.8), threadCut(-1.0), threadCut(1.6)});
  EXPECT_EQ(s.cuts, 2);
  EXPECT_DOUBLE_EQ(s.meanCutEndMm, 1.2);
  EXPECT_DOUBLE_EQ(s.longestCutEndMm, 1.6);
}

Rubric knotLessonRubric(const std::string& lesson) {
  const auto loaded =
      loadRubric(std::string(MICROSIM_SOURCE_DIR) + "/resources/rubrics/" + lesson + ".json");
  EXPECT_TRUE(std::holds_alternative<Rubric>(loaded));
  return std::holds_alternative<Rubric>(loaded) ? std::get<Rubric>(loaded) : Rubric{};
}

bool knotFeedbackGiven(const AttemptScore& score, const std::string& key) {
  for (const MetricScore& m : score.metrics)
    if (m.feedback == key) return true;
  for (const std::string& f : score.neverEvents)
    if (f == key) return true;
  return false;
}

TEST(KnotMetrics, LessonThreeWeighsTheKnotAndTheTails) {
  Attempt tied;
  tied.events = {knotTightened(KnotType::Surgeons, 2), threadCut(1.1), threadCut(0.9)};
  Attempt granny = tied;
  granny.events = {knotTightened(KnotType::Granny, 2), knotSlipped(), threadCut(1.1), threadCut(0.9)};
  Attempt untied;

  const AttemptMetrics m = computeMetrics(tied);
  EXPECT_EQ(m.value("knots_tied"), 1.0);
  EXPECT_EQ(m.value("secure_knots"), 1.0);
  EXPECT_EQ(m.value("knots_slipped"), 0.0);
  EXPECT_EQ(m.value("knot_throws"), 2.0);
  EXPECT_EQ(m.value("thread_cuts"), 2.0);
  EXPECT_DOUBLE_EQ(*m.value("cut_end_length"), 1.0);

  const Rubric rubric = knotLessonRubric("03_single_stitch");
  const AttemptScore good = scoreAttempt(tied, rubric);
  const AttemptScore slip = scoreAttempt(granny, rubric);
  const AttemptScore none = scoreAttempt(untied, rubric);
  for (const char* key : {"knot.not_tied", "knot.not_secure", "cut.not_done", "cut_end.too_long",
                          "cut_end.too_short"})
    EXPECT_FALSE(knotFeedbackGiven(good, key)) << key;
  // the granny slipped: a never-event caps the attempt, and it is not a secure knot
  EXPECT_TRUE(knotFeedbackGiven(slip, "never.knot_slipped"));
  EXPECT_TRUE(knotFeedbackGiven(slip, "knot.not_secure"));
  EXPECT_LE(slip.score, 50.0);
  EXPECT_TRUE(knotFeedbackGiven(none, "knot.not_tied"));
  EXPECT_TRUE(knotFeedbackGiven(none, "cut.not_done"));
  EXPECT_FALSE(knotFeedbackGiven(none, "never.knot_slipped"));
  EXPECT_GT(good.score, none.score);
}

}  // namespace
}  // namespace microsim::assessment
