#pragma once
// A live view of the calibrated tools: the tip of each hand (the profile's device mapping,
// tip offsets, registration and scaling applied: calibration::toScene) plotted in the
// scene frame, from above (x–y) and from the side (x–z), with the last second as a trail.
// The view is centred on the scaling anchor and spans ±range mm.

#include "calibration/setup_calibration.h"
#include "tracking/frame_assembler.h"

#include <QPointer>
#include <QWidget>

#include <array>
#include <deque>
#include <optional>

namespace microsim::tracking {
class TrackerSource;
struct RawPose;
}  // namespace microsim::tracking

namespace microsim::gui {

class LiveToolView : public QWidget {
  Q_OBJECT

 public:
  explicit LiveToolView(QWidget* parent = nullptr);

  void setSource(tracking::TrackerSource* source);
  void setCalibration(const tracking::DeviceMapping& mapping, const calibration::SetupCalibration& calibration);
  void setRange(double mm) { rangeMm_ = mm; }

  /// The latest calibrated tip of a hand (scene frame, mm); none until its device was seen.
  std::optional<Eigen::Vector3d> tip(sim::Hand hand) const;

  QSize sizeHint() const override { return {480, 260}; }

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  void onPose(const tracking::RawPose& pose);

  QPointer<tracking::TrackerSource> source_;
  tracking::FrameAssembler assembler_;
  calibration::SetupCalibration calibration_;
  double rangeMm_ = 60.0;
  struct Sample {
    double time;  ///< s, source clock
    Eigen::Vector3d tip;
  };
  std::array<std::deque<Sample>, sim::kHandCount> trails_;
};

}  // namespace microsim::gui
