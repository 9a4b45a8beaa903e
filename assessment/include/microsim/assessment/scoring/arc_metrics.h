#pragma once
// Did the needle follow its own arc? A curved needle is a circular arc of radius R; driven
// properly (a wrist turn about the arc's centre) its tip moves along that circle, so between
// two moments of one continuous hold the tip's displacement is fixed by how far the needle
// turned:
//
//     p₁ − p₀ = R · (t₁ − t₀) × n,   n = (t₀ × t₁) / |t₀ × t₁|
//
// p the tip, t its forward tangent (unit), n the normal of the circle's plane (the turn is
// taken as the shorter one, < 180°, between the two moments). The arc deviation of a pair is
// |(p₁ − p₀) − R (t₁ − t₀) × n|: 0 for a tip carried along the circle, the whole
// displacement for a needle pushed or swept without turning (t₁ = t₀).
//
// The moments are the pierce events (PierceEvent: where the tip crossed a wall and its
// tangent there), consecutive in time and not separated by a grip or release of the needle
// (a re-grip legitimately re-orients the needle between bites). A straight push through a
// wall of thickness w deviates by about w; a sideways sweep through the lumen by the sweep.
//
// Units: millimetres.

#include "microsim/assessment/scoring/attempt.h"

namespace microsim::assessment {

/// |(p₁ − p₀) − R (t₁ − t₀) × n| for two tip positions and forward tangents (unit) of a
/// needle of radius R (mm).
double arcDeviationMm(const sim::Vec3& p0, const sim::Vec3& t0, const sim::Vec3& p1,
                      const sim::Vec3& t1, double needleRadius);

/// The largest arc deviation (mm) between consecutive pierce events of one hold; NaN when
/// there is no such pair or the scene's needle is not curved (Attempt::needleRadius NaN).
double needleArcDeviationMm(const Attempt& attempt);

}  // namespace microsim::assessment
