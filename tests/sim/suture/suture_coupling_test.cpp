#include "microsim/sim/mesh/vessel.h"
#include "microsim/sim/solve/solver.h"
#include "microsim/sim/suture/suture_coupling.h"
#include "microsim/sim/suture/suture_solver.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace microsim::sim::suture {
namespace {

// the outer-surface face nearest `target` (by centroid)
int faceNear(const VesselMesh& v, const Vec3& target) {
  int best = v.outerSurface.begin;
  double bestDistance = 1e300;
  for (int f = v.outerSurface.begin; f < v.outerSurface.end; ++f) {
    const auto& t = v.model.triangles()[static_cast<std::size_t>(f)];
    const Vec3 c = (v.model.restPositions().col(t[0]) + v.model.restPositions().col(t[1]) +
                    v.model.restPositions().col(t[2])) / 3.0;
    if ((c - target).norm() < bestDistance) {
      bestDistance = (c - target).norm();
      best = f;
    }
  }
  return best;
}

SutureModel thread(int links, double length) {
  SutureDef d;
  d.links = links;
  d.needleLinks = 0;
  d.length = length;
  return SutureModel(d);
}

TEST(SutureCoupling, PiercePointsFollowTheTissueAndPullsBecomeControls) {
  const VesselMesh v = vessel();
  const int face = faceNear(v, Vec3(2.5, 0, 0.5));
  const SutureModel m = thread(20, 2.0);
  SutureState s = SutureState::laidOut(m);
  Pierce p;
  p.face = face;
  p.barycentric = Vec3(0.2, 0.3, 0.5);
  p.node = 10;
  s.pierces.push_back(p);
  Points tx = v.model.restPositions();
  readPiercePoints(v.model, tx, s);
  EXPECT_LT((s.pierces[0].point - tissuePoint(v.model, tx, face, p.barycentric)).norm(), 1e-15);
  tx.colwise() += Vec3(0, 0, 0.25);
  readPiercePoints(v.model, tx, s);
  EXPECT_NEAR(s.pierces[0].point.z(), tissuePoint(v.model, v.model.restPositions(), face, p.barycentric).z() + 0.25, 1e-12);

  // both sides taut by 0.1 mm straight up: the pull is 0.2 mm up, on the face's three nodes
  const Vec3 P = s.pierces[0].point;
  const Grip g[2] = {{0, P + Vec3(0, 0, 1.1)}, {20, P + Vec3(0, 0, 1.1)}};
  const std::vector<PierceTension> tensions = pierceTensions(m, s, g);
  ASSERT_EQ(tensions.size(), 1u);
  EXPECT_LT((tensions[0].pull - Vec3(0, 0, 0.2)).norm(), 1e-12);
  const SpringControls c = couplingControls(v.model, tx, m, s, g);
  ASSERT_EQ(c.size(), 3);
  for (int k = 0; k < 3; ++k)
    EXPECT_LT((c.targets.col(k) - tx.col(c.nodes[static_cast<std::size_t>(k)]) - Vec3(0, 0, 0.2)).norm(), 1e-12);
}

// one frame of the coupled loop: read pierce points, step the suture, pull the tissue;
// returns the controls the tissue solved with
SpringControls frame(const SpringModel& tissue, SpringState& ts, TissueSolver& tsolver,
                     const SutureModel& m, SutureState& s, SutureSolver& ssolver,
                     std::span<const Grip> grips, double gain = 0.5) {
  readPiercePoints(tissue, ts.x, s);
  ssolver.step(m, s, grips, {});
  SpringControls controls = couplingControls(tissue, ts.x, m, s, grips, {gain});
  SolveBudget budget;
  budget.maxIterations = 20;
  tsolver.solve(tissue, ts, controls, budget);
  return controls;
}

// a 4 mm thread of 40 links through `face`, node 20 at the pierce, both halves straight up
void threadThroughFace(const VesselMesh& v, const SpringState& ts, int face, SutureState& s) {
  Pierce p;
  p.face = face;
  p.barycentric = Vec3(1.0 / 3, 1.0 / 3, 1.0 / 3);
  p.node = 20;
  s.pierces.push_back(p);
  readPiercePoints(v.model, ts.x, s);
  const Vec3 P = s.pierces[0].point;
  for (int i = 0; i <= 40; ++i) s.x.col(i) = P + Vec3(0.0, 0.0, 0.1 * std::abs(i - 20));
  s.x.col(0).x() -= 1e-3;  // two strands, not one
  s.xPrev = s.x;
}

TEST(SutureCoupling, APiercedSuturePulledAtBothEndsMovesTheVesselNodesNextToThePierce) {
  const VesselMesh v = vessel();
  const int face = faceNear(v, Vec3(2.75, 0, 0.5));
  const auto& tri = v.model.triangles()[static_cast<std::size_t>(face)];
  SpringState ts = SpringState::atRest(v.model);
  auto tsolver = makeSolver("newton");
  ASSERT_NE(tsolver, nullptr);

  const SutureModel m = thread(40, 4.0);
  SutureState s = SutureState::laidOut(m);
  threadThroughFace(v, ts, face, s);
  const Vec3 P = s.pierces[0].point;
  auto ssolver = makeSutureSolver("direct");

  // both ends pulled up 0.5 mm past taut
  for (int k = 1; k <= 50; ++k) {
    const double up = 2.0 + 0.01 * k;
    const Grip g[2] = {{0, P + Vec3(-1e-3, 0, up)}, {40, P + Vec3(0, 0, up)}};
    frame(v.model, ts, *tsolver, m, s, *ssolver, g);
    ASSERT_TRUE(ts.x.allFinite());
    ASSERT_TRUE(s.x.allFinite());
  }
  for (int node : tri)
    EXPECT_GT(ts.x(2, node) - v.model.restPositions()(2, node), 0.1) << node;
  // the clamped ring does not move
  for (int node : v.model.fixedNodes())
    EXPECT_EQ(ts.x.col(node), v.model.restPositions().col(node));
}

// A taut pierce whose excess the tissue has taken holds its face: the coupling's controls
// stay on from frame to frame instead of switching off and on (release, spring back, pull
// again), which made every other step of the fine scene a whole-vessel solve.
TEST(SutureCoupling, ATautPierceWithNoExcessKeepsItsControlFromFrameToFrame) {
  const VesselMesh v = vessel();
  const int face = faceNear(v, Vec3(2.75, 0, 0.5));
  const auto& tri = v.model.triangles()[static_cast<std::size_t>(face)];
  SpringState ts = SpringState::atRest(v.model);
  auto tsolver = makeSolver("newton");
  auto ssolver = makeSutureSolver("direct");
  const SutureModel m = thread(40, 4.0);
  SutureState s = SutureState::laidOut(m);
  threadThroughFace(v, ts, face, s);
  const Vec3 P = s.pierces[0].point;
  const auto pulledTo = [&](double up) {
    const Grip g[2] = {{0, P + Vec3(-1e-3, 0, up)}, {40, P + Vec3(0, 0, up)}};
    return frame(v.model, ts, *tsolver, m, s, *ssolver, g, 1.0);
  };

  // pulled 0.1 mm past taut over 10 frames, then held still for 6: the pierce stays taut
  // throughout, so its face's three nodes are controlled on every frame (the tissue takes
  // each frame's excess at once, and a frame with none left holds the face where it is)
  std::vector<int> controlCounts;
  for (int k = 1; k <= 10; ++k) controlCounts.push_back(pulledTo(2.0 + 0.01 * k).size());
  const Points heldAt = ts.x;
  for (int k = 0; k < 6; ++k) {
    const SpringControls c = pulledTo(2.1);
    controlCounts.push_back(c.size());
    for (int i = 0; i < c.size(); ++i)
      EXPECT_LT((c.targets.col(i) - heldAt.col(c.nodes[static_cast<std::size_t>(i)])).norm(), 1e-6);
  }
  EXPECT_EQ(controlCounts, std::vector<int>(16, 3));

  // the face stayed up where the pull left it; nothing sprang back
  for (int node : tri) {
    EXPECT_GT(ts.x(2, node) - v.model.restPositions()(2, node), 0.05) << node;
    EXPECT_LT((ts.x.col(node) - heldAt.col(node)).norm(), 1e-6) << node;
  }

  // the ends come down and the thread goes slack: the face is let go
  EXPECT_EQ(pulledTo(1.0).size(), 0);
}

TEST(SutureCoupling, PierceTensionsTellTautFromPulling) {
  const VesselMesh v = vessel();
  const SutureModel m = thread(40, 4.0);
  SutureState s = SutureState::laidOut(m);
  Pierce p;
  p.face = faceNear(v, Vec3(2.5, 0, 0.5));
  p.barycentric = Vec3(0.2, 0.3, 0.5);
  p.node = 20;
  s.pierces.push_back(p);
  const Points& rest = v.model.restPositions();
  readPiercePoints(v.model, rest, s);
  const Vec3 P = s.pierces[0].point;

  // both ends 1.99 mm from the pierce with 2 mm of thread each way: within a link of
  // straight, so taut, but with no excess to pull: the face is held where it is
  const Grip straight[2] = {{0, P + Vec3(0, 0, 1.99)}, {40, P + Vec3(0, 0, 1.99)}};
  std::vector<PierceTension> t = pierceTensions(m, s, straight);
  ASSERT_EQ(t.size(), 1u);
  EXPECT_TRUE(t[0].taut);
  EXPECT_TRUE(t[0].pull.isZero(0.0));
  const SpringControls held = couplingControls(v.model, rest, m, s, straight);
  ASSERT_EQ(held.size(), 3);
  for (int k = 0; k < 3; ++k)
    EXPECT_EQ(held.targets.col(k), rest.col(held.nodes[static_cast<std::size_t>(k)]));

  // both ends 1 mm from the pierce: slack, neither taut nor pulling, nothing held
  const Grip slack[2] = {{0, P + Vec3(0, 0, 1.0)}, {40, P + Vec3(0, 0, 1.0)}};
  t = pierceTensions(m, s, slack);
  EXPECT_FALSE(t[0].taut);
  EXPECT_TRUE(t[0].pull.isZero(0.0));
  EXPECT_EQ(couplingControls(v.model, rest, m, s, slack).size(), 0);
}

// A knot tied over two holes (a stay stitch's two outer holes, 0.6 mm apart): the thread leaves
// each hole for the knot 0.3 mm above their middle, and the hands hold its ends from there. The
// path from a hand through the knot, the holes and the knot to the other hand is never straight,
// so without the knot nothing reads taut; with it, what the hands reach past the thread pulls
// each hole towards the knot and the other hole, and a slack knot pulls nothing.
TEST(SutureCoupling, AKnotOverTheHolesCarriesTheHandsPullToThem) {
  const SutureModel m = thread(40, 4.0);  // links of 0.1 mm
  SutureState s = SutureState::laidOut(m);
  const Vec3 knot(0.3, 0.0, 0.3);
  for (const auto& [node, at] :
       {std::pair{15, Vec3(0.0, 0.0, 0.0)}, std::pair{25, Vec3(0.6, 0.0, 0.0)}}) {
    Pierce p;
    p.node = node;
    p.point = at;
    s.x.col(node) = at;
    s.pierces.push_back(p);
  }
  // the knot's passages, nodes 12 and 28: 1.6 mm of thread for a straight path of 0.849 + 0.6
  s.x.col(12) = knot;
  s.x.col(28) = knot + Vec3(0.0, 0.02, 0.0);
  const KnotOverStitch tied{12.0, 28.0, knotWrap(m, s, 12.0, 28.0)};
  EXPECT_NEAR(
      tied.wrap,
      1.6 - (knot - s.pierces[0].point).norm() - 0.6 - (s.x.col(28) - s.pierces[1].point).norm(),
      1e-12);

  // each hand 1.21 mm out from the knot on 1.2 mm of thread: 0.02 mm reached past it
  const auto hands = [&](double out) {
    return std::vector<Grip>{{0, knot + Vec3(-out, 0.0, 0.0)},
                             {40, Vec3(s.x.col(28)) + Vec3(out, 0.0, 0.0)}};
  };
  const std::vector<Grip> pulling = hands(1.21);
  EXPECT_FALSE(pierceTensions(m, s, pulling)[0].taut);  // no knot: the path is not straight
  std::vector<PierceTension> t = pierceTensions(m, s, pulling, tied);
  ASSERT_EQ(t.size(), 2U);
  for (std::size_t k = 0; k < 2; ++k) {
    const Vec3& at = s.pierces[k].point;
    const Vec3 toKnot = (s.x.col(k == 0 ? 12 : 28) - at).normalized();
    const Vec3 toOther = (s.pierces[1 - k].point - at).normalized();
    EXPECT_TRUE(t[k].taut) << k;
    EXPECT_LT((t[k].pull - 0.02 * (toKnot + toOther)).norm(), 1e-9) << k;
  }
  // the hands come in a little: the path still takes the thread, the holes are held, not pulled
  t = pierceTensions(m, s, hands(1.17), tied);
  EXPECT_TRUE(t[0].taut && t[1].taut);
  EXPECT_TRUE(t[0].pull.isZero(0.0) && t[1].pull.isZero(0.0));
  // and further: the knot's loop has slack, and it carries nothing
  t = pierceTensions(m, s, hands(1.0), tied);
  EXPECT_FALSE(t[0].taut || t[1].taut);
  EXPECT_TRUE(t[0].pull.isZero(0.0) && t[1].pull.isZero(0.0));
}

// two vessels facing each other across a gap, as one tissue model
VesselMesh twoVesselEnds(int& secondOffset) {
  VesselDef a;
  a.origin = Vec3(-3.3, 0, 0);
  VesselDef b;
  b.origin = Vec3(3.3, 0, 0);
  b.direction = -Vec3::UnitX();
  VesselMesh va = vessel(a);
  const VesselMesh vb = vessel(b);
  SpringModel both;
  const auto copy = [&](const SpringModel& src, int offset) {
    for (int i = 0; i < src.nodeCount(); ++i) {
      both.addNode(src.restPositions().col(i), src.mass(i), src.damping(i));
      if (src.isFixed(i)) both.setFixed(offset + i);
    }
    for (const Link& l : src.links()) both.addLink(offset + l.a, offset + l.b, l.k, l.rest);
    for (const auto& t : src.triangles()) both.addTriangle(offset + t[0], offset + t[1], offset + t[2]);
  };
  copy(va.model, 0);
  secondOffset = va.model.nodeCount();
  copy(vb.model, secondOffset);
  both.finalize();
  va.model = std::move(both);
  return va;
}

TEST(SutureCoupling, PullingAStitchThroughTwoVesselEndsBringsThemCloser) {
  int offset = 0;
  const VesselMesh v = twoVesselEnds(offset);
  const int triPerVessel = static_cast<int>(v.model.triangles().size()) / 2;
  // pierce faces: on top of each cut end (x = ∓0.3)
  const int fa = faceNear(v, Vec3(-0.55, 0, 0.5));
  int fb = fa;
  double best = 1e300;
  for (int f = triPerVessel; f < 2 * triPerVessel; ++f) {
    const auto& t = v.model.triangles()[static_cast<std::size_t>(f)];
    const Vec3 c = (v.model.restPositions().col(t[0]) + v.model.restPositions().col(t[1]) +
                    v.model.restPositions().col(t[2])) / 3.0;
    if ((c - Vec3(0.55, 0, 0.5)).norm() < best) {
      best = (c - Vec3(0.55, 0, 0.5)).norm();
      fb = f;
    }
  }
  SpringState ts = SpringState::atRest(v.model);
  auto tsolver = makeSolver("newton");

  // 6 mm thread: left strand up from A (nodes 0..20), a slack bridge (20..40), right strand up
  const SutureModel m = thread(60, 6.0);
  SutureState s = SutureState::laidOut(m);
  for (int f : {fa, fb}) {
    Pierce p;
    p.face = f;
    p.barycentric = Vec3(1.0 / 3, 1.0 / 3, 1.0 / 3);
    s.pierces.push_back(p);
  }
  s.pierces[0].node = 20;
  s.pierces[1].node = 40;
  readPiercePoints(v.model, ts.x, s);
  const Vec3 A = s.pierces[0].point;
  const Vec3 B = s.pierces[1].point;
  for (int i = 0; i <= 20; ++i) s.x.col(i) = A + Vec3(0, 0, 0.1 * (20 - i));
  for (int i = 40; i <= 60; ++i) s.x.col(i) = B + Vec3(0, 0, 0.1 * (i - 40));
  for (int i = 21; i < 40; ++i) {
    const double t = (i - 20) / 20.0;
    s.x.col(i) = (1 - t) * A + t * B + Vec3(0, 0, -0.8 * std::sin(3.14159265 * t));  // sagging
  }
  s.xPrev = s.x;
  auto ssolver = makeSutureSolver("direct");
  const double gap0 = (B - A).norm();

  // pulled up 0.8 mm past the strands' length, then held
  for (int k = 1; k <= 80; ++k) {
    const double up = 2.0 + 0.02 * std::min(k, 40);
    const Grip g[2] = {{0, A + Vec3(0, 0, up)}, {60, B + Vec3(0, 0, up)}};
    frame(v.model, ts, *tsolver, m, s, *ssolver, g);
    ASSERT_TRUE(ts.x.allFinite());
  }
  readPiercePoints(v.model, ts.x, s);
  ASSERT_EQ(s.pierces.size(), 2u);
  // the bridge slid out to the strands, then pulled the two ends together
  EXPECT_GT(s.pierces[0].node, 20);
  EXPECT_LT(s.pierces[1].node, 40);
  EXPECT_LT((s.pierces[1].point - s.pierces[0].point).norm(), gap0 - 0.1);
  EXPECT_EQ(s.brokenLinkCount(), 0);
}

}  // namespace
}  // namespace microsim::sim::suture
