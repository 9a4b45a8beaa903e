#pragma once
// Per-stitch metrics. A stitch is one needle pass through both ends of a severed vessel:
// two consecutive wall passages (pierce_metrics.h; four pierce events) of the same vessel
// through different ends. A passage that does not pair so is not part of a stitch.
//
//   symmetry    |bite_a − bite_b| (mm): the two bites should be equal;
//   position    the circular mean of the two passages' circumferential angles;
//   spacing     the smaller angle between this stitch's position and the previous
//               stitch's (degrees, [0, 180]); NaN for the first stitch;
//   triangulation (of the first three stitches, Cobbett's method): the three stitch
//               positions sorted around the circle cut it into three arcs, ideally 120°
//               each; the error is the largest |arc − 120°|.
//
// Units: millimetres, degrees.

#include "microsim/assessment/scoring/pierce_metrics.h"

#include <optional>
#include <vector>

namespace microsim::assessment {

struct StitchMetrics {
  int first = -1;                ///< index of the first passage into the pierceMetrics list
  int second = -1;               ///< index of the second
  double time = 0.0;             ///< s, the first entry's
  double biteAMm = 0.0;          ///< first passage's bite (mm)
  double biteBMm = 0.0;          ///< second passage's bite (mm)
  double symmetryMm = 0.0;       ///< |biteA − biteB| (mm)
  double positionDeg = 0.0;      ///< [0, 360)
  double spacingDeg = 0.0;       ///< to the previous stitch, [0, 180]; NaN for the first
  bool fullThickness = false;    ///< both passages full thickness
};

/// Groups passages into stitches, in order.
std::vector<StitchMetrics> stitchMetrics(const std::vector<PierceMetrics>& passages);

/// Largest |arc − 120°| of the first three stitches' positions; nullopt with fewer than 3.
std::optional<double> triangulationErrorDeg(const std::vector<StitchMetrics>& stitches);

/// Smaller angle between two directions on the circle, [0, 180] degrees.
double angularDistanceDeg(double aDeg, double bDeg);

}  // namespace microsim::assessment
