// Motion metrics on synthetic tool-tip paths with known answers: a straight constant-speed
// path's length, a minimum-jerk reach's log dimensionless jerk, movement segmentation,
// idle time, and re-grasps from an event sequence.
#include "microsim/assessment/scoring/motion_metrics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace {

using namespace microsim::assessment;
using microsim::sim::SceneEvent;
using microsim::sim::SceneEventKind;
using microsim::sim::Vec3;

std::vector<MotionSample> path(int n, double dt, const auto& at) {
  std::vector<MotionSample> s(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    s[static_cast<std::size_t>(i)].time = i * dt;
    s[static_cast<std::size_t>(i)].position = at(i * dt);
    s[static_cast<std::size_t>(i)].tracked = true;
  }
  return s;
}

// x(t) = A (10τ³ − 15τ⁴ + 6τ⁵) along a direction: the minimum-jerk reach of duration T
Vec3 minimumJerk(double t, double T, double A) {
  const double u = std::clamp(t / T, 0.0, 1.0);
  return A * (10 * u * u * u - 15 * u * u * u * u + 6 * u * u * u * u * u) * Vec3(0.6, 0.8, 0.0);
}

TEST(MotionMetrics, AStraightConstantSpeedPathHasItsLengthAndSpeed) {
  const double dt = 0.01;
  // 2 mm/s along (1, 2, 2)/3 for 3 s: 6 mm
  const auto s = path(301, dt, [](double t) -> Vec3 { return Vec3(1, 2, 2) / 3.0 * 2.0 * t; });
  EXPECT_NEAR(pathLength(s), 6.0, 1e-9);
  for (double v : speeds(s, dt)) EXPECT_NEAR(v, 2.0, 1e-9);
  const auto moves = segmentMovements(s, dt, MotionParams{});
  ASSERT_EQ(moves.size(), 1u);
  EXPECT_EQ(moves[0].begin, 0);
  EXPECT_EQ(moves[0].end, 301);
  EXPECT_NEAR(moves[0].duration, 3.0, 1e-9);
  EXPECT_NEAR(moves[0].peakSpeed, 2.0, 1e-9);
}

TEST(MotionMetrics, UntrackedStretchesAddNoPath) {
  auto s = path(11, 0.1, [](double t) -> Vec3 { return Vec3(t, 0, 0); });
  s[5].tracked = false;  // the steps 4→5 and 5→6 do not count
  EXPECT_NEAR(pathLength(s), 0.8, 1e-12);
}

TEST(MotionMetrics, AMinimumJerkReachHasTheKnownLogDimensionlessJerk) {
  // ∫|jerk|² = 720 A²/T⁵ and v_peak = 1.875 A/T, so LDLJ = −ln(720/1.875²) ≈ −5.3219
  const double T = 1.0, A = 5.0, dt = 0.001;
  const auto s = path(1001, dt, [&](double t) -> Vec3 { return minimumJerk(t, T, A); });
  const double expected = -std::log(720.0 / (1.875 * 1.875));
  EXPECT_NEAR(logDimensionlessJerk(s, 0, 1001, dt), expected, 0.01);
  // independent of amplitude and duration
  const auto slow = path(3001, dt, [&](double t) -> Vec3 { return minimumJerk(t, 3.0, 0.5); });
  EXPECT_NEAR(logDimensionlessJerk(slow, 0, 3001, dt), expected, 0.01);
  // a jerkier path (two reaches back to back, a kink between) scores lower
  const auto twice = path(1001, dt, [&](double t) -> Vec3 {
    return t < 0.5 ? minimumJerk(t, 0.5, A) : Vec3(minimumJerk(0.5, 0.5, A) + Vec3(0, 0, A * 2 * (t - 0.5)));
  });
  EXPECT_LT(logDimensionlessJerk(twice, 0, 1001, dt), expected - 1.0);
}

TEST(MotionMetrics, TooFewSamplesOrNoMotionHaveNoJerk) {
  const auto still = path(10, 0.01, [](double) -> Vec3 { return Vec3(1, 1, 1); });
  EXPECT_TRUE(std::isnan(logDimensionlessJerk(still, 0, 10, 0.01)));
  EXPECT_TRUE(std::isnan(logDimensionlessJerk(still, 0, 3, 0.01)));
}

TEST(MotionMetrics, SegmentationSplitsAtRestsMergesDipsAndDropsTremor) {
  const double dt = 0.01;
  // 0–1 s at 3 mm/s, 1–2 s still, 2–2.02 s still (dip inside the next move), 2–3 s at 3 mm/s
  // with a 0.03 s pause at 2.5 s, then a 0.05 s twitch at 3.5 s
  auto speedAt = [](double t) {
    if (t < 1.0) return 3.0;
    if (t < 2.0) return 0.0;
    if (t < 3.0) return (t >= 2.5 && t < 2.53) ? 0.0 : 3.0;
    if (t >= 3.5 && t < 3.55) return 3.0;
    return 0.0;
  };
  std::vector<MotionSample> s(401);
  double x = 0.0;
  for (int i = 0; i <= 400; ++i) {
    s[static_cast<std::size_t>(i)].position = Vec3(x, 0, 0);
    s[static_cast<std::size_t>(i)].tracked = true;
    x += speedAt(i * dt + 1e-9) * dt;
  }
  const MotionParams params;  // 1 mm/s, 0.1 s minimum, 0.05 s merge gap
  const auto moves = segmentMovements(s, dt, params);
  ASSERT_EQ(moves.size(), 2u);
  EXPECT_EQ(moves[0].begin, 0);
  EXPECT_EQ(moves[0].end, 101);
  EXPECT_EQ(moves[1].begin, 200);
  EXPECT_EQ(moves[1].end, 301);
  const HandMotion h = handMotion(s, dt, params);
  EXPECT_NEAR(h.pathLengthMm, 3.0 * (2.0 - 0.03) + 3.0 * 0.05, 1e-9);
  // still: 1–2 s, the 0.03 s pause, 3–4 s less the twitch (the last sample repeats)
  EXPECT_NEAR(h.idleS, (100 + 3 + 96) * dt, 1e-9);
}

TEST(MotionMetrics, IdleTimeCountsStepsWhenBothHandsRest) {
  Attempt a;
  a.stepDt = 0.1;
  a.motion[0] = path(11, 0.1, [](double t) -> Vec3 { return Vec3(std::max(0.0, t - 0.5), 0, 0); });
  a.motion[1] = path(11, 0.1, [](double t) -> Vec3 { return Vec3(0, t < 0.3 ? 0.0 : t, 0); });
  // left moves from step 5, right from step 2 (0.2→0.3 jumps, then 1 mm/s): both rest in 0–1
  EXPECT_NEAR(idleTime(a, MotionParams{}), 0.2, 1e-12);
}

TEST(MotionMetrics, RegraspsAreGrabsAfterTheSameHandsRelease) {
  auto e = [](SceneEventKind k, int hand) {
    SceneEvent ev;
    ev.kind = k;
    ev.hand = hand;
    return ev;
  };
  using K = SceneEventKind;
  const std::vector<SceneEvent> events{
      e(K::GripSuture, 1),  e(K::GrabTissue, 0),   e(K::ReleaseTissue, 0), e(K::PierceEntry, -1),
      e(K::GrabTissue, 0),  e(K::ReleaseSuture, 1), e(K::GripSuture, 0),   e(K::GripSuture, 1),
      e(K::ReleaseSuture, 1), e(K::Cut, 1)};
  // left re-grabs tissue, then grips the suture with no release between (not a regrasp);
  // right re-grips after its release
  EXPECT_EQ(regrasps(events), 2);
}

}  // namespace
