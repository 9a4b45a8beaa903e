// Microscissors in the shipped scene: after the shipped stitch, scissors closed across the
// short tail a millimetre beyond the first entry cut it there and report the end left at the
// stitch; the needle keeps the rest, and a cut next to the needle reports a thread too short to
// tie; scissors that close beside the thread, or are taken up closed, cut nothing; frames with
// the scissors, written to a recording and read back, replay to the same state and cut.
#include "microsim/sim/scene/recording.h"
#include "microsim/sim/scene/scene.h"
#include "microsim/sim/suture/suture_model.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <variant>
#include <vector>

namespace microsim::sim {
namespace {

const std::string kRoot = MICROSIM_SOURCE_DIR;

SceneDef shippedScene() {
  SceneDefLoad load = loadSceneDef(kRoot + "/resources/scenes/anastomosis.json");
  EXPECT_TRUE(std::holds_alternative<SceneDef>(load));
  return std::get<SceneDef>(std::move(load));
}

/// The scene after the shipped stitch recording.
struct Stitched {
  std::unique_ptr<Scene> scene;
  InputFrame last;
};

Stitched stitched() {
  Recording rec;
  EXPECT_TRUE(readRecording(kRoot + "/resources/recordings/stitch.msrec", rec).ok());
  Stitched s{std::make_unique<Scene>(shippedScene()), rec.frames.back()};
  for (const InputFrame& f : rec.frames) s.scene->step(f);
  return s;
}

/// The point `arc` mm along the thread from chain node `from` towards its free end, and the
/// thread's direction there.
std::pair<Vec3, Vec3> pointTowardsTail(const suture::SutureState& st, int from, double arc) {
  double walked = 0.0;
  for (int n = from; n + 1 < st.x.cols(); ++n) {
    const Vec3 step = st.x.col(n + 1) - st.x.col(n);
    if (walked + step.norm() >= arc) {
      const double f = (arc - walked) / step.norm();
      return {st.x.col(n) + f * step, step.normalized()};
    }
    walked += step.norm();
  }
  return {st.x.col(st.x.cols() - 1), Vec3::UnitX()};
}

/// Scissors with their blades across the thread at `point` (tangent `along`): the thread
/// lies in the blades' plane, 0.2 mm behind the tip, the blades coming down from above.
HandInput scissorsAcross(const Vec3& point, const Vec3& along, double closure) {
  Vec3 back = Vec3::UnitZ() - Vec3::UnitZ().dot(along) * along;  // up, square to the thread
  back.normalize();
  Eigen::Matrix3d r;
  r.col(0) = back;
  r.col(1) = along;
  r.col(2) = back.cross(along);
  HandInput h;
  h.instrument = Instrument::Scissors;
  h.tracked = true;
  h.position = point - 0.2 * back;
  h.orientation = Eigen::Quaterniond(r);
  h.closure = closure;
  return h;
}

/// Frames after `last`: the right hand takes the scissors open, then closes them.
std::vector<InputFrame> closeScissors(const InputFrame& last, const HandInput& open) {
  std::vector<InputFrame> frames;
  double t = last.time;
  for (int k = 0; k <= 10; ++k) {
    InputFrame f = last;
    t += 0.01;
    f.time = t;
    f.hand(Hand::Right) = open;
    f.hand(Hand::Right).closure = k <= 3 ? 0.0 : std::min(1.0, (k - 3) / 5.0);
    frames.push_back(f);
  }
  return frames;
}

std::vector<SceneEvent> eventsOf(const Scene& scene, SceneEventKind kind) {
  std::vector<SceneEvent> out;
  for (const SceneEvent& e : scene.events())
    if (e.kind == kind) out.push_back(e);
  return out;
}

/// The pierce nearest the thread's free end (the first entry, where the short tail hangs).
int pierceNodeNearestTail(const suture::SutureState& st) {
  int node = -1;
  for (const suture::Pierce& p : st.pierces) node = std::max(node, p.node);
  return node;
}

TEST(ScissorsCut, TheThreadIsCutWhereTheBladesCloseAndTheEndIsMeasured) {
  Stitched s = stitched();
  Scene& scene = *s.scene;
  const suture::SutureState& st = *scene.sutureState();
  ASSERT_FALSE(st.pierces.empty());
  const int anchor = pierceNodeNearestTail(st);
  ASSERT_GT(anchor, scene.sutureModel()->swage());
  const auto [point, along] = pointTowardsTail(st, anchor, 1.0);
  const int brokenBefore = st.brokenLinkCount();

  for (const InputFrame& f : closeScissors(s.last, scissorsAcross(point, along, 0.0))) scene.step(f);

  const std::vector<SceneEvent> cuts = eventsOf(scene, SceneEventKind::ThreadCut);
  ASSERT_EQ(cuts.size(), 1u);
  EXPECT_EQ(cuts[0].hand, 1);
  EXPECT_EQ(scene.sutureState()->brokenLinkCount(), brokenBefore + 1);
  EXPECT_FALSE(scene.sutureState()->alive[static_cast<std::size_t>(cuts[0].index)]);
  // the link cut is the one under the blades, and the end left at the stitch is the millimetre
  // the blades were put at (within a link's length: the cut is at a link, the thread moved)
  EXPECT_GE(cuts[0].index, anchor);
  // (the thread sags a little while the blades close): measured along the thread from the
  // first entry's node to the point on the cut link
  const Points& x = scene.sutureState()->x;
  double toLink = 0.0;
  for (int n = anchor; n < cuts[0].index; ++n) toLink += (x.col(n + 1) - x.col(n)).norm();
  const double linkLength = (x.col(cuts[0].index + 1) - x.col(cuts[0].index)).norm();
  EXPECT_GE(cuts[0].value, toLink - 1e-3);
  EXPECT_LE(cuts[0].value, toLink + linkLength + 1e-3);
  EXPECT_NEAR(cuts[0].value, 1.0, 0.3);
  // the needle keeps the thread from its swage to the cut (through the stitch); enough of it
  // to tie, or reported
  double kept = 0.0;
  for (int n = scene.sutureModel()->swage(); n < cuts[0].index + 1; ++n)
    kept += (scene.sutureState()->x.col(n + 1) - scene.sutureState()->x.col(n)).norm();
  const std::vector<SceneEvent> shorts = eventsOf(scene, SceneEventKind::ThreadTooShort);
  EXPECT_EQ(shorts.empty(), kept >= scene.def().needle->minTieLength);
  // the cut pieces stay finite as they fall
  EXPECT_TRUE(scene.sutureState()->x.allFinite());
}

TEST(ScissorsCut, ScissorsFramesWrittenToARecordingReplayToTheSameStateAndCut) {
  Recording rec;
  ASSERT_TRUE(readRecording(kRoot + "/resources/recordings/stitch.msrec", rec).ok());
  Stitched s = stitched();
  const suture::SutureState& st = *s.scene->sutureState();
  const auto [point, along] = pointTowardsTail(st, pierceNodeNearestTail(st), 1.0);
  for (const InputFrame& f : closeScissors(s.last, scissorsAcross(point, along, 0.0))) {
    s.scene->step(f);
    rec.frames.push_back(f);
  }
  ASSERT_EQ(eventsOf(*s.scene, SceneEventKind::ThreadCut).size(), 1u);

  // through a file, as an attempt writes it
  const std::string path =
      (std::filesystem::temp_directory_path() / ("microsim-scissors-" + std::to_string(::getpid()) + ".msrec")).string();
  RecordingWriter writer;
  ASSERT_TRUE(writer.open(path, rec.scene, rec.metadata).ok());
  for (const InputFrame& f : rec.frames) ASSERT_TRUE(writer.append(f).ok());
  ASSERT_TRUE(writer.finish().ok());
  Recording back;
  ASSERT_TRUE(readRecording(path, back).ok());
  std::remove(path.c_str());
  ASSERT_EQ(back.frames.size(), rec.frames.size());
  EXPECT_TRUE(std::equal(back.frames.begin(), back.frames.end(), rec.frames.begin()));
  EXPECT_EQ(back.frames.back().hand(Hand::Right).instrument, Instrument::Scissors);

  // replayed on a fresh scene: the same state to the bit, the same cut
  Scene replay(shippedScene());
  for (const InputFrame& f : back.frames) replay.step(f);
  EXPECT_EQ(replay.hash(), s.scene->hash());
  const std::vector<SceneEvent> live = eventsOf(*s.scene, SceneEventKind::ThreadCut);
  const std::vector<SceneEvent> replayed = eventsOf(replay, SceneEventKind::ThreadCut);
  ASSERT_EQ(replayed.size(), 1u);
  EXPECT_EQ(replayed[0].index, live[0].index);
  EXPECT_EQ(replayed[0].step, live[0].step);
  EXPECT_EQ(replayed[0].value, live[0].value);
}

TEST(ScissorsCut, ACutNextToTheNeedleLeavesTooLittleToTie) {
  Stitched s = stitched();
  Scene& scene = *s.scene;
  const suture::SutureState& st = *scene.sutureState();
  const int swage = scene.sutureModel()->swage();
  // across the thread's second link behind the swage (about 0.25 mm of thread)
  const Vec3 along = (st.x.col(swage + 2) - st.x.col(swage + 1)).normalized();
  const Vec3 point = 0.5 * (st.x.col(swage + 1) + st.x.col(swage + 2));
  for (const InputFrame& f : closeScissors(s.last, scissorsAcross(point, along, 0.0))) scene.step(f);
  const std::vector<SceneEvent> shorts = eventsOf(scene, SceneEventKind::ThreadTooShort);
  ASSERT_EQ(shorts.size(), 1u);
  EXPECT_LT(shorts[0].value, scene.def().needle->minTieLength);
  EXPECT_LT(shorts[0].value, 0.6);
}

TEST(ScissorsCut, BladesClosingBesideTheThreadCutNothing) {
  Stitched s = stitched();
  Scene& scene = *s.scene;
  const suture::SutureState& st = *scene.sutureState();
  const auto [point, along] = pointTowardsTail(st, pierceNodeNearestTail(st), 1.0);
  // the same scissors 1 mm above the thread
  HandInput open = scissorsAcross(point + Vec3(0.0, 0.0, 1.0), along, 0.0);
  for (const InputFrame& f : closeScissors(s.last, open)) scene.step(f);
  EXPECT_TRUE(eventsOf(scene, SceneEventKind::ThreadCut).empty());
  EXPECT_EQ(scene.sutureState()->brokenLinkCount(), 0);
}

TEST(ScissorsCut, ScissorsTakenUpClosedDoNotCut) {
  Stitched s = stitched();
  Scene& scene = *s.scene;
  const suture::SutureState& st = *scene.sutureState();
  const auto [point, along] = pointTowardsTail(st, pierceNodeNearestTail(st), 1.0);
  InputFrame f = s.last;
  f.time += 0.01;
  f.hand(Hand::Right) = scissorsAcross(point, along, 1.0);
  scene.step(f);
  f.time += 0.01;
  scene.step(f);
  EXPECT_TRUE(eventsOf(scene, SceneEventKind::ThreadCut).empty());
}

}  // namespace
}  // namespace microsim::sim
