#pragma once
// A stored setup profile as the tracking and calibration code use it: the hands' device
// mapping (for FrameAssembler / IgtlClient) and the tracker → scene calibration (toScene).

#include "calibration/setup_calibration.h"
#include "tracking/frame_assembler.h"

#include "microsim/assessment/storage/setup_profiles.h"

namespace microsim::gui {

tracking::DeviceMapping deviceMapping(const assessment::SetupProfile& profile);
calibration::SetupCalibration setupCalibration(const assessment::SetupProfile& profile);

}  // namespace microsim::gui
