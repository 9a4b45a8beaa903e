#pragma once
// A Learn-mode mark the viewport draws over the scene (never in Test mode): a target point as
// a ring, or the ideal needle direction at a point as an arrow. Scene frame, millimetres.

#include <Eigen/Core>

#include <cstdint>

namespace microsim::gui {

struct Guide {
  enum class Kind : std::uint8_t {
    Target,           ///< a ring around `point` in the plane normal to `direction`
    NeedleDirection,  ///< an arrow from `point` along `direction`
  };
  Kind kind = Kind::Target;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();       ///< mm, scene frame
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  ///< unit: ring normal / arrow direction
  double size = 0.15;  ///< mm: ring radius (Target) or arrow length (NeedleDirection)
  bool done = false;   ///< drawn dimmed (the target was hit)
};

}  // namespace microsim::gui
