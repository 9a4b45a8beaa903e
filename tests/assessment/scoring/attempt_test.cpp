// Attempts: motion samples follow the frames the scene used (rejected frames repeat the last
// good one, lost hands hold still), the vessels' angle frame is shared by both ends, and
// the shipped stitch recording replays to the same pinned score every run, truncated or not.
#include "support/golden_stitch.h"

#include "microsim/assessment/scoring/attempt.h"
#include "microsim/assessment/scoring/rubric.h"
#include "microsim/assessment/scoring/score.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using namespace microsim::assessment;
namespace sim = microsim::sim;

const std::string kRoot = MICROSIM_SOURCE_DIR;
const std::string kScene = kRoot + "/resources/scenes/anastomosis.json";
const std::string kStitch = kRoot + "/resources/recordings/stitch.msrec";
const std::string kRubric = kRoot + "/resources/rubrics/03_single_stitch.json";
// microsim-cli score prints the same (tests/app/cli/score_command_test.cpp)
constexpr double kStitchScore = microsim::testing::kGoldenStitchScoreSingleStitch;

sim::SceneDef anastomosis() {
  auto d = sim::loadSceneDef(kScene);
  EXPECT_TRUE(std::holds_alternative<sim::SceneDef>(d));
  return std::get<sim::SceneDef>(std::move(d));
}

sim::InputFrame frameAt(double t, double x) {
  sim::InputFrame f;
  f.time = t;
  for (auto& h : f.hands) {
    h.tracked = true;
    h.position = sim::Vec3(x, 0.0, 0.0);
  }
  return f;
}

TEST(Attempt, MotionFollowsTheFramesTheSceneUsed) {
  const sim::SceneDef def = anastomosis();
  std::vector<sim::InputFrame> frames{frameAt(0.00, 0.0), frameAt(0.01, 1.0), frameAt(0.02, 2.0),
                                      frameAt(0.03, 3.0)};
  frames[2].hands[0].position.x() = std::numeric_limits<double>::quiet_NaN();  // rejected
  frames[3].hands[1].tracked = false;                                           // right hand lost
  const Attempt a = assembleAttempt(def, {}, {}, frames, 0.25);
  ASSERT_EQ(a.motion[0].size(), 4u);
  EXPECT_EQ(a.steps, 4);
  EXPECT_NEAR(a.duration, 4.0 / def.step.rateHz, 1e-12);
  EXPECT_DOUBLE_EQ(a.maxStretch, 0.25);
  EXPECT_DOUBLE_EQ(a.motion[0][2].position.x(), 1.0);  // the rejected frame repeats step 1
  EXPECT_DOUBLE_EQ(a.motion[1][2].position.x(), 1.0);
  EXPECT_DOUBLE_EQ(a.motion[0][3].position.x(), 3.0);
  EXPECT_FALSE(a.motion[1][3].tracked);
  EXPECT_DOUBLE_EQ(a.motion[1][3].position.x(), 1.0);  // held where it was
  EXPECT_NEAR(a.motion[0][3].time, 4.0 / def.step.rateHz, 1e-12);
}

TEST(Attempt, BothEndsOfASeveredVesselShareOneAngleFrameFacingTheCamera) {
  const sim::SceneDef def = anastomosis();
  const std::vector<VesselGeometry> g = vesselGeometry(def);
  ASSERT_EQ(g.size(), 2u);
  EXPECT_EQ(g[0].object, g[1].object);
  EXPECT_NEAR(g[0].axis.dot(g[1].axis), -1.0, 1e-12);
  EXPECT_NEAR((g[0].angleAxis - g[1].angleAxis).norm(), 0.0, 1e-12);
  EXPECT_NEAR(g[0].angleZero.dot(g[0].angleAxis), 0.0, 1e-12);
  EXPECT_GT(g[0].angleZero.dot(def.camera.eye - g[0].cutCentre), 0.0);
  EXPECT_NEAR((g[0].cutCentre - g[1].cutCentre).norm(), 0.5, 1e-9);  // the gap
  EXPECT_GT(g[0].wallThickness, 0.0);
}

TEST(Attempt, TheShippedStitchScoresTheSamePinnedValueEveryRun) {
  auto rubric = loadRubric(kRubric);
  ASSERT_TRUE(std::holds_alternative<Rubric>(rubric));
  double scores[2] = {0.0, 0.0};
  for (double& score : scores) {
    auto replayed = replayAttempt(kScene, kStitch);
    ASSERT_TRUE(std::holds_alternative<Attempt>(replayed));
    const Attempt& a = std::get<Attempt>(replayed);
    EXPECT_FALSE(a.truncated);
    EXPECT_EQ(a.pierces.size(), 4u);
    const AttemptScore s = scoreAttempt(a, std::get<Rubric>(rubric));
    EXPECT_EQ(s.rubricId, "03_single_stitch");
    EXPECT_EQ(s.pierces.size(), 2u);
    EXPECT_EQ(s.stitches.size(), 1u);
    score = s.score;
  }
  EXPECT_EQ(scores[0], scores[1]);
  EXPECT_NEAR(scores[0], kStitchScore, 1e-9);
}

// The replay ends with the leak test on the final scene: the shipped stitch is one stitch with no
// knot, so its line leaks, widest opposite the stitch (tests/sim/scene/leak_test_test.cpp); the
// score does not count it (metrics.h: lapse_index).
TEST(Attempt, TheReplayCarriesTheLeakTestOfTheFinalScene) {
  auto replayed = replayAttempt(kScene, kStitch);
  ASSERT_TRUE(std::holds_alternative<Attempt>(replayed));
  const Attempt& a = std::get<Attempt>(replayed);
  ASSERT_TRUE(a.leak.has_value());
  EXPECT_EQ(a.leak->status, sim::LeakTestStatus::Solved);
  EXPECT_TRUE(a.leak->leaks);
  EXPECT_GT(a.leak->largestGapMm, 0.5);
  EXPECT_GT(std::abs(std::remainder(a.leak->angleDeg, 360.0)), 135.0);
  EXPECT_DOUBLE_EQ(a.leak->limitMm, 0.05);
  EXPECT_DOUBLE_EQ(a.leak->pressureMmHg, 100.0);

  auto rubric = loadRubric(kRubric);
  ASSERT_TRUE(std::holds_alternative<Rubric>(rubric));
  const AttemptScore s = scoreAttempt(a, std::get<Rubric>(rubric));
  ASSERT_TRUE(s.leak.has_value());
  EXPECT_EQ(s.leak->largestGapMm, a.leak->largestGapMm);
  EXPECT_NEAR(s.score, kStitchScore, 1e-9);

  // an attempt captured from a scene has none
  EXPECT_FALSE(captureAttempt(sim::Scene(anastomosis()), {}).leak.has_value());
}

// A test without a verdict passes on its status and no numbers.
TEST(Attempt, ALeakTestWithoutAVerdictIsAFindingWithoutNumbers) {
  sim::LeakResult r;
  r.status = sim::LeakTestStatus::NoStitches;
  r.pressureMmHg = 100.0;
  r.leak = true;
  r.largestGapMm = 0.3;
  const LeakFinding f = leakFinding(r);
  EXPECT_EQ(f.status, sim::LeakTestStatus::NoStitches);
  EXPECT_FALSE(f.leaks);
  EXPECT_TRUE(std::isnan(f.largestGapMm));
  EXPECT_TRUE(std::isnan(f.angleDeg));
  EXPECT_TRUE(std::isnan(f.limitMm));
  EXPECT_DOUBLE_EQ(f.pressureMmHg, 100.0);
}

TEST(Attempt, ATruncatedRecordingScoresWhatItHoldsAndSaysSo) {
  sim::Recording whole;
  ASSERT_TRUE(sim::readRecording(kStitch, whole).ok());
  std::vector<std::uint8_t> bytes = sim::encodeRecording(whole);
  bytes.resize(bytes.size() / 4);
  sim::Recording part;
  ASSERT_EQ(sim::decodeRecording(bytes, part).error, sim::RecordingError::Truncated);
  auto replayed = replayAttempt(kScene, part, true);
  ASSERT_TRUE(std::holds_alternative<Attempt>(replayed));
  const Attempt& a = std::get<Attempt>(replayed);
  EXPECT_TRUE(a.truncated);
  EXPECT_EQ(a.steps, static_cast<int>(part.frames.size()));
  EXPECT_LT(a.steps, static_cast<int>(whole.frames.size()));
}

TEST(Attempt, ReplayErrorsNameTheirSource) {
  auto noScene = replayAttempt(kRoot + "/resources/scenes/missing.json", kStitch);
  ASSERT_TRUE(std::holds_alternative<ReplayError>(noScene));
  EXPECT_EQ(std::get<ReplayError>(noScene).kind, ReplayErrorKind::Scene);
  ASSERT_TRUE(std::get<ReplayError>(noScene).sceneError.has_value());
  auto noRecording = replayAttempt(kScene, kScene);  // JSON is not a recording
  ASSERT_TRUE(std::holds_alternative<ReplayError>(noRecording));
  EXPECT_EQ(std::get<ReplayError>(noRecording).kind, ReplayErrorKind::Recording);
  EXPECT_EQ(std::get<ReplayError>(noRecording).recording.error, sim::RecordingError::NotARecording);
}

TEST(Attempt, CaptureFromASteppedSceneMatchesTheRecorder) {
  auto opened = sim::openScene(kScene);
  ASSERT_TRUE(std::holds_alternative<std::unique_ptr<sim::Scene>>(opened));
  sim::Scene& scene = *std::get<std::unique_ptr<sim::Scene>>(opened);
  std::vector<sim::InputFrame> frames;
  AttemptRecorder recorder;
  for (int i = 0; i < 5; ++i) {
    frames.push_back(frameAt(i * scene.dt(), 0.1 * i));
    scene.step(frames.back());
    recorder.afterStep(scene, frames.back());
  }
  const Attempt captured = captureAttempt(scene, frames);
  const Attempt recorded = recorder.attempt(scene);
  EXPECT_EQ(captured.steps, 5);
  EXPECT_EQ(captured.motion[0].size(), recorded.motion[0].size());
  EXPECT_DOUBLE_EQ(captured.maxStretch, tissueStretch(scene));
  EXPECT_GE(recorded.maxStretch, captured.maxStretch);
}

}  // namespace
