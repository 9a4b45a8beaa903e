// The instructor's replay player on the shipped stitch (resources/recordings/stitch.msrec on
// resources/scenes/anastomosis.json): seeks land on the state a straight deterministic replay
// has at that frame, and on the review page, with real widgets, the player plays, pauses, jumps
// to the first pierce from the timeline, steps by key, changes speed and scrubs back.
#include "gui/review/attempt_detail_view.h"
#include "gui/review/replay_controls.h"
#include "gui/review/replay_event_scan.h"
#include "gui/review/replay_player.h"
#include "gui/review/replay_timeline.h"
#include "gui/review/review_page.h"
#include "gui/simulation_runner.h"
#include "gui/viewport.h"
#include "microsim/assessment/storage/attempt_store.h"
#include "microsim/assessment/storage/people_store.h"
#include "microsim/assessment/storage/score_store.h"
#include "microsim/sim/scene/recording.h"
#include "microsim/sim/scene/render_snapshot.h"
#include "microsim/sim/scene/scene.h"
#include "support/shipped_files.h"

#include <QApplication>
#include <QComboBox>
#include <QFile>
#include <QHelpEvent>
#include <QProgressBar>
#include <QSignalSpy>
#include <QSlider>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>
#include <QToolTip>

#include <gtest/gtest.h>

#include <algorithm>
#include <variant>

namespace microsim::gui {
namespace {

// generous: the machine that runs the suite runs builds beside it
constexpr int kReplayTimeoutMs = 180000;

QByteArray shippedStitchBytes() {
  QFile file(testing::kShippedStitch);
  EXPECT_TRUE(file.open(QIODevice::ReadOnly));
  return file.readAll();
}

std::vector<sim::InputFrame> shippedStitchFrames() {
  sim::Recording rec;
  EXPECT_TRUE(sim::readRecording(testing::kShippedStitch.toStdString(), rec).ok());
  return rec.frames;
}

// the scene after a straight deterministic replay of the stitch's first `frames` frames
std::unique_ptr<sim::Scene> straightReplay(int frames) {
  auto opened = sim::openScene(testing::kShippedScene.toStdString(), sim::StepMode::Deterministic);
  EXPECT_TRUE(std::holds_alternative<std::unique_ptr<sim::Scene>>(opened));
  std::unique_ptr<sim::Scene> scene = std::move(std::get<std::unique_ptr<sim::Scene>>(opened));
  const std::vector<sim::InputFrame> all = shippedStitchFrames();
  for (int i = 0; i < frames; ++i) scene->step(all[std::size_t(i)]);
  return scene;
}

// the runner's state equals the straight replay's to the bit: hash, positions, pierces
void expectStraightReplayState(const ReplayPlayer& player, int frames) {
  const std::unique_ptr<sim::Scene> reference = straightReplay(frames);
  sim::RenderSnapshot expected;
  sim::fillSnapshot(*reference, expected);
  const std::shared_ptr<const sim::RenderSnapshot> shown = player.runner()->latestSnapshot();
  ASSERT_NE(shown, nullptr);
  EXPECT_EQ(shown->steps, frames);
  EXPECT_EQ(player.runner()->stateHash(), reference->hash());
  EXPECT_EQ(shown->tissuePositions, expected.tissuePositions);
  EXPECT_EQ(shown->suturePositions, expected.suturePositions);
  EXPECT_EQ(shown->pierceCount, expected.pierceCount);
}

// waits until the player has stepped everything handed over and stands at `position`
::testing::AssertionResult settlesAt(const ReplayPlayer& player, int position) {
  if (!QTest::qWaitFor([&] { return !player.isBusy(); }, kReplayTimeoutMs))
    return ::testing::AssertionFailure() << "still stepping towards " << player.target();
  if (player.position() != position)
    return ::testing::AssertionFailure() << "at " << player.position() << ", not " << position;
  return ::testing::AssertionSuccess();
}

TEST(ReplayPlayer, SeeksEitherWayGiveTheStraightReplaysState) {
  ReplayPlayer player;
  ASSERT_EQ(player.load(testing::kShippedScene, shippedStitchBytes()), ReplayLoad::Ok);
  EXPECT_EQ(player.frameCount(), int(shippedStitchFrames().size()));
  EXPECT_EQ(player.position(), 0);

  QSignalSpy settled(&player, &ReplayPlayer::settled);
  player.seek(300);
  EXPECT_TRUE(player.isBusy());
  EXPECT_FALSE(player.isRerunning());
  EXPECT_TRUE(settlesAt(player, 300));
  EXPECT_EQ(settled.count(), 1);
  expectStraightReplayState(player, 300);

  // backward: the scene is stepped again from the start
  player.seek(120);
  EXPECT_TRUE(player.isRerunning());
  EXPECT_TRUE(settlesAt(player, 120));
  EXPECT_FALSE(player.isRerunning());
  expectStraightReplayState(player, 120);

  player.stepForward();
  EXPECT_TRUE(settlesAt(player, 121));
  player.stepBackward();
  player.stepBackward();
  EXPECT_TRUE(settlesAt(player, 119));
  expectStraightReplayState(player, 119);

  player.seek(0);
  EXPECT_TRUE(settlesAt(player, 0));
  expectStraightReplayState(player, 0);
}

TEST(ReplayPlayer, ASeekDuringAChunkCountsItsLateEnd) {
  ReplayPlayer player;
  ASSERT_EQ(player.load(testing::kShippedScene, shippedStitchBytes()), ReplayLoad::Ok);
  // the second seek stops the first chunk wherever it is; its replayFinished arrives late
  player.seek(400);
  player.seek(50);
  player.seek(80);
  EXPECT_TRUE(settlesAt(player, 80));
  expectStraightReplayState(player, 80);
}

TEST(ReplayEventScan, FindsTheEventsOfAStraightReplay) {
  const std::vector<sim::InputFrame> all = shippedStitchFrames();
  auto def = sim::loadSceneDef(testing::kShippedScene.toStdString());
  ASSERT_TRUE(std::holds_alternative<sim::SceneDef>(def));
  ReplayEventScan scan;
  QSignalSpy done(&scan, &ReplayEventScan::finished);
  scan.start(std::get<sim::SceneDef>(def), all);
  ASSERT_TRUE(done.wait(kReplayTimeoutMs));
  const std::vector<sim::SceneEvent>& found = scan.events();
  const std::unique_ptr<sim::Scene> reference = straightReplay(int(all.size()));
  const std::vector<sim::SceneEvent>& expected = reference->events();
  ASSERT_EQ(found.size(), expected.size());
  ASSERT_FALSE(found.empty());
  for (std::size_t i = 0; i < found.size(); ++i) {
    EXPECT_EQ(found[i].kind, expected[i].kind);
    EXPECT_EQ(found[i].step, expected[i].step);
  }
}

class ReplayOnReviewPage : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(dir_.isValid());
    history_.setPasswordIterations(1000);
    ASSERT_TRUE(history_.open(dir_.filePath(QStringLiteral("history.sqlite"))).ok());
    const std::optional<qint64> instructor =
        assessment::PeopleStore(history_).addInstructor(QStringLiteral("Dr Grey"), QStringLiteral("correct horse"));
    ASSERT_TRUE(instructor);
    instructor_ = {*instructor, assessment::Role::Instructor};
    const std::optional<qint64> ana = assessment::PeopleStore(history_).addTrainee(QStringLiteral("Ana"));
    ASSERT_TRUE(ana);
    const std::optional<qint64> id =
        assessment::AttemptStore(history_).begin(*ana, QStringLiteral("03_single_stitch"), assessment::AttemptMode::Test);
    ASSERT_TRUE(id);
    attempt_ = *id;
    assessment::AttemptScore score;
    score.score = 66.0;
    score.rubricId = "03_single_stitch";
    score.rubricVersion = 1;
    ASSERT_TRUE(assessment::ScoreStore(history_).finish(attempt_, score, shippedStitchBytes()));
  }

  QTemporaryDir dir_;
  assessment::HistoryDatabase history_;
  assessment::Viewer instructor_;
  qint64 attempt_ = 0;
};

TEST_F(ReplayOnReviewPage, PausesJumpsToThePierceStepsChangesSpeedAndScrubsBack) {
  ReviewPage page(history_, instructor_);
  page.resize(1200, 800);
  page.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&page));
  page.showAttempt(attempt_);
  AttemptDetailView* detail = page.detailView();

  // play: the replay starts playing at the recorded pace
  ASSERT_TRUE(detail->startReplay());
  ReplayPlayer* player = detail->replayPlayer();
  ReplayControls* controls = detail->replayControls();
  ASSERT_NE(player, nullptr);
  ASSERT_NE(controls, nullptr);
  EXPECT_EQ(controls->slider()->maximum(), player->frameCount());
  EXPECT_TRUE(player->isPlaying());
  ASSERT_TRUE(QTest::qWaitFor([&] { return player->position() > 0; }, kReplayTimeoutMs));

  // pause (the button): the chunk in flight finishes and the player stays there
  QTest::mouseClick(controls->playButton(), Qt::LeftButton);
  EXPECT_FALSE(player->isPlaying());
  ASSERT_TRUE(QTest::qWaitFor([&] { return !player->isBusy(); }, kReplayTimeoutMs));
  EXPECT_EQ(player->position(), player->target());
  EXPECT_EQ(controls->slider()->value(), player->position());

  // Space plays and pauses too
  // the keys are shortcuts of the replay area: they act in the active window (under Xvfb,
  // without a window manager, the page is no longer active once the viewport is made)
  page.activateWindow();
  ASSERT_TRUE(QTest::qWaitForWindowActive(&page));
  detail->replayViewport()->setFocus();
  QTest::keyClick(detail->replayViewport(), Qt::Key_Space);
  EXPECT_TRUE(player->isPlaying());
  QTest::keyClick(detail->replayViewport(), Qt::Key_Space);
  EXPECT_FALSE(player->isPlaying());

  // the timeline shows the recording's pierces once scanned; a click on the first entry
  // shows the state at which it has happened: the pierce count steps from 0 to 1 there
  ReplayTimeline* timeline = controls->timeline();
  ASSERT_TRUE(QTest::qWaitFor([&] { return !timeline->marks().empty(); }, kReplayTimeoutMs));
  const auto& marks = timeline->marks();
  const auto firstPierce = std::find_if(marks.begin(), marks.end(),
                                        [](const ReplayMark& m) { return m.kind == ReplayMarkKind::PierceEntry; });
  ASSERT_NE(firstPierce, marks.end());
  const int pierceAt = firstPierce->position;
  ASSERT_GT(pierceAt, 1);
  // its tooltip names the first pass through a wall
  const QPoint onMark = timeline->markRect(int(firstPierce - marks.begin())).center();
  QHelpEvent hover(QEvent::ToolTip, onMark, timeline->mapToGlobal(onMark));
  QApplication::sendEvent(timeline, &hover);
  EXPECT_EQ(QToolTip::text(), ReplayTimeline::describe(*firstPierce));
  EXPECT_TRUE(QToolTip::text().contains(ReplayTimeline::tr("Pierce %1: the needle enters the wall").arg(1)));
  QTest::mouseClick(timeline, Qt::LeftButton, {}, onMark);
  ASSERT_TRUE(settlesAt(*player, pierceAt));
  EXPECT_EQ(controls->slider()->value(), pierceAt);
  EXPECT_EQ(player->runner()->latestSnapshot()->steps, pierceAt);
  EXPECT_EQ(player->runner()->latestSnapshot()->pierceCount, 1);

  // Left: one frame back, before the pierce; Right: on it again
  QTest::keyClick(detail->replayViewport(), Qt::Key_Left);
  ASSERT_TRUE(settlesAt(*player, pierceAt - 1));
  EXPECT_EQ(player->runner()->latestSnapshot()->pierceCount, 0);
  QTest::keyClick(detail->replayViewport(), Qt::Key_Right);
  ASSERT_TRUE(settlesAt(*player, pierceAt));
  EXPECT_EQ(player->runner()->latestSnapshot()->pierceCount, 1);
  expectStraightReplayState(*player, pierceAt);

  // 4×: the speed box sets the player's pace, and it plays on from the pierce
  QComboBox* speed = controls->speedBox();
  const auto& offered = ReplayControls::speeds();
  speed->setCurrentIndex(int(std::find(offered.begin(), offered.end(), 4.0) - offered.begin()));
  EXPECT_EQ(player->speed(), 4.0);
  QTest::mouseClick(controls->playButton(), Qt::LeftButton);
  EXPECT_TRUE(player->isPlaying());
  ASSERT_TRUE(QTest::qWaitFor([&] { return player->position() > pierceAt + 20; }, kReplayTimeoutMs));
  QTest::mouseClick(controls->playButton(), Qt::LeftButton);
  ASSERT_TRUE(QTest::qWaitFor([&] { return !player->isBusy(); }, kReplayTimeoutMs));

  // scrub back: the scene is stepped again from the start, with its progress shown, to the
  // state of a straight replay at that frame
  const int back = pierceAt / 2;
  controls->slider()->setValue(back);
  EXPECT_TRUE(player->isRerunning());
  EXPECT_TRUE(controls->rerunProgress()->isVisible());
  ASSERT_TRUE(settlesAt(*player, back));
  EXPECT_FALSE(controls->rerunProgress()->isVisible());
  EXPECT_EQ(controls->slider()->value(), back);
  expectStraightReplayState(*player, back);

  // End and Home
  QTest::keyClick(detail->replayViewport(), Qt::Key_End);
  ASSERT_TRUE(settlesAt(*player, player->frameCount()));
  QTest::keyClick(detail->replayViewport(), Qt::Key_Home);
  ASSERT_TRUE(settlesAt(*player, 0));
}

}  // namespace
}  // namespace microsim::gui
