#include "tracking/spacenav_mapping.h"

#include <algorithm>

namespace microsim::tracking {

RateCommand spacenavCommand(const SpacenavMotion& motion, const SpacenavScale& scale) {
  const auto axis = [&scale](int counts) { return pastDeadZone(counts / scale.fullScale, scale.deadZone); };
  RateCommand command;
  command.translation = {axis(motion.x), axis(motion.y), axis(-motion.z)};
  command.rotation = {axis(-motion.rx), axis(-motion.ry), axis(motion.rz)};
  return command;
}

double spacenavStep(const SpacenavMotion& motion, const SpacenavScale& scale) {
  return std::min(motion.periodMs * 1e-3, scale.maxStepS);
}

SpacenavButtonAction spacenavButtonAction(int button) {
  switch (button) {
    case 0: return SpacenavButtonAction::HoldJaws;
    case 1: return SpacenavButtonAction::SwitchHand;
    case 2: return SpacenavButtonAction::SwitchInstrument;
    default: return SpacenavButtonAction::None;
  }
}

}  // namespace microsim::tracking
