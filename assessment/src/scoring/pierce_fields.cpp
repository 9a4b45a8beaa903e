#include "microsim/assessment/scoring/pierce_fields.h"

#include <array>

namespace microsim::assessment {

namespace {

constexpr std::array<PierceField, 8> kPierceFields{{
    {"time_s", "s", [](const PierceMetrics& p) { return p.time; }},
    {"entry_angle_deg", "deg", [](const PierceMetrics& p) { return p.entryAngleDeg; }},
    {"exit_angle_deg", "deg", [](const PierceMetrics& p) { return p.exitAngleDeg; }},
    {"bite_mm", "mm", [](const PierceMetrics& p) { return p.biteMm; }},
    {"bite_walls", "1", [](const PierceMetrics& p) { return p.biteWalls; }},
    {"circumference_deg", "deg", [](const PierceMetrics& p) { return p.circumferenceDeg; }},
    {"full_thickness", "flag", [](const PierceMetrics& p) { return p.fullThickness ? 1.0 : 0.0; }},
    {"back_wall", "flag", [](const PierceMetrics& p) { return p.backWall ? 1.0 : 0.0; }},
}};

}  // namespace

std::span<const PierceField> pierceFields() { return kPierceFields; }

}  // namespace microsim::assessment
