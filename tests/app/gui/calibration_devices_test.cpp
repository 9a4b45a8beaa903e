// The 6-DoF devices where the app chooses its input (the Calibration menu): both are offered,
// an absent one is refused with its reason, and a game controller (SDL's virtual controller,
// through the real library) drives a running scene whose recording replays to what was shown.
#include "gui/calibration/calibration_menu.h"
#include "gui/main_window.h"
#include "gui/pages/attempt_page.h"
#include "gui/simulation_runner.h"
#include "gui/viewport.h"

#include "app/gui/core_profile.h"
#include "microsim/sim/scene/recording.h"
#include "support/queued_signal_spy.h"
#include "support/shipped_files.h"
#include "support/virtual_gamepad.h"
#include "tracking/gamepad_source.h"

#include <QAction>
#include <QFile>
#include <QMainWindow>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace microsim::gui {
namespace {

bool waitForDevices(const std::function<bool()>& done) {
  for (int i = 0; i < 1000 && !done(); ++i) QTest::qWait(10);
  return done();
}

TEST(CalibrationDevices, TheMenuOffersTheThreeDMouseAndTheGameController) {
  QMainWindow window;
  addCalibrationMenu(&window, nullptr);
  const auto* spacenav = window.findChild<QAction*>(QStringLiteral("useSpacenavAction"));
  const auto* gamepad = window.findChild<QAction*>(QStringLiteral("useGamepadAction"));
  ASSERT_NE(spacenav, nullptr);
  ASSERT_NE(gamepad, nullptr);
  EXPECT_EQ(spacenav->text(), QStringLiteral("Use a 3D mouse (spacenavd)"));
  EXPECT_EQ(gamepad->text(), QStringLiteral("Use a game controller"));
}

TEST(CalibrationDevices, AnAbsentDeviceIsRefusedWithItsReasonAndTheSourceStays) {
  SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
  ASSERT_EQ(SDL_InitSubSystem(SDL_INIT_GAMECONTROLLER), 0);
  const int present = SDL_NumJoysticks();
  SDL_QuitSubSystem(SDL_INIT_GAMECONTROLLER);
  if (present > 0 || QFile::exists(QStringLiteral("/var/run/spnav.sock")) || QFile::exists(QStringLiteral("/etc/spnavrc")))
    GTEST_SKIP() << "a game controller or a spacenavd is present here";

  QTemporaryDir dir;
  qputenv("SPNAV_SOCKET", dir.filePath(QStringLiteral("nobody-listens.sock")).toUtf8());
  CalibrationSession session(nullptr);
  QString error;
  EXPECT_FALSE(session.useSpacenav(&error));
  EXPECT_TRUE(error.contains(QStringLiteral("spacenavd")));
  EXPECT_EQ(session.source(), nullptr);
  error.clear();
  EXPECT_FALSE(session.useGamepad(&error));
  EXPECT_TRUE(error.contains(QStringLiteral("No game controller")));
  EXPECT_EQ(session.source(), nullptr);
  qunsetenv("SPNAV_SOCKET");
}

// Frames from the controller reach the simulation as they are (no registration applies to a
// device that moves tools in the scene frame), start where the scene shows the tools, are
// recorded like any tracker's, and the recording replays to the state the live run ended in.
TEST(CalibrationDevices, AGameControllerDrivesTheSceneAndIsRecordedAndReplayedLikeAnyOtherSource) {
  testing::VirtualGamepad pad;
  if (pad.controllersBefore() > 0) GTEST_SKIP() << "a real game controller is plugged in here";
  ASSERT_TRUE(pad.pluggedIn()) << pad.error();

  QTemporaryDir dir;
  const QString recording = dir.filePath(QStringLiteral("pad.msrec"));
  SimulationRunner runner;
  ASSERT_TRUE(runner.load(testing::kShippedScene, sim::StepMode::Deterministic));
  runner.setRecordingFile(recording);

  CalibrationSession session(nullptr);
  assessment::SetupProfile profile;
  profile.trackerToScene.topRightCorner<3, 1>() = Eigen::Vector3d(-10, -20, -30);  // must not apply
  profile.calibratedAt = QDateTime::currentDateTimeUtc();
  session.setProfile(profile);
  session.setRateToolProviders(
      [&runner]() -> std::optional<sim::InputFrame> {
        const auto shown = runner.latestSnapshot();
        return shown ? tracking::toolsShown(*shown) : std::nullopt;
      },
      nullptr, nullptr);
  QObject::connect(&session, &CalibrationSession::sceneFrameReady, &runner, &SimulationRunner::submitFrame);
  QSignalSpy frames(&session, &CalibrationSession::sceneFrameReady);

  runner.start();
  testing::QueuedSignalSpy snapshots(&runner, &SimulationRunner::snapshotReady);
  ASSERT_TRUE(snapshots.count() > 0 || snapshots.wait(10000));
  const std::optional<sim::InputFrame> before = tracking::toolsShown(*runner.latestSnapshot());
  ASSERT_TRUE(before.has_value());

  QString error;
  ASSERT_TRUE(session.useGamepad(&error)) << error.toStdString();
  auto* source = qobject_cast<tracking::GamepadSource*>(session.source());
  ASSERT_NE(source, nullptr);
  pad.setAxis(SDL_CONTROLLER_AXIS_LEFTX, 32767);
  ASSERT_TRUE(waitForDevices([&] { return frames.count() >= 3; }));
  pad.setAxis(SDL_CONTROLLER_AXIS_LEFTX, 0);

  // as the source made it, in the scene frame, from where the right tool was shown
  const auto sent = frames.last().at(0).value<sim::InputFrame>();
  EXPECT_EQ(sent, source->current());
  const Eigen::Vector3d moved = sent.hand(sim::Hand::Right).position - before->hand(sim::Hand::Right).position;
  EXPECT_GT(moved.x(), 0.0);
  EXPECT_LT(moved.norm(), 1.0);

  // the simulation steps with it and the recording holds it
  ASSERT_TRUE(waitForDevices([&] {
    const std::vector<sim::InputFrame> consumed = runner.consumedFrames();
    return !consumed.empty() && consumed.back() == sent;
  }));
  runner.stop();
  const std::uint64_t shown = runner.stateHash();
  sim::Recording stored;
  ASSERT_TRUE(sim::readRecording(recording.toStdString(), stored).ok());
  EXPECT_EQ(stored.frames, runner.consumedFrames());
  EXPECT_EQ(stored.frames.back(), sent);

  SimulationRunner replayed;
  ASSERT_TRUE(replayed.load(testing::kShippedScene, sim::StepMode::Deterministic));
  testing::QueuedSignalSpy finished(&replayed, &SimulationRunner::replayFinished);
  replayed.replay(stored.frames);
  ASSERT_TRUE(finished.count() > 0 || finished.wait(60000));
  EXPECT_EQ(replayed.stateHash(), shown);
  session.setSource(nullptr);
}

// In the app, the controller takes over the tools where the attempt shows them and moves them
// along the microscope's axes as the viewport has them.
TEST(CalibrationDevices, InTheAppTheControllerMovesTheShownToolAlongTheViewsRight) {
  testing::VirtualGamepad pad;
  if (pad.controllersBefore() > 0) GTEST_SKIP() << "a real game controller is plugged in here";
  ASSERT_TRUE(pad.pluggedIn()) << pad.error();
  requestCoreProfile();
  QTemporaryDir dir;
  assessment::HistoryDatabase history;
  const QString path = dir.filePath(QStringLiteral("history.sqlite"));
  const assessment::DatabaseStatus status = history.open(path);
  MainWindow window(&history, status, path);
  window.resize(800, 600);
  window.show();
  ASSERT_TRUE(window.startLesson(0, assessment::AttemptMode::Learn));
  SimulationRunner* runner = window.attemptPage()->runner();
  ASSERT_NE(runner, nullptr);
  ASSERT_TRUE(waitForDevices([runner] { return runner->latestSnapshot() && runner->steps() > 0; }));
  const std::optional<sim::InputFrame> shown = tracking::toolsShown(*runner->latestSnapshot());
  ASSERT_TRUE(shown.has_value());

  // the microscope turned: its right is no longer a scene axis
  window.viewport()->camera().orbit(40.0f, 0.0f);
  window.viewport()->cameraChanged();
  const QVector3D right = window.viewport()->camera().right();
  ASSERT_LT(std::abs(right.x()), 0.9f);

  QString error;
  ASSERT_TRUE(window.calibration()->useGamepad(&error)) << error.toStdString();
  QSignalSpy frames(window.calibration(), &CalibrationSession::sceneFrameReady);
  pad.setAxis(SDL_CONTROLLER_AXIS_LEFTX, 32767);
  ASSERT_TRUE(waitForDevices([&] { return frames.count() >= 2; }));
  pad.setAxis(SDL_CONTROLLER_AXIS_LEFTX, 0);

  const auto first = frames.first().at(0).value<sim::InputFrame>();
  const auto last = frames.last().at(0).value<sim::InputFrame>();
  // the first frame is one poll away from where the right tool was shown (a keyboard start
  // pose is not moved by the manual source unless a key is pressed)
  EXPECT_LT((first.hand(sim::Hand::Right).position - shown->hand(sim::Hand::Right).position).norm(), 0.2);
  const Eigen::Vector3d moved = last.hand(sim::Hand::Right).position - shown->hand(sim::Hand::Right).position;
  ASSERT_GT(moved.norm(), 0.0);
  EXPECT_GT(moved.normalized().dot(Eigen::Vector3d(right.x(), right.y(), right.z())), 0.999);
  EXPECT_EQ(last.hand(sim::Hand::Left), shown->hand(sim::Hand::Left));
  window.attemptPage()->stop();
}

}  // namespace
}  // namespace microsim::gui
