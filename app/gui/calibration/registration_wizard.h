#pragma once
// Paired-point registration of the tracker to the scene, with any TrackerSource. Each row
// of the table is a point with known scene coordinates (typed in, mm) and a role: a
// fiducial (used in the fit) or a check point (used only for the TRE). "Touch" takes the
// calibrated tip (p + R d, d the pivot-calibrated offset) averaged over the last poses of
// the chosen device. With ≥ 3 fiducials touched, the result page shows FRE (fit) and TRE
// (check points) from calibration::registerPoints (Eigen's umeyama).

#include "calibration/registration.h"

#include <Eigen/Core>

#include <QPointer>
#include <QWizard>

#include <deque>

class QTableWidget;
class QLabel;

namespace microsim::tracking {
class TrackerSource;
struct RawPose;
}  // namespace microsim::tracking

namespace microsim::gui {

class RegistrationWizard : public QWizard {
  Q_OBJECT

 public:
  enum Page { PointsPage, ResultPage };
  enum class Role { Fiducial, Check };

  /// `device` carries the pointer tool, whose tip is `tipOffset` (tool frame, mm).
  RegistrationWizard(tracking::TrackerSource* source, const QString& device, const Eigen::Vector3d& tipOffset,
                     QWidget* parent = nullptr);

  /// Adds a row; returns its index.
  int addPoint(Role role, const Eigen::Vector3d& scene);
  /// Takes the current tip for `row`; false when no pose of the device has arrived.
  bool touch(int row);
  /// Sets the tracker coordinates of `row` directly (mm).
  void setTracker(int row, const Eigen::Vector3d& tracker);

  const calibration::RegistrationResult& result() const { return result_; }
  static QString describe(calibration::RegistrationStatus status);

 private:
  class PointsWizardPage;
  class ResultWizardPage;

  void onPose(const tracking::RawPose& pose);
  void solve();
  Role roleOf(int row) const;
  bool touched(int row) const;

  QPointer<tracking::TrackerSource> source_;
  QString device_;
  Eigen::Vector3d tipOffset_;
  std::deque<Eigen::Vector3d> recentTips_;  ///< mm, tracker frame, the last poses' tips
  QTableWidget* table_ = nullptr;
  PointsWizardPage* pointsPage_ = nullptr;
  calibration::RegistrationResult result_;
};

}  // namespace microsim::gui
