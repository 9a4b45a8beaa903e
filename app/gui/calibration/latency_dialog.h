#pragma once
// Latency estimate: the tracked tool and a reference (another device or source moved
// together with it, e.g. the mouse emulation or a faster tracker) are recorded while the
// trainee moves; calibration::estimateLatency correlates their speeds. Two devices of one
// source keep the source's timestamps; two sources are stamped with this program's
// receive clock, so the estimate is the tracker's lag as the simulation sees it, relative
// to the reference's own lag.

#include "calibration/latency.h"

#include <QDialog>
#include <QElapsedTimer>
#include <QPointer>

#include <vector>

class QComboBox;
class QDialogButtonBox;
class QLabel;
class QPushButton;

namespace microsim::tracking {
class TrackerSource;
struct RawPose;
}  // namespace microsim::tracking

namespace microsim::gui {

class LatencyDialog : public QDialog {
  Q_OBJECT

 public:
  /// `reference` may be the same object as `tracked` (two devices of one source).
  LatencyDialog(tracking::TrackerSource* tracked, tracking::TrackerSource* reference, QWidget* parent = nullptr);

  void setDevices(const QString& tracked, const QString& reference);
  void startRecording();
  /// Stops and estimates; the result is shown and kept.
  const calibration::LatencyResult& stopRecording();
  const calibration::LatencyResult& result() const { return result_; }

 private:
  void onPose(const tracking::RawPose& pose, bool fromReference);

  QPointer<tracking::TrackerSource> tracked_;
  QPointer<tracking::TrackerSource> reference_;
  QComboBox* trackedBox_ = nullptr;
  QComboBox* referenceBox_ = nullptr;
  QPushButton* record_ = nullptr;
  QLabel* label_ = nullptr;
  QDialogButtonBox* buttons_ = nullptr;
  QElapsedTimer clock_;
  bool recording_ = false;
  std::vector<calibration::TimedPosition> trackedPath_, referencePath_;
  calibration::LatencyResult result_;
};

}  // namespace microsim::gui
