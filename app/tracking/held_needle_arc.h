#pragma once
// The circle of a needle a forceps holds, in that forceps' frame: what the wrist turn of a
// surgeon follows. Turning the tool about this circle's axis, through its centre, moves the
// held needle along its own curve (the grip keeps the needle fixed on the jaws), so the tip
// goes where the needle's body already is.
//
// Read from what is drawn (a RenderSnapshot): the hand holds the needle when its jaws hold
// the suture and a needle link lies on the jaws' axis, within kHeldNeedleGapMm (the grasp
// takes the point nearest the line where the jaws meet: tools/jaw_grasp.h; the thread, which
// may drape anywhere once the needle is in a wall, does not count). The
// circle passes through the needle's tip, its middle node and its swage; a straight needle
// has none. The circle is given in the tool frame of the same snapshot, so it stays right
// however far the tool has moved since (the needle moves with the jaws).
//
// Units: millimetres.

#include "microsim/sim/scene/input_frame.h"
#include "microsim/sim/scene/render_snapshot.h"

#include <Eigen/Core>

#include <optional>

namespace microsim::tracking {

/// A held needle's circle in the holding tool's frame.
struct HeldNeedleArc {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< mm, tool frame
  /// Unit axis, tool frame: turning the tool by a positive angle about it (right hand) moves
  /// the needle tip first, forward along the needle's curve.
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  double radius = 0.0;  ///< mm
};

/// How far along its axis (mm, from the tip toward the hinge) a tool's jaws are searched for
/// the held link: longer than any shipped jaw.
inline constexpr double kHeldNeedleJawReachMm = 5.0;
/// How far from the jaws' axis (mm) a needle link may lie and still be the one they hold: the
/// jaws' gripping faces are about this wide.
inline constexpr double kHeldNeedleGapMm = 0.1;

/// The circle of the needle `hand` holds in `snapshot`; null when that hand holds no needle
/// or the needle is straight.
std::optional<HeldNeedleArc> heldNeedleArc(const sim::RenderSnapshot& snapshot, sim::Hand hand);

}  // namespace microsim::tracking
