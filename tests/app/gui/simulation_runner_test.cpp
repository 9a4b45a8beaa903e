#include "support/golden_stitch.h"
#include "support/queued_signal_spy.h"
#include "gui/simulation_runner.h"

#include "microsim/sim/scene/recorded_scene.h"
#include "microsim/sim/scene/recording.h"
#include "support/shipped_files.h"

#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace microsim::gui {
namespace {

using microsim::testing::kShippedScene;
using microsim::testing::kShippedStitch;
using microsim::testing::kSourceRoot;
// the golden hash of stitch.msrec on anastomosis.json (tests/sim/scene/stitch_test.cpp)
using microsim::testing::kGoldenStitchHash;

std::vector<sim::InputFrame> stitchFrames() {
  sim::Recording rec;
  const sim::RecordingStatus status = sim::readRecording(kShippedStitch.toStdString(), rec);
  EXPECT_TRUE(status.ok());
  return rec.frames;
}

TEST(SimulationRunner, ReplayOfTheStitchGivesTheGoldenHashAndFourPierces) {
  QTemporaryDir dir;
  const QString recording = dir.filePath(QStringLiteral("again.msrec"));
  SimulationRunner runner;
  ASSERT_TRUE(runner.load(kShippedScene, sim::StepMode::Deterministic));
  ASSERT_NE(runner.sceneDef(), nullptr);
  ASSERT_NE(runner.latestSnapshot(), nullptr);
  EXPECT_EQ(runner.latestSnapshot()->steps, 0);

  const std::vector<sim::InputFrame> frames = stitchFrames();
  ASSERT_FALSE(frames.empty());
  runner.setRecordingFile(recording);
  testing::QueuedSignalSpy finished(&runner, &SimulationRunner::replayFinished);
  testing::QueuedSignalSpy events(&runner, &SimulationRunner::sceneEvent);
  runner.replay(frames);
  ASSERT_TRUE(finished.count() > 0 || finished.wait(120000));

  EXPECT_EQ(runner.stateHash(), kGoldenStitchHash);
  EXPECT_EQ(runner.pierces().size(), 4u);
  EXPECT_EQ(runner.steps(), static_cast<int>(frames.size()));
  EXPECT_EQ(runner.latestSnapshot()->steps, static_cast<int>(frames.size()));
  EXPECT_EQ(runner.latestSnapshot()->pierceCount, 4);
  EXPECT_EQ(runner.consumedFrames(), frames);
  EXPECT_FALSE(runner.isRunning());
  // every event reached the signal, in order
  QTRY_COMPARE(events.count(), static_cast<int>(runner.events().size()));
  EXPECT_GE(runner.events().size(), 4u);

  // the recording holds exactly the consumed frames, with its end record, and names the
  // scene they were stepped on (microsim-cli run and score then need no --scene)
  runner.stop();
  EXPECT_TRUE(runner.recordingStatus().ok());
  sim::Recording again;
  ASSERT_TRUE(sim::readRecording(recording.toStdString(), again).ok());
  EXPECT_EQ(again.frames, frames);
  EXPECT_EQ(again.scene, sim::recordScene(kShippedScene.toStdString()));
  EXPECT_EQ(again.scene.path, kShippedScene.toStdString());
}

TEST(SimulationRunner, LiveStepsWithTheLatestSubmittedFrame) {
  SimulationRunner runner;
  ASSERT_TRUE(runner.load(kShippedScene, sim::StepMode::RealTime));
  testing::QueuedSignalSpy snapshots(&runner, &SimulationRunner::snapshotReady);
  runner.start();
  EXPECT_TRUE(runner.isRunning());
  ASSERT_TRUE(snapshots.wait(10000));  // steps happen before any frame (tools untracked)

  sim::InputFrame frame;
  frame.time = 0.5;
  sim::HandInput& right = frame.hand(sim::Hand::Right);
  right.tracked = true;
  right.position = Eigen::Vector3d(1.5, 0.4, 1.2);
  runner.submitFrame(frame);
  // a later snapshot shows the right forceps where the frame put it
  QTRY_VERIFY_WITH_TIMEOUT(
      [&] {
        const auto s = runner.latestSnapshot();
        return s && (s->forceps[1].pose.block<3, 1>(0, 3).cast<double>() - right.position).norm() < 1e-5;
      }(),
      10000);
  const int before = runner.steps();
  QTRY_VERIFY_WITH_TIMEOUT(runner.steps() > before + 3, 10000);
  runner.stop();
  EXPECT_FALSE(runner.isRunning());
  const std::vector<sim::InputFrame> consumed = runner.consumedFrames();
  ASSERT_EQ(static_cast<int>(consumed.size()), runner.steps());
  EXPECT_EQ(consumed.back(), frame);
  EXPECT_FALSE(consumed.front().hand(sim::Hand::Right).tracked);
  // stopped means stopped: no step after stop() returned
  const int after = runner.steps();
  QTest::qWait(50);
  EXPECT_EQ(runner.steps(), after);
}

// What the trainee sees is what is scored: a live attempt steps deterministically (attempt
// page), so the frames it consumed replay to the very states it showed, however slow a step.
TEST(SimulationRunner, ALiveDeterministicRunReplaysToTheStatesItShowed) {
  SimulationRunner live;
  ASSERT_TRUE(live.load(kShippedScene, sim::StepMode::Deterministic));
  std::vector<sim::InputFrame> frames = stitchFrames();
  frames.resize(std::min<std::size_t>(frames.size(), 120));
  live.start();
  for (const sim::InputFrame& f : frames) {
    const int before = live.steps();
    live.submitFrame(f);
    QTRY_VERIFY_WITH_TIMEOUT(live.steps() > before, 10000);
  }
  live.stop();
  const std::uint64_t shown = live.stateHash();
  const std::vector<sim::InputFrame> consumed = live.consumedFrames();
  ASSERT_EQ(static_cast<int>(consumed.size()), live.steps());

  SimulationRunner scored;
  ASSERT_TRUE(scored.load(kShippedScene, sim::StepMode::Deterministic));
  testing::QueuedSignalSpy finished(&scored, &SimulationRunner::replayFinished);
  scored.replay(consumed);
  ASSERT_TRUE(finished.count() > 0 || finished.wait(60000));
  EXPECT_EQ(scored.stateHash(), shown);
  EXPECT_EQ(scored.pierces().size(), live.pierces().size());
}

TEST(SimulationRunner, DestroyedWhileRunningOrReplayingStopsCleanly) {
  {
    auto runner = std::make_unique<SimulationRunner>();
    ASSERT_TRUE(runner->load(kShippedScene, sim::StepMode::RealTime));
    testing::QueuedSignalSpy snapshots(runner.get(), &SimulationRunner::snapshotReady);
    runner->start();
    ASSERT_TRUE(snapshots.wait(10000));
    runner.reset();  // joins the thread; a hang or a crash fails the test
  }
  {
    auto runner = std::make_unique<SimulationRunner>();
    ASSERT_TRUE(runner->load(kShippedScene, sim::StepMode::Deterministic));
    testing::QueuedSignalSpy snapshots(runner.get(), &SimulationRunner::snapshotReady);
    runner->replay(stitchFrames());
    ASSERT_TRUE(snapshots.wait(10000));
    runner.reset();
  }
  SUCCEED();
}

TEST(SimulationRunner, ASnapshotHeldByTheReaderStaysUntouched) {
  SimulationRunner runner;
  ASSERT_TRUE(runner.load(kShippedScene, sim::StepMode::Deterministic));
  const auto held = runner.latestSnapshot();
  const std::vector<float> positions = held->tissuePositions;
  testing::QueuedSignalSpy finished(&runner, &SimulationRunner::replayFinished);
  std::vector<sim::InputFrame> frames = stitchFrames();
  frames.resize(std::min<std::size_t>(frames.size(), 200));
  runner.replay(frames);
  ASSERT_TRUE(finished.wait(60000));
  EXPECT_EQ(held->steps, 0);
  EXPECT_EQ(held->tissuePositions, positions);
  EXPECT_NE(runner.latestSnapshot(), held);
  EXPECT_EQ(runner.latestSnapshot()->steps, 200);
}

TEST(SimulationRunner, AMissingSceneFailsWithTheLoadersError) {
  SimulationRunner runner;
  sim::SceneError error;
  EXPECT_FALSE(runner.load(kSourceRoot + QStringLiteral("/resources/scenes/no_such.json"), sim::StepMode::RealTime, &error));
  EXPECT_FALSE(error.file.empty());
  EXPECT_FALSE(runner.isLoaded());
  EXPECT_EQ(runner.sceneDef(), nullptr);
  EXPECT_EQ(runner.latestSnapshot(), nullptr);
  runner.start();  // no scene: nothing to run
  EXPECT_FALSE(runner.isRunning());
}

}  // namespace
}  // namespace microsim::gui
