#include "microsim/sim/suture/knot_recognition.h"

#include "bench/knot_geometry.h"

#include <gtest/gtest.h>

#include <numbers>
#include <random>

namespace microsim::sim::suture {
namespace {

using knot_test::ThreadBuilder;

KnotReading recognise(const ThreadBuilder& b) { return recogniseKnot(b.points(), b.anchors()); }

// the throws' handedness and wraps, in order, as "R1 L2 ..."
std::string throwsOf(const KnotReading& r) {
  std::string s;
  for (const KnotThrow& t : r.throws) {
    s += (s.empty() ? "" : " ");
    s += (t.handedness == Handedness::Right ? "R" : "L") + std::to_string(t.wraps);
  }
  return s;
}

TEST(KnotRecognition, UnknotWithExtraLoopsIsNone) {
  ThreadBuilder b;
  b.start(Vec3(-2.0, 0.0, 0.0));
  b.curve(knot_test::curls(Vec3::Zero()), 0.0, 6.0 * std::numbers::pi);  // three loops
  b.lineTo(b.last() + Vec3(2.0, 0.0, 0.0));
  const KnotReading r = recognise(b);
  EXPECT_EQ(r.type, KnotType::None);
  EXPECT_TRUE(r.throws.empty());
  EXPECT_EQ(r.crossings, 0);
}

TEST(KnotRecognition, OverhandLeftAndRight) {
  // an overhand whose tube turns about the thread like a left-handed screw is left-handed
  const KnotReading left = recognise(knot_test::throwsInARow({{1, false}}));
  EXPECT_EQ(left.type, KnotType::SingleThrow);
  EXPECT_EQ(throwsOf(left), "L1");
  ASSERT_EQ(left.throws.size(), 1U);
  EXPECT_EQ(left.throws[0].form, ThrowForm::Overhand);
  EXPECT_EQ(left.throws[0].crossings, 3);

  const KnotReading right = recognise(knot_test::throwsInARow({{1, true}}));
  EXPECT_EQ(right.type, KnotType::SingleThrow);
  EXPECT_EQ(throwsOf(right), "R1");
}

TEST(KnotRecognition, OverhandWithExtraLoopsInItsTails) {
  ThreadBuilder b;
  b.start(Vec3(-9.0, -1.8, 0.0));
  b.curve(knot_test::curls(Vec3(-8.0, -1.8, 0.0)), 0.0, 4.0 * std::numbers::pi);
  const auto f = knot_test::overhandCurve(1, true, Vec3::Zero());
  b.lineTo(f(2.0 * std::numbers::pi - 0.08));
  b.curve(f, 2.0 * std::numbers::pi - 0.08, 0.08);
  b.lineTo(Vec3(2.0, -1.8, 0.0));
  b.curve(knot_test::curls(Vec3(2.0, -1.8, 0.0)), 0.0, 4.0 * std::numbers::pi);
  const KnotReading r = recognise(b);
  EXPECT_EQ(r.type, KnotType::SingleThrow);
  EXPECT_EQ(throwsOf(r), "R1");
  EXPECT_EQ(r.unexplained, 0);
}

TEST(KnotRecognition, SquareAndGrannyDifferOnlyInTheSecondThrowsHandedness) {
  const KnotReading square = recognise(knot_test::throwsInARow({{1, true}, {1, false}}));
  EXPECT_EQ(square.type, KnotType::Square);
  EXPECT_EQ(throwsOf(square), "R1 L1");

  const KnotReading granny = recognise(knot_test::throwsInARow({{1, true}, {1, true}}));
  EXPECT_EQ(granny.type, KnotType::Granny);
  EXPECT_EQ(throwsOf(granny), "R1 R1");
}

TEST(KnotRecognition, SurgeonsKnotIsADoubleThrowThenASingleOfTheOtherHand) {
  const KnotReading surgeons = recognise(knot_test::throwsInARow({{2, false}, {1, true}}));
  EXPECT_EQ(surgeons.type, KnotType::Surgeons);
  EXPECT_EQ(throwsOf(surgeons), "L2 R1");

  // the same hand twice is a granny, however many wraps
  const KnotReading slipping = recognise(knot_test::throwsInARow({{2, false}, {1, false}}));
  EXPECT_EQ(slipping.type, KnotType::Granny);
}

TEST(KnotRecognition, HalfKnotRoundTheStitchIsOneThrowWithItsHandedness) {
  // the strands run opposite ways, so a right-handed screw reads left-handed (knot_geometry.h)
  const KnotReading a = recognise(knot_test::stitchTwist(1.0, true));
  EXPECT_EQ(a.type, KnotType::SingleThrow);
  EXPECT_EQ(throwsOf(a), "L1");
  ASSERT_EQ(a.throws.size(), 1U);
  EXPECT_EQ(a.throws[0].form, ThrowForm::Twist);

  const KnotReading b = recognise(knot_test::stitchTwist(1.0, false));
  EXPECT_EQ(throwsOf(b), "R1");

  // a surgeon's double throw: two wraps, four crossings
  const KnotReading d = recognise(knot_test::stitchTwist(2.0, false));
  EXPECT_EQ(d.type, KnotType::SingleThrow);
  EXPECT_EQ(throwsOf(d), "R2");

  // the same twist without anchors is no knot: the loop it sits on untwists
  const ThreadBuilder loose = knot_test::stitchTwist(2.0, false);
  EXPECT_EQ(recogniseKnot(loose.points(), {}).type, KnotType::None);
}

TEST(KnotRecognition, StrandsUntwistedRoundTheStitchAreNone) {
  EXPECT_EQ(recognise(knot_test::stitchTwist(0.0, true)).type, KnotType::None);
  // half a turn only lays one strand across the other
  EXPECT_EQ(recognise(knot_test::stitchTwist(0.5, true)).type, KnotType::None);
}

TEST(KnotRecognition, SlipKnotIsOneStrandWoundRoundTheOtherStraightOne) {
  const KnotReading hitch = recognise(knot_test::stitchTwist(2.0, true, true));
  EXPECT_EQ(hitch.type, KnotType::SlipKnot);
  ASSERT_EQ(hitch.throws.size(), 1U);
  EXPECT_EQ(hitch.throws[0].form, ThrowForm::Hitch);
  EXPECT_EQ(hitch.throws[0].wraps, 2);
}

TEST(KnotRecognition, TripleCrossingInOnePictureIsLookedPast) {
  // a straight strand along x at z = 0, and above it (z ≈ 1) a curl — the trochoid
  // x = t − 1.6 sin t, y = 1.6 cos t — whose double point (t = ±t*, t* = 1.6 sin t*) lies on
  // the strand: seen along z, three strands pass through one point. Then an overhand.
  double tStar = 1.6;
  for (int k = 0; k < 20; ++k) {
    tStar -= (tStar - 1.6 * std::sin(tStar)) / (1.0 - 1.6 * std::cos(tStar));
  }
  const double y0 = 1.6 * std::cos(tStar);
  const auto curl = [](double t) { return Vec3(t - 1.6 * std::sin(t), 1.6 * std::cos(t), 1.0 + 0.3 * std::sin(t)); };
  ThreadBuilder b;
  b.start(Vec3(-3.0, y0, 0.0)).lineTo(Vec3(3.0, y0, 0.0));
  b.lineTo(Vec3(5.0, -4.0, 0.0)).lineTo(Vec3(-4.0, -4.0, 0.0)).lineTo(curl(-std::numbers::pi));
  b.curve(curl, -std::numbers::pi, std::numbers::pi);
  const Vec3 knotAt(8.0, 2.0, 0.0);
  const auto f = knot_test::overhandCurve(1, false, knotAt);
  b.lineTo(f(2.0 * std::numbers::pi - 0.08));
  b.curve(f, 2.0 * std::numbers::pi - 0.08, 0.08);
  b.lineTo(knotAt + Vec3(3.0, -1.8, 0.0));

  const KnotDiagram along = projectKnot(b.points(), {}, Vec3::UnitZ());
  EXPECT_LT(along.quality, 0.1);

  KnotRecognitionDef def;
  def.directions = knot_test::withFirst(Vec3::UnitZ(), knotViewDirections(b.points()));
  const KnotReading r = recogniseKnot(b.points(), {}, def);
  EXPECT_EQ(r.type, KnotType::SingleThrow);
  EXPECT_EQ(throwsOf(r), "L1");
  // read from a clear picture, so not along z, even if from near it
  EXPECT_GE(r.quality, def.clearQuality);
  EXPECT_GT((r.direction - Vec3::UnitZ()).norm(), 1e-6);
}

TEST(KnotRecognition, StrandsParallelToTheViewAreLookedPast) {
  // seen along x, the square knot's tails and the piece between its throws are points
  const ThreadBuilder b = knot_test::throwsInARow({{1, true}, {1, false}});
  const KnotDiagram along = projectKnot(b.points(), {}, Vec3::UnitX());
  EXPECT_LT(along.quality, 0.5);

  KnotRecognitionDef def;
  def.directions = knot_test::withFirst(Vec3::UnitX(), knotViewDirections(b.points()));
  const KnotReading r = recogniseKnot(b.points(), {}, def);
  EXPECT_EQ(r.type, KnotType::Square);
  EXPECT_GE(r.quality, def.clearQuality);
  EXPECT_LT(std::abs(r.direction.dot(Vec3::UnitX())), 0.99);
}

TEST(KnotRecognition, RigidRotationsChangeNothing) {
  struct Case {
    const char* name;
    ThreadBuilder thread;
    KnotType type;
    std::string throws;
  };
  const std::vector<Case> cases = {
      {"overhand", knot_test::throwsInARow({{1, true}}), KnotType::SingleThrow, "R1"},
      {"square", knot_test::throwsInARow({{1, true}, {1, false}}), KnotType::Square, "R1 L1"},
      {"granny", knot_test::throwsInARow({{1, false}, {1, false}}), KnotType::Granny, "L1 L1"},
      {"surgeons", knot_test::throwsInARow({{2, true}, {1, false}}), KnotType::Surgeons, "R2 L1"},
      {"half knot", knot_test::stitchTwist(1.0, false), KnotType::SingleThrow, "R1"},
      {"slip knot", knot_test::stitchTwist(2.0, true, true), KnotType::SlipKnot, "L2"},
  };
  for (const Case& c : cases) {
    for (unsigned seed = 1; seed <= 8; ++seed) {
      const Points x = knot_test::moved(c.thread.points(), knot_test::randomRigidMotion(seed));
      const KnotReading r = recogniseKnot(x, c.thread.anchors());
      EXPECT_EQ(r.type, c.type) << c.name << " seed " << seed;
      EXPECT_EQ(throwsOf(r), c.throws) << c.name << " seed " << seed;
    }
  }
}

TEST(KnotRecognition, JitterOfAFifthOfALinkChangesNothing) {
  // every node moved by up to 0.01 mm (links are 0.05 mm) in a random direction
  struct Case {
    ThreadBuilder thread;
    KnotType type;
  };
  const std::vector<Case> cases = {
      {knot_test::throwsInARow({{1, true}, {1, false}}), KnotType::Square},
      {knot_test::throwsInARow({{1, false}, {1, false}}), KnotType::Granny},
      {knot_test::throwsInARow({{2, false}, {1, true}}), KnotType::Surgeons},
      {knot_test::stitchTwist(1.0, true), KnotType::SingleThrow},
  };
  std::mt19937 rng(19);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (const Case& c : cases) {
    Points x = c.thread.points();
    for (Eigen::Index i = 0; i < x.cols(); ++i) {
      x.col(i) += 0.01 / std::sqrt(3.0) * Vec3(unit(rng), unit(rng), unit(rng));
    }
    EXPECT_EQ(recogniseKnot(x, c.thread.anchors()).type, c.type);
  }
}

TEST(KnotRecognition, AKnotNoRuleExplainsIsUnknown) {
  // the figure-eight knot: its crossings have both signs, so it is no throw
  const KnotReading r = recognise(knot_test::figureEight());
  EXPECT_EQ(r.type, KnotType::Unknown);
  EXPECT_GE(r.unexplained, 4);
}

}  // namespace
}  // namespace microsim::sim::suture
