#pragma once
// The pierces of an attempt drawn on the vessel, seen from the side: the vessel axis runs
// left to right, up is toward the microscope (the scene's view direction projected out of the
// axis). Each vessel is its wall band around the lumen; each pierce a dot where it crossed
// (entries red, exits blue) with the needle's direction through it and its angle to the
// wall normal (0° = perpendicular).

#include "microsim/sim/mesh/vessel.h"
#include "microsim/sim/scene/scene_events.h"

#include <QImage>
#include <QSize>

#include <vector>

namespace microsim::gui {

QImage drawPierceAngles(const std::vector<sim::VesselDef>& vessels,
                        const std::vector<sim::PierceEvent>& pierces, QSize size);

}  // namespace microsim::gui
