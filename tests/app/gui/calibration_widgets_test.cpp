// The calibration widgets around the wizards: the tracker status line, the live view of
// calibrated tips, the profile chooser's import/export, and the menu's session applying
// a profile to the frames it passes on.
#include "gui/calibration/calibration_menu.h"
#include "gui/calibration/live_tool_view.h"
#include "gui/calibration/profile_chooser_dialog.h"
#include "gui/calibration/profile_conversion.h"
#include "gui/calibration/tracker_status_widget.h"

#include "app/calibration/synthetic_pivot_stream.h"
#include "microsim/assessment/storage/setup_profiles.h"
#include "tracking/replay_source.h"

#include <QFile>
#include <QFileInfo>
#include <QMainWindow>
#include <QMenuBar>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

#include <limits>

namespace microsim::gui {
namespace {

tracking::ReplayConfig fast() {
  tracking::ReplayConfig c;
  c.pace = tracking::ReplayPace::AsFastAsPossible;
  return c;
}

assessment::SetupProfile profile() {
  assessment::SetupProfile p;
  p.name = QStringLiteral("Bench");
  p.hands[1].device = QStringLiteral("Stylus");
  p.hands[1].tipOffset = Eigen::Vector3d(0, 0, 150);
  p.trackerToScene.topRightCorner<3, 1>() = Eigen::Vector3d(-10, -20, -30);
  p.calibratedAt = QDateTime(QDate(2026, 11, 22), QTime(12, 0), Qt::UTC);
  return p;
}

TEST(CalibrationWidgets, StatusLineCountsWhatTheSourceRefused) {
  tracking::PoseStream stream = testing::pivotStream("Stylus", {0, 0, 150}, {0, 0, 0}, 30, 20.0, 0.0);
  tracking::RawPose nan = std::get<tracking::RawPose>(stream.samples[5]);
  nan.matrix(1, 1) = std::numeric_limits<double>::infinity();
  stream.samples.push_back(nan);
  tracking::ReplaySource source(stream, fast());
  TrackerStatusWidget status;
  EXPECT_EQ(status.text(), QStringLiteral("No tracker"));
  status.setSource(&source);
  EXPECT_TRUE(status.text().startsWith(QStringLiteral("Tracker not connected")));
  QSignalSpy finished(&source, &tracking::ReplaySource::finished);
  source.start();
  ASSERT_TRUE(finished.wait(10000));
  status.refresh();
  EXPECT_TRUE(status.text().contains(QStringLiteral("1 dropped"))) << status.text().toStdString();
  EXPECT_TRUE(status.toolTip().contains(QStringLiteral("non_finite: 1"))) << status.toolTip().toStdString();
}

TEST(CalibrationWidgets, LiveViewPlotsTheCalibratedTip) {
  const Eigen::Vector3d pivot(5, 6, 7);
  tracking::ReplaySource source(testing::pivotStream("Stylus", {0, 0, 150}, pivot, 50, 20.0, 0.0), fast());
  LiveToolView view;
  view.setSource(&source);
  view.setCalibration(deviceMapping(profile()), setupCalibration(profile()));
  view.show();
  QSignalSpy finished(&source, &tracking::ReplaySource::finished);
  source.start();
  ASSERT_TRUE(finished.wait(10000));
  EXPECT_FALSE(view.tip(sim::Hand::Left));
  ASSERT_TRUE(view.tip(sim::Hand::Right));
  // the tip stays on the pivot, moved by the registration
  EXPECT_LE((*view.tip(sim::Hand::Right) - (pivot + Eigen::Vector3d(-10, -20, -30))).norm(), 1e-6);
  EXPECT_FALSE(view.grab().isNull());
}

TEST(CalibrationWidgets, ChooserImportsExportsAndNamesTheFieldAtFault) {
  QTemporaryDir dir;
  assessment::HistoryDatabase db;
  ASSERT_TRUE(db.open(dir.filePath(QStringLiteral("h.sqlite"))).ok());
  ProfileChooserDialog chooser(&db);

  const QString good = dir.filePath(QStringLiteral("good.json"));
  {
    QFile f(good);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(assessment::exportProfileJson(profile()));
  }
  QString error;
  const std::optional<qint64> id = chooser.importFile(good, &error);
  ASSERT_TRUE(id) << error.toStdString();
  chooser.reload(*id);
  const QString out = dir.filePath(QStringLiteral("out.json"));
  ASSERT_TRUE(chooser.exportFile(*id, out, &error));
  QFile back(out);
  ASSERT_TRUE(back.open(QIODevice::ReadOnly));
  const auto parsed = assessment::importProfileJson(back.readAll());
  ASSERT_TRUE(std::holds_alternative<assessment::SetupProfile>(parsed));
  EXPECT_TRUE(std::get<assessment::SetupProfile>(parsed).sameContent(profile()));

  const QString bad = dir.filePath(QStringLiteral("bad.json"));
  {
    QFile f(bad);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(assessment::exportProfileJson(profile()).replace("\"hand_per_scene\": 1", "\"hand_per_scene\": -1"));
  }
  EXPECT_FALSE(chooser.importFile(bad, &error));
  EXPECT_TRUE(error.contains(QStringLiteral("motion_scaling.hand_per_scene"))) << error.toStdString();
}

TEST(CalibrationWidgets, ChooserExportOnAFullDiskNamesTheFileAndTheReason) {
  QTemporaryDir dir;
  assessment::HistoryDatabase db;
  ASSERT_TRUE(db.open(dir.filePath(QStringLiteral("h.sqlite"))).ok());
  assessment::SetupProfileStore store(db);
  const std::optional<qint64> id = store.save(profile());
  ASSERT_TRUE(id) << store.lastError().toStdString();
  ProfileChooserDialog chooser(&db);
  QString error;

  // /dev/full: QFile takes the bytes into its buffer; the flush is where ENOSPC shows
  const QString full = QStringLiteral("/dev/full");
  ASSERT_TRUE(QFileInfo::exists(full) && !QFileInfo(full).isFile()) << "/dev/full is not the device";
  EXPECT_FALSE(chooser.exportFile(*id, full, &error));
  EXPECT_TRUE(error.contains(full)) << error.toStdString();
  EXPECT_TRUE(error.contains(QStringLiteral("No space left on device"))) << error.toStdString();
  // written in place, never replaced (QSaveFile's rename would succeed as root)
  ASSERT_FALSE(QFileInfo(full).isFile()) << "the export put a regular file where the device was; as root restore it: rm /dev/full && mknod -m 666 /dev/full c 1 7";

  const QString nowhere = dir.filePath(QStringLiteral("missing/out.json"));
  error.clear();
  EXPECT_FALSE(chooser.exportFile(*id, nowhere, &error));
  EXPECT_TRUE(error.contains(nowhere)) << error.toStdString();
  EXPECT_TRUE(error.contains(QStringLiteral("No such file or directory"))) << error.toStdString();
}

TEST(CalibrationWidgets, MenuSessionCalibratesTheFramesItPassesOn) {
  QTemporaryDir dir;
  assessment::HistoryDatabase db;
  ASSERT_TRUE(db.open(dir.filePath(QStringLiteral("h.sqlite"))).ok());
  QMainWindow window;
  CalibrationSession* session = addCalibrationMenu(&window, &db);
  ASSERT_NE(session, nullptr);
  bool found = false;
  for (QAction* a : window.menuBar()->actions()) found = found || a->text() == QStringLiteral("&Calibration");
  EXPECT_TRUE(found);
  session->setProfile(profile());

  const Eigen::Vector3d pivot(1, 2, 3);
  tracking::ReplayConfig config = fast();
  config.mapping = session->mapping();
  auto source = std::make_unique<tracking::ReplaySource>(
      testing::pivotStream("Stylus", {0, 0, 150}, pivot, 20, 20.0, 0.0), config);
  tracking::ReplaySource* replay = source.get();
  QSignalSpy frames(session, &CalibrationSession::sceneFrameReady);
  QSignalSpy finished(replay, &tracking::ReplaySource::finished);
  session->adoptSource(std::move(source));
  replay->start();
  ASSERT_TRUE(finished.wait(10000));
  ASSERT_EQ(frames.count(), 20);
  const auto last = frames.last().at(0).value<sim::InputFrame>();
  EXPECT_LE((last.hands[1].position - (pivot + Eigen::Vector3d(-10, -20, -30))).norm(), 1e-6);
}

}  // namespace
}  // namespace microsim::gui
