#pragma once
// Pivot calibration of one tool tip, with any TrackerSource: (1) choose the tracked
// device and the hand it serves, (2) pivot the tool in the divot while poses are collected
// automatically (calibration::PivotCollector: the page completes only when enough poses
// span enough angle), (3) the solution with its RMS error, accepted when the RMS is within
// the threshold; otherwise "Collect again" clears the poses and returns to step 2.

#include "calibration/pivot_collector.h"

#include "microsim/sim/scene/input_frame.h"

#include <QPointer>
#include <QWizard>

class QComboBox;
class QLabel;
class QProgressBar;

namespace microsim::tracking {
class TrackerSource;
struct RawPose;
}  // namespace microsim::tracking

namespace microsim::gui {

class PivotWizard : public QWizard {
  Q_OBJECT

 public:
  enum Page { DevicePage, CollectPage, ResultPage };

  PivotWizard(tracking::TrackerSource* source, calibration::PivotCollectorOptions options = {},
              QWidget* parent = nullptr);

  /// Preselects the device (it need not have been seen yet) and the hand.
  void setDevice(const QString& device, sim::Hand hand = sim::Hand::Left);
  QString device() const;
  sim::Hand hand() const;

  const calibration::PivotCollector& collector() const { return collector_; }
  /// The last solution (valid on the result page and after accept()).
  const calibration::PivotResult& result() const { return result_; }

  /// A user-readable sentence for a solver status.
  static QString describe(calibration::PivotStatus status);

 Q_SIGNALS:
  /// The collection page's counts changed (for tests and screen readers).
  void collectionChanged(int poses, double spreadDeg);
  void solved(const microsim::calibration::PivotResult& result);

 private:
  class CollectWizardPage;
  class ResultWizardPage;

  void onPose(const tracking::RawPose& pose);
  void redo();

  QPointer<tracking::TrackerSource> source_;
  calibration::PivotCollector collector_;
  calibration::PivotResult result_;
  QComboBox* deviceBox_ = nullptr;
  QComboBox* handBox_ = nullptr;
  CollectWizardPage* collectPage_ = nullptr;
  ResultWizardPage* resultPage_ = nullptr;
};

}  // namespace microsim::gui
