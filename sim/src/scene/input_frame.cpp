#include "microsim/sim/scene/input_frame.h"

#include <cmath>

namespace microsim::sim {

bool validateFrame(const InputFrame& frame, InputRejection& why) {
  if (!std::isfinite(frame.time)) {
    why = InputRejection::NonFinite;
    return false;
  }
  for (const HandInput& h : frame.hands) {
    if (!h.position.allFinite() || !h.orientation.coeffs().allFinite() || !std::isfinite(h.closure)) {
      why = InputRejection::NonFinite;
      return false;
    }
    if (std::abs(h.orientation.norm() - 1.0) > 1e-6) {
      why = InputRejection::NotUnitRotation;
      return false;
    }
    if (h.closure < 0.0 || h.closure > 1.0) {
      why = InputRejection::ClosureOutOfRange;
      return false;
    }
  }
  return true;
}

bool validateSequence(const InputFrame& frame, double previousTime, InputRejection& why) {
  if (!validateFrame(frame, why)) return false;
  if (frame.time < previousTime) {
    why = InputRejection::TimeBackwards;
    return false;
  }
  return true;
}

}  // namespace microsim::sim
