#pragma once
// The pierces of an attempt drawn on the vessel, seen from the side: the vessel axis runs
// left to right, up is toward the microscope (the scene's view direction projected out of the
// axis). Each vessel is its wall band around the lumen; each pierce a dot where it crossed
// (entries red, exits blue) with the needle's direction through it and its angle to the
// wall normal (0° = perpendicular), labelled "1: 51°" in the interface's number format.
//
// Pierces of one stitch lie a fraction of a millimetre apart, a few pixels at this scale, so
// each label is placed where it covers no other label and no pierce's dot: beside its dot
// (odd pierces above first, even ones below), else stacked further away, always inside the
// image where there is room.

#include "microsim/sim/mesh/vessel.h"
#include "microsim/sim/scene/scene_events.h"

#include <QImage>
#include <QRectF>
#include <QSize>

#include <vector>

namespace microsim::gui {

QImage drawPierceAngles(const std::vector<sim::VesselDef>& vessels,
                        const std::vector<sim::PierceEvent>& pierces, QSize size);

/// Where drawPierceAngles writes each pierce's label, in image pixels, in pierce order.
std::vector<QRectF> pierceLabelRects(const std::vector<sim::VesselDef>& vessels,
                                     const std::vector<sim::PierceEvent>& pierces, QSize size);

}  // namespace microsim::gui
