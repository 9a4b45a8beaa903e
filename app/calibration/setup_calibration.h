#pragma once
// A setup's calibration applied to tracker-frame InputFrames (DESIGN.md §Data flow):
//   tip      x = p + R d                  (p, R: tool pose in the tracker frame; d: the hand's
//                                          pivot-calibrated tip offset, tool frame, mm)
//   register y = s Q x + t                (trackerToScene = [s Q, t; 0 1], from registerPoints)
//   scale    z = a + (y − a) / h          (motion scaling: h = hand mm per scene mm, about the
//                                          scene anchor a, mm; h > 1 makes motion finer)
// The orientation becomes Q R. Untracked hands, time and closure pass unchanged.

#include "microsim/sim/scene/input_frame.h"

#include <Eigen/Core>

#include <array>

namespace microsim::calibration {

struct MotionScaling {
  double handPerScene = 1.0;                            ///< mm of hand motion per mm of scene motion (> 0)
  Eigen::Vector3d anchor = Eigen::Vector3d::Zero();     ///< scene point that stays fixed, mm
};

/// z = a + (y − a) / h.
Eigen::Vector3d scaleMotion(const MotionScaling& scaling, const Eigen::Vector3d& y);

struct SetupCalibration {
  Eigen::Matrix4d trackerToScene = Eigen::Matrix4d::Identity();  ///< homogeneous, similarity
  std::array<Eigen::Vector3d, sim::kHandCount> tipOffset{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};  ///< mm, tool frame
  MotionScaling scaling;
};

/// Maps a tracker-frame frame to the scene frame (equations above).
sim::InputFrame toScene(const sim::InputFrame& trackerFrame, const SetupCalibration& calibration);

}  // namespace microsim::calibration
