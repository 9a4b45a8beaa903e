// The latency estimate recovers a known delay between a reference motion and a tracked
// copy of it, sampled at different rates and phases, from speeds alone.
#include "calibration/latency.h"

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace microsim::calibration {
namespace {

// a hand-like motion: sums of incommensurate sines on each axis (mm, s)
Eigen::Vector3d motion(double t) {
  return {20.0 * std::sin(2.0 * M_PI * 0.7 * t) + 6.0 * std::sin(2.0 * M_PI * 1.9 * t + 0.4),
          15.0 * std::sin(2.0 * M_PI * 0.45 * t + 1.0) + 4.0 * std::sin(2.0 * M_PI * 2.3 * t),
          5.0 * std::sin(2.0 * M_PI * 1.1 * t + 2.0)};
}

std::vector<TimedPosition> sample(double rateHz, double phase, double delay, double seconds, double sigma, unsigned seed,
                                  const Eigen::Matrix3d& frame = Eigen::Matrix3d::Identity()) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  std::vector<TimedPosition> out;
  // counted in samples, so rounding never adds or drops one
  for (int k = 0; phase + k / rateHz < seconds; ++k) {
    const double t = phase + k / rateHz;
    out.push_back({t, frame * motion(t - delay) + Eigen::Vector3d(noise(rng), noise(rng), noise(rng))});
  }
  return out;
}

TEST(Latency, RecoversAKnownDelayFromSpeeds) {
  // the tracked copy is 37 ms late, at 60 Hz, in a rotated frame; the reference at 100 Hz
  const Eigen::Matrix3d rotated = Eigen::AngleAxisd(0.8, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  for (double delay : {0.0, 0.037, 0.120}) {
    const std::vector<TimedPosition> ref = sample(100.0, 0.0, 0.0, 12.0, 0.01, 1);
    const std::vector<TimedPosition> trk = sample(60.0, 0.003, delay, 12.0, 0.01, 2, rotated);
    const LatencyResult r = estimateLatency(speedSignal(ref), speedSignal(trk));
    EXPECT_EQ(r.status, LatencyStatus::Ok);
    EXPECT_NEAR(r.latency, delay, 0.003) << "delay " << delay;
    EXPECT_GT(r.correlation, 0.9);
  }
}

TEST(Latency, AnEarlySignalGivesANegativeLag) {
  std::vector<SignalSample> ref, trk;
  for (int i = 0; i < 2000; ++i) {
    const double t = 0.005 * i;
    ref.push_back({t, std::sin(3.0 * t) + 0.5 * std::sin(7.3 * t)});
    trk.push_back({t, std::sin(3.0 * (t + 0.05)) + 0.5 * std::sin(7.3 * (t + 0.05))});
  }
  const LatencyResult r = estimateLatency(ref, trk);
  EXPECT_EQ(r.status, LatencyStatus::Ok);
  EXPECT_NEAR(r.latency, -0.05, 0.002);
}

TEST(Latency, RefusesShortFlatAndBrokenSignals) {
  std::vector<SignalSample> shortRef{{0.0, 1.0}, {0.1, 2.0}, {0.2, 1.0}};
  EXPECT_EQ(estimateLatency(shortRef, shortRef).status, LatencyStatus::TooShort);

  std::vector<SignalSample> flat, moving;
  for (int i = 0; i < 3000; ++i) {
    flat.push_back({0.001 * i, 4.0});
    moving.push_back({0.001 * i, std::sin(0.01 * i)});
  }
  EXPECT_EQ(estimateLatency(flat, moving).status, LatencyStatus::Flat);

  std::vector<SignalSample> broken = moving;
  broken[10].value = std::nan("");
  EXPECT_EQ(estimateLatency(moving, broken).status, LatencyStatus::NonFinite);
  broken = moving;
  broken[10].time = broken[9].time;
  EXPECT_EQ(estimateLatency(moving, broken).status, LatencyStatus::NonFinite);
}

}  // namespace
}  // namespace microsim::calibration
