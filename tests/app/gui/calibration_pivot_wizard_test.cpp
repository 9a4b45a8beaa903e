// The pivot wizard walked with a replayed tracker stream of a tool pivoting about a known
// tip: the poses are collected automatically, and the accepted tip is within 0.1 mm.
#include "gui/calibration/pivot_wizard.h"

#include "app/calibration/synthetic_pivot_stream.h"
#include "tracking/replay_source.h"

#include <QAbstractButton>
#include <QSignalSpy>
#include <QTest>

#include <gtest/gtest.h>

namespace microsim::gui {
namespace {

tracking::ReplayConfig fastPivotReplay() {
  tracking::ReplayConfig c;
  c.pace = tracking::ReplayPace::AsFastAsPossible;
  c.batch = 8;
  return c;
}

TEST(CalibrationPivotWizard, ReplayedPivotReachesAnAcceptedTipWithinATenthOfAMillimetre) {
  const Eigen::Vector3d tip(1.5, -2.0, 148.0);
  const Eigen::Vector3d pivot(40.0, -12.0, 220.0);
  tracking::ReplaySource source(testing::pivotStream("Stylus", tip, pivot, 1500, 35.0, 0.05), fastPivotReplay());

  calibration::PivotCollectorOptions options;
  options.targetPoses = 120;
  PivotWizard wizard(&source, options);
  wizard.setDevice(QStringLiteral("Stylus"), sim::Hand::Right);
  wizard.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&wizard));
  EXPECT_EQ(wizard.currentId(), PivotWizard::DevicePage);

  // the collection page fills from the stream and completes by itself
  wizard.next();
  ASSERT_EQ(wizard.currentId(), PivotWizard::CollectPage);
  EXPECT_FALSE(wizard.currentPage()->isComplete());
  source.start();
  QTRY_VERIFY_WITH_TIMEOUT(wizard.currentPage()->isComplete(), 20000);
  EXPECT_GE(wizard.collector().count(), 120);
  EXPECT_GE(wizard.collector().spreadDeg(), options.solve.minSpreadDeg);

  // the result page: accepted, within a tenth of a millimetre
  QSignalSpy accepted(&wizard, &QDialog::accepted);
  wizard.next();
  ASSERT_EQ(wizard.currentId(), PivotWizard::ResultPage);
  const calibration::PivotResult& r = wizard.result();
  EXPECT_TRUE(r.accepted()) << PivotWizard::describe(r.status).toStdString();
  EXPECT_TRUE(wizard.currentPage()->isComplete());
  EXPECT_LE((r.tipOffset - tip).norm(), 0.1) << r.tipOffset.transpose();
  EXPECT_LE((r.pivot - pivot).norm(), 0.1) << r.pivot.transpose();
  EXPECT_LT(r.rmsError, 0.15);
  EXPECT_EQ(wizard.hand(), sim::Hand::Right);
  wizard.button(QWizard::FinishButton)->click();
  EXPECT_EQ(accepted.count(), 1);
  source.stop();
}

TEST(CalibrationPivotWizard, AToolSpunAboutItsAxisNeverCompletes) {
  // tilts of 3°: plenty of poses, not enough spread
  tracking::ReplaySource source(testing::pivotStream("Stylus", {0, 0, 150}, {0, 0, 0}, 600, 3.0, 0.0), fastPivotReplay());
  calibration::PivotCollectorOptions options;
  options.targetPoses = 20;
  options.minStepDeg = 0.2;
  PivotWizard wizard(&source, options);
  wizard.setDevice(QStringLiteral("Stylus"));
  wizard.show();
  wizard.next();
  QSignalSpy finished(&source, &tracking::ReplaySource::finished);
  source.start();
  ASSERT_TRUE(finished.wait(20000));
  EXPECT_GE(wizard.collector().count(), 20);
  EXPECT_FALSE(wizard.collector().spreadEnough());
  EXPECT_FALSE(wizard.currentPage()->isComplete());
}

TEST(CalibrationPivotWizard, ABadFitIsRefusedAndCollectedAgain) {
  // 2 mm of noise: the RMS error is above the 0.5 mm threshold
  tracking::ReplaySource source(testing::pivotStream("Stylus", {0, 0, 150}, {0, 0, 0}, 1000, 35.0, 2.0), fastPivotReplay());
  calibration::PivotCollectorOptions options;
  options.targetPoses = 60;
  PivotWizard wizard(&source, options);
  wizard.setDevice(QStringLiteral("Stylus"));
  wizard.show();
  wizard.next();
  source.start();
  QTRY_VERIFY_WITH_TIMEOUT(wizard.currentPage()->isComplete(), 20000);
  source.stop();
  wizard.next();
  EXPECT_EQ(wizard.result().status, calibration::PivotStatus::RmsAboveThreshold);
  EXPECT_FALSE(wizard.currentPage()->isComplete());

  // "Collect again" returns to an empty collection
  wizard.back();
  EXPECT_EQ(wizard.currentId(), PivotWizard::CollectPage);
  EXPECT_EQ(wizard.collector().count(), 0);
}

}  // namespace
}  // namespace microsim::gui
