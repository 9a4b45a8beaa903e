// The 3D mouse through the real libspnav, talking to a fake spacenavd on a temporary socket
// (fake_spacenavd.h): the protocol handshake, motion and button events, the daemon going
// away, and no daemon at all.
#include "tracking/spacenav_source.h"

#include "app/tracking/fake_spacenavd.h"

#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include <numbers>

namespace microsim::tracking {
namespace {

bool waitForSpacenavFrames(QSignalSpy& spy, int count) {
  while (spy.count() < count)
    if (!spy.wait(10000)) return spy.count() >= count;
  return true;
}

sim::InputFrame lastSpacenavFrame(const QSignalSpy& spy) { return spy.last().at(0).value<sim::InputFrame>(); }

// a view looking along −x: right is +y, up is +z, the viewer sits at +x
ViewAxes spacenavSideView() {
  return {Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX()};
}

sim::InputFrame spacenavStartTools() {
  sim::InputFrame f;
  for (int h = 0; h < sim::kHandCount; ++h) {
    f.hands[static_cast<std::size_t>(h)].tracked = true;
    f.hands[static_cast<std::size_t>(h)].position = Eigen::Vector3d(h == 0 ? -1.0 : 1.0, 0.0, 0.5);
  }
  return f;
}

bool realDaemonConfigured() {
  return QFile::exists(QStringLiteral("/var/run/spnav.sock")) || QFile::exists(QStringLiteral("/etc/spnavrc"));
}

TEST(SpacenavSource, TheCapMovesTurnsAndClosesTheActiveToolThroughLibspnav) {
  testing::FakeSpacenavd daemon;
  SpacenavSource source;
  source.setTools(spacenavStartTools());
  source.setViewAxesProvider(spacenavSideView);
  QSignalSpy frames(&source, &TrackerSource::frameReady);
  QSignalSpy hands(&source, &RateToolSource::activeHandChanged);
  source.start();
  ASSERT_TRUE(source.status().connected) << source.status().lastError.toStdString();
  ASSERT_TRUE(daemon.handshakeDone());
  // libspnav asked for protocol 1 (REQ_TAG | REQ_CHANGE_PROTO | 1)
  EXPECT_EQ(daemon.request(), 0x7faa5501);

  // full deflection to the right for 20 ms: 2 mm/s · 0.02 s along the view's right (+y)
  daemon.sendMotion({350, 0, 0, 0, 0, 0, 20});
  ASSERT_TRUE(waitForSpacenavFrames(frames, 1));
  const sim::InputFrame moved = lastSpacenavFrame(frames);
  const sim::InputFrame start = spacenavStartTools();
  EXPECT_LT((moved.hand(sim::Hand::Right).position - start.hand(sim::Hand::Right).position -
             Eigen::Vector3d(0, 0.04, 0)).norm(), 1e-12);
  EXPECT_EQ(moved.hand(sim::Hand::Left), start.hand(sim::Hand::Left));

  // button 0 held closes the active jaws; a resting cap sends nothing on
  daemon.sendButton(0, true);
  daemon.sendMotion({0, 0, 0, 0, 0, 0, 16});
  ASSERT_TRUE(waitForSpacenavFrames(frames, 2));
  EXPECT_EQ(lastSpacenavFrame(frames).hand(sim::Hand::Right).closure, 1.0);

  // button 1 switches to the left hand; twisting the cap (rz) rolls it about the view axis
  // toward the viewer: 60°/s for 50 ms
  daemon.sendButton(1, true);
  daemon.sendButton(1, false);
  daemon.sendMotion({0, 0, 0, 0, 0, 350, 50});
  ASSERT_TRUE(waitForSpacenavFrames(frames, 3));
  EXPECT_EQ(frames.count(), 3);
  ASSERT_EQ(hands.count(), 1);
  EXPECT_EQ(source.activeHand(), sim::Hand::Left);
  const sim::InputFrame turned = lastSpacenavFrame(frames);
  const Eigen::AngleAxisd roll(turned.hand(sim::Hand::Left).orientation);
  EXPECT_NEAR(roll.angle(), 3.0 * std::numbers::pi / 180.0, 1e-12);
  EXPECT_LT((roll.axis() - Eigen::Vector3d::UnitX()).norm(), 1e-9);
  EXPECT_EQ(turned.hand(sim::Hand::Left).position, start.hand(sim::Hand::Left).position);
  EXPECT_EQ(turned.hand(sim::Hand::Right).closure, 1.0);
  sim::InputRejection why{};
  EXPECT_TRUE(sim::validateSequence(turned, moved.time, why));

  // the daemon goes away: the tools stay (untracked), the link is down and says why
  QSignalSpy down(&source, &TrackerSource::linkDown);
  daemon.closeClient();
  ASSERT_TRUE(down.wait(10000));
  EXPECT_FALSE(source.status().connected);
  EXPECT_FALSE(source.status().lastError.isEmpty());
  EXPECT_FALSE(lastSpacenavFrame(frames).hand(sim::Hand::Left).tracked);
  EXPECT_FALSE(lastSpacenavFrame(frames).hand(sim::Hand::Right).tracked);
  source.stop();
}

TEST(SpacenavSource, TheThirdButtonSwapsTheActiveHandsForcepsForTheScissors) {
  testing::FakeSpacenavd daemon;
  SpacenavSource source;
  source.setTools(spacenavStartTools());
  QSignalSpy frames(&source, &TrackerSource::frameReady);
  source.start();
  ASSERT_TRUE(source.status().connected) << source.status().lastError.toStdString();
  ASSERT_TRUE(daemon.handshakeDone());

  // pressed: the scissors, taken up open; released: nothing more
  daemon.sendButton(2, true);
  daemon.sendButton(2, false);
  ASSERT_TRUE(waitForSpacenavFrames(frames, 1));
  EXPECT_EQ(lastSpacenavFrame(frames).hand(sim::Hand::Right).instrument, sim::Instrument::Scissors);
  EXPECT_EQ(lastSpacenavFrame(frames).hand(sim::Hand::Right).closure, 0.0);
  EXPECT_EQ(lastSpacenavFrame(frames).hand(sim::Hand::Left).instrument, sim::Instrument::Forceps);

  // the left button closes the blades as it closes jaws; pressed again, the forceps is back
  daemon.sendButton(0, true);
  ASSERT_TRUE(waitForSpacenavFrames(frames, 2));
  EXPECT_EQ(lastSpacenavFrame(frames).hand(sim::Hand::Right).closure, 1.0);
  daemon.sendButton(2, true);
  ASSERT_TRUE(waitForSpacenavFrames(frames, 3));
  EXPECT_EQ(frames.count(), 3);
  EXPECT_EQ(lastSpacenavFrame(frames).hand(sim::Hand::Right).instrument, sim::Instrument::Forceps);
  EXPECT_EQ(lastSpacenavFrame(frames).hand(sim::Hand::Right).closure, 0.0);
  source.stop();
}

TEST(SpacenavSource, WithoutADaemonItSaysSoAndProducesNothing) {
  if (realDaemonConfigured()) GTEST_SKIP() << "a spacenavd socket or /etc/spnavrc exists on this machine";
  QTemporaryDir dir;
  const bool wasSet = qEnvironmentVariableIsSet("SPNAV_SOCKET");
  const QByteArray previous = qgetenv("SPNAV_SOCKET");
  qputenv("SPNAV_SOCKET", dir.filePath(QStringLiteral("nobody-listens.sock")).toUtf8());
  SpacenavSource source;
  QSignalSpy frames(&source, &TrackerSource::frameReady);
  QSignalSpy down(&source, &TrackerSource::linkDown);
  source.start();
  if (wasSet)
    qputenv("SPNAV_SOCKET", previous);
  else
    qunsetenv("SPNAV_SOCKET");
  EXPECT_EQ(down.count(), 1);
  EXPECT_FALSE(source.status().connected);
  EXPECT_TRUE(source.status().lastError.contains(QStringLiteral("spacenavd")));
  source.readPending();  // nothing to read, no crash
  EXPECT_EQ(frames.count(), 0);
  source.stop();
}

}  // namespace
}  // namespace microsim::tracking
