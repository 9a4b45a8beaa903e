#pragma once
// The operating microscope's camera: it looks at a target from a distance, orbits around the
// target, pans the target in the view plane, zooms by changing the distance, and has a focal
// distance (where the image is sharp; the viewport shades what lies off it). For stereo it
// gives each eye its own view and an off-axis frustum, so both eyes converge on the focal
// plane (zero parallax there, as in a real stereo microscope).
//
// Named views. The scene's camera is the microscope's home: reset() keeps it, and the table's
// normal is taken from it (the direction to the eye with its tilt toward the scene's up axis
// taken out), so the views are the same whatever the camera was turned to: Microscope (the
// scene's own view), Top (straight down the table's normal), Oblique (45° off it, from the
// trainee's side: what a tilted microscope shows of heights) and Side (along the table, the
// scene's up toward the back: height on screen is height above the table). Orbiting turns
// about the table's normal, and never past looking straight down.
//
// Units: millimetres, degrees.

#include "microsim/sim/scene/scene_def.h"

#include <QMatrix4x4>
#include <QQuaternion>
#include <QVector3D>

namespace microsim::gui {

enum class Eye { Centre, Left, Right };

/// The camera's named views (see the header essay).
enum class NamedView { Microscope, Top, Oblique, Side };

class MicroscopeCamera {
 public:
  MicroscopeCamera();

  /// Places the camera as the scene says (eye, target, up, vertical field of view); the focus
  /// goes to the target. The view is kept as home for the named views.
  void reset(const sim::CameraDef& def);
  /// Looks at the home target from the home distance as `view` says; the focus goes to the
  /// target.
  void showView(NamedView view);
  /// The unit normal of the table under the scene (scene frame), from the home view.
  QVector3D tableNormal() const { return tableNormal_; }

  /// Turns about the target: `yawDeg` about the table's normal, `pitchDeg` about the view's
  /// right axis (never past looking straight down).
  void orbit(float yawDeg, float pitchDeg);
  /// Moves the target (and the eye with it) by a drag of (dx, dy) pixels on a view `height`
  /// pixels tall: the point under the cursor stays under it at the target's depth.
  void pan(float dx, float dy, int height);
  /// Wheel steps: each brings the eye 10 % closer (negative: farther); the focal distance
  /// follows so the sharp plane stays on the same point.
  void zoom(float steps);
  /// Distance from the eye to the sharp plane (mm), clamped to [near, far].
  void setFocusDistance(float mm);
  float focusDistance() const { return focus_; }
  float distance() const { return distance_; }
  float fovDeg() const { return fovDeg_; }

  QVector3D target() const { return target_; }
  QVector3D eye() const;
  QVector3D right() const;    ///< unit, scene frame
  QVector3D up() const;       ///< unit, scene frame
  QVector3D forward() const;  ///< unit, from the eye toward the target

  /// Distance between the two eyes (mm): the microscope's stereo base scaled to the working
  /// distance (about 1/30 of it).
  float eyeSeparation() const { return distance_ / 30.0f; }
  QMatrix4x4 view(Eye eye = Eye::Centre) const;
  QMatrix4x4 projection(float aspect, Eye eye = Eye::Centre) const;
  /// Size of a pixel at the target's depth (mm) on a view `height` pixels tall.
  float mmPerPixel(int height) const;
  float nearPlane() const { return distance_ * 0.2f; }
  float farPlane() const { return distance_ * 4.0f; }

 private:
  void look(const QVector3D& towardEye, const QVector3D& screenUp);

  sim::CameraDef home_;
  QVector3D tableNormal_{0.0f, 0.0f, 1.0f};
  QVector3D target_;
  QQuaternion orientation_;  // camera → scene; the camera looks down its −z, up is its +y
  float distance_ = 40.0f;
  float fovDeg_ = 12.0f;
  float focus_ = 40.0f;
};

}  // namespace microsim::gui
