#pragma once
// The depth inset (issue #18, depth): a small second view in the viewport's top-right corner
// that looks at the microscope's target from the side, at right angles to the microscope, so
// a tool's height above the tissue, which the view from above cannot show, reads as height
// on screen. It draws the frame's draw list (draw_list.h) with this camera, without the
// shadow pass or the microscope's depth cues, so it stays cheap on a software renderer.
//
// Units: millimetres, logical pixels.

#include "gui/render/camera.h"

#include <QRect>
#include <QSize>

namespace microsim::gui {

/// The side camera of `microscope`: at its distance from its target, looking along its up
/// axis (from the side of the view's bottom edge, where the trainee sits), the direction to
/// the microscope up on screen, the same field of view.
MicroscopeCamera sideViewCamera(const MicroscopeCamera& microscope);

/// The inset's area in a widget of `widget` size: the top-right corner, 10 px in, a quarter
/// of the width (at least 96 px) and 3:4 as tall as wide.
QRect sideViewArea(const QSize& widget);

}  // namespace microsim::gui
