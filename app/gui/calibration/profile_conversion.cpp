#include "gui/calibration/profile_conversion.h"

namespace microsim::gui {

tracking::DeviceMapping deviceMapping(const assessment::SetupProfile& profile) {
  tracking::DeviceMapping m;
  for (int h = 0; h < sim::kHandCount; ++h) {
    const assessment::ProfileHand& in = profile.hands[h];
    tracking::HandMapping& out = m.hands[h];
    out.device = in.device.toStdString();
    out.instrument = in.instrument;
    out.closureChannel = in.closureChannel.toStdString();
    out.closureOpen = in.closureOpen;
    out.closureClosed = in.closureClosed;
  }
  return m;
}

calibration::SetupCalibration setupCalibration(const assessment::SetupProfile& profile) {
  calibration::SetupCalibration c;
  c.trackerToScene = profile.trackerToScene;
  for (int h = 0; h < sim::kHandCount; ++h) c.tipOffset[h] = profile.hands[h].tipOffset;
  c.scaling.handPerScene = profile.handPerScene;
  c.scaling.anchor = profile.scalingAnchor;
  return c;
}

}  // namespace microsim::gui
