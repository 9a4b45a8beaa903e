#pragma once
// The hands of a scripted needle pass (stitch_script.cpp, back_wall_catch_script.cpp): what
// the two tools do, frame by frame, to take a curved needle along one circle through tissue
// and draw its thread after it. The scripts differ only in the circle, where the tools wait
// and which way the thread is drawn; the hands' phases are these:
//   1. the needle holder (right hand) goes to the needle where the scene lays it and closes;
//   2. it carries the needle to the start of the arc;
//   3. it turns the needle about the circle's centre through the tissue;
//   4. the forceps (left hand) comes from the side, slides onto the needle along its jaws and
//      closes behind the tip; only then does the holder open, draw back along its jaws and go
//      aside (the needle is held throughout, as hands pass it); the forceps turns the needle
//      on along the circle until it is out and draws the thread;
//   5. the forceps opens.

#include "microsim/sim/scene/recording.h"
#include "microsim/sim/scene/scene_def.h"
#include "microsim/sim/scene/stitch_script.h"

#include <Eigen/Geometry>

#include <numbers>
#include <string>

namespace microsim::sim {

inline constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;

struct PassPlan {
  StitchGeometry circle;     ///< the needle's tip runs on it (ψ, see needleOnPassCircle)
  double startDeg = 0.0;     ///< ψ where the holder brings the tip (degrees)
  double handOverDeg = 0.0;  ///< ψ where the forceps takes the needle (degrees)
  double pullOutDeg = 0.0;   ///< ψ the forceps turns the needle to (degrees)
  double passSeconds = 1.0;  ///< duration of phase 3 (s)
  int gripNode = 8;          ///< needle node the holder takes
  int pullGripNode = 1;      ///< needle node the forceps takes
  Eigen::Isometry3d forcepsWaits =
      Eigen::Isometry3d::Identity();  ///< the forceps' pose until phase 4
  Eigen::Isometry3d holderGoes =
      Eigen::Isometry3d::Identity();   ///< the holder's pose after it lets go
  Vec3 pullDirection = Vec3::UnitZ();  ///< the thread is drawn along this (unit)
  double pullMm = 3.0;                 ///< this far (mm)
  std::string metadata;                ///< the recording's metadata (names the script)
};

/// The frames of `plan` at the scene's rate (the scene must have a needle).
Recording recordPass(const SceneDef& scene, const PassPlan& plan);

}  // namespace microsim::sim
