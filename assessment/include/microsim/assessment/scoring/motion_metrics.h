#pragma once
// Motion metrics of one hand's tool-tip samples (attempt.h: one per step, dt apart).
//
//   path length   Σ |x_{i+1} − x_i| over consecutive tracked samples (mm);
//   speed         v_i = |x_{i+1} − x_i| / dt (mm/s), the forward difference;
//   movements     velocity-threshold segmentation: a movement is a maximal run of speeds
//                 ≥ movementSpeed lasting at least minMovementS; runs closer than mergeGapS
//                 are one movement (a brief dip is not a new movement);
//   idle time     time in which the speed is below idleSpeed (mm/s), in s;
//   smoothness    log dimensionless jerk of each movement (Hogan & Sternad 2009, the
//                 peak-speed normalisation as used by Balasubramanian et al. 2015):
//                     LDLJ = −ln( (T³ / v_peak²) ∫ |d³x/dt³|² dt )
//                 T the movement's duration, v_peak its peak speed; the jerk is the third
//                 finite difference of positions. Higher (closer to 0) is smoother; a
//                 minimum-jerk reach scores −ln(720 / 1.875²) = −5.32.
//   stepped input the tips move in steps rather than continuously: at least half of the
//                 samples in which a tracked tip moved are followed by one in which it stood
//                 exactly still. Key presses and key repeat (tracking/manual_source.h: one
//                 0.05 mm jump per press, nothing in between) and a source slower than the
//                 step rate that holds its last pose look like this; a tracked hand is never
//                 exactly still in the middle of a movement. Finite differences of such
//                 motion measure the steps, not the hand: its jerk is that of the jumps and
//                 every step between two jumps is "idle", so smoothness and idle time do not
//                 apply to it (metrics.h marks them not applicable).
//
// Units: millimetres, seconds.

#include "microsim/assessment/scoring/attempt.h"

#include <vector>

namespace microsim::assessment {

struct MotionParams {
  double movementSpeed = 1.0;  ///< mm/s: at and above it the tip is moving
  double idleSpeed = 0.2;      ///< mm/s: below it the hand is idle
  double minMovementS = 0.1;   ///< s: shorter runs are tremor, not movements
  double mergeGapS = 0.05;     ///< s: runs separated by less are one movement
};

struct Movement {
  int begin = 0;               ///< first sample index
  int end = 0;                 ///< one past the last sample index
  double duration = 0.0;       ///< s
  double peakSpeed = 0.0;      ///< mm/s
  double ldlj = 0.0;           ///< log dimensionless jerk (dimensionless)
};

struct HandMotion {
  double pathLengthMm = 0.0;
  double idleS = 0.0;
  std::vector<Movement> movements;
  double meanLdlj = 0.0;       ///< mean over movements; NaN without movements
};

/// Sum of the steps between consecutive tracked samples (mm).
double pathLength(const std::vector<MotionSample>& samples);

/// Forward-difference speeds (mm/s), one per sample; the last repeats the one before.
std::vector<double> speeds(const std::vector<MotionSample>& samples, double dt);

/// −ln((T³/v_peak²) ∫|jerk|² dt) over samples [begin, end); NaN with fewer than 4 samples
/// or no motion.
double logDimensionlessJerk(const std::vector<MotionSample>& samples, int begin, int end,
                            double dt);

/// Segments a hand's samples into movements.
std::vector<Movement> segmentMovements(const std::vector<MotionSample>& samples, double dt,
                                       const MotionParams& params);

HandMotion handMotion(const std::vector<MotionSample>& samples, double dt,
                      const MotionParams& params);

/// Time (s) in which both hands are below idleSpeed.
double idleTime(const Attempt& attempt, const MotionParams& params);

/// True when the attempt's tips moved in steps (see "stepped input" above); false when they
/// never moved.
bool steppedInput(const Attempt& attempt);

/// Grabs (GripSuture, GrabTissue) by a hand after that hand's release.
int regrasps(const std::vector<sim::SceneEvent>& events);

}  // namespace microsim::assessment
