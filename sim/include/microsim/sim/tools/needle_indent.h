#pragma once
// The needle's tip pressing on a wall before it punctures it.
//
// A sharp tip that meets a tissue surface does not cut at once: the wall dents under it until
// the force on the tip reaches the tissue's puncture force, and only then does the tip go in
// (Okamura et al., IEEE TBME 2004, for the force profile: a rising elastic phase, a puncture,
// then cutting and friction; Ergeneman et al., J. Med. Devices 2011, for puncture forces of
// micro-vessels in the millinewton range).
//
// The scene keeps at most one indentation, started where the tip's path first crosses a face
// into the material (an entry crossing, tools/needle.h; an exit is the tip already cutting and
// is pierced at once). While it lasts, the face's point under the tip is tied to the tip by a
// stiff zero-rest spring (mesh/point_spring.h): the tip drags the face with it, so the wall
// dents, and it cannot slide off the face (a sharp tip catches; it is pushed along the path
// it cuts, so the face is dragged with it as much as pressed). After each tissue solve the
// force on the tip along its direction of travel τ (the needle's tangent at the tip) is
//     f = k (t − g)·τ        (µN)
// with t the tip, g the face point and k the spring's stiffness. The wall is punctured, and
// the pierce made at the face point, when f reaches the puncture force, or when the tip has
// carried the face its wall's thickness past where it touched,
//     d = (p₀ − t)·s ≥ the wall thickness     (p₀ the first touch, s below)
// (a wall that gives way as a whole never pushes back with the puncture force: the free end
// of a severed vessel, entered from its lumen on a deep pass, rose with the tip and was carried
// up and over it with no pierce; by then the tip has gone through where the wall was, and
// the tissue it carried is the dent a real wall shows before it gives). The indentation ends
// without a pierce when the tip draws back past where it first touched, d < 0 with s the face
// normal at first touch turned towards the side the tip came from, when the face's point lies
// clearly past the tip ((t − g)·s above 1 µm: something stronger than the spring moved the
// wall away), or when the needle is let go. (The sign of (t − g)·s alone cannot tell: the
// spring keeps g within a fraction of a micrometre of t, the solve's tolerance, and a test on
// it ended dents at random, so a tip pressing into a wall from the lumen in notches slipped
// through it with no pierce.) Only a tip that moves point first cuts: one going back, tail first, follows the
// channel it cut, and an entry it makes pierces at once. At the puncture the tip sits in the dent's apex, so going on it may cross the
// dent's other faces (those around the punctured one, facesAround): those entries are the
// same passage, and the scene ignores them until the tip's next crossing.
//
// Units: mm, k in g/s², forces in µN (g·mm/s²).

#include "microsim/sim/mesh/point_spring.h"
#include "microsim/sim/mesh/spring_model.h"
#include "microsim/sim/tools/needle.h"

#include <vector>

namespace microsim::sim::tools {

/// A tip pressing on a face: where it first touched and from which side.
struct Indentation {
  FaceCrossing touch;         ///< the entry crossing that started it (face, barycentric)
  Vec3 side = Vec3::Zero();   ///< unit: the face normal at first touch, towards the tip's side
  double throughDepth = 0.0;  ///< mm: the wall's thickness, d at which the tip is through; 0 = none
};

/// Starts an indentation at an entry crossing into a wall `throughDepth` thick (mm; 0 = the
/// force alone punctures).
Indentation beginIndentation(const FaceCrossing& entry, double throughDepth);

/// The face's point under the tip at positions x (mm).
Vec3 indentedPoint(const SpringModel& tissue, const Points& x, const Indentation& in);

/// The spring that holds the face's point at the tip.
PointSpring indentationSpring(const SpringModel& tissue, const Indentation& in, const Vec3& tip, double k);

/// The force the tip pushes the face with along its direction of travel τ (unit): k (t − g)·τ
/// (µN, > 0 when pushing).
double indentationForce(const SpringModel& tissue, const Points& x, const Indentation& in, const Vec3& tip,
                        const Vec3& travel, double k);

/// How far the tip has gone past where it first touched, against the side it came from:
/// d = (p₀ − t)·s (mm).
double indentationDepth(const Indentation& in, const Vec3& tip);

/// Whether the tip is through: it pushes with `punctureForce` (µN) along `travel`, or d has
/// reached the indentation's throughDepth.
bool punctured(const SpringModel& tissue, const Points& x, const Indentation& in, const Vec3& tip,
               const Vec3& travel, double k, double punctureForce);

/// Whether the tip no longer presses on the face: back past where it first touched (d < 0),
/// or the face's point clearly past it.
bool tipWithdrawn(const SpringModel& tissue, const Points& x, const Indentation& in, const Vec3& tip);

/// The faces that share a corner with `face`, itself included, in index order.
std::vector<int> facesAround(const SpringModel& tissue, int face);

}  // namespace microsim::sim::tools
