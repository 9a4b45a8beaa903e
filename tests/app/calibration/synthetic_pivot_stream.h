#pragma once
// A tool pivoting smoothly about its tip, as a tracker would stream it: tilts on a
// Lissajous path up to `tiltDeg` about two axes, a slow spin about the tool axis, 100 Hz,
// Gaussian noise `sigma` (mm) on the marker position. Smooth, so the PoseFilter's speed
// check passes it like a real hand.
#include "tracking/pose_stream.h"

#include <Eigen/Geometry>

#include <cmath>
#include <random>
#include <string>

namespace microsim::testing {

inline tracking::PoseStream pivotStream(const std::string& device, const Eigen::Vector3d& tip,
                                        const Eigen::Vector3d& pivot, int n, double tiltDeg, double sigma,
                                        unsigned seed = 1) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  tracking::PoseStream stream;
  const double a = tiltDeg * M_PI / 180.0;
  for (int i = 0; i < n; ++i) {
    const double t = 0.01 * i;
    const Eigen::Matrix3d r = (Eigen::AngleAxisd(a * std::sin(2.0 * M_PI * 0.5 * t), Eigen::Vector3d::UnitX()) *
                               Eigen::AngleAxisd(a * std::sin(2.0 * M_PI * 0.35 * t + 1.0), Eigen::Vector3d::UnitY()) *
                               Eigen::AngleAxisd(0.3 * t, Eigen::Vector3d::UnitZ()))
                                  .toRotationMatrix();
    tracking::RawPose pose;
    pose.device = device;
    pose.time = 100.0 + t;
    pose.matrix.topLeftCorner<3, 3>() = r;
    pose.matrix.topRightCorner<3, 1>() = pivot - r * tip + Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
    stream.samples.emplace_back(pose);
  }
  return stream;
}

}  // namespace microsim::testing
