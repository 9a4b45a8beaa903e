// Tissue against tissue (collide/tissue_contact.h): two plates facing each other, which pairs
// are found, which are violations, the springs' normals, and a solve that keeps them apart.
#include "microsim/sim/collide/tissue_contact.h"

#include "microsim/sim/collide/point_triangle.h"
#include "microsim/sim/solve/solver.h"
#include "microsim/sim/solve/spring_kernels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace microsim::sim::collide {
namespace {

constexpr int kTissueContactCells = 6;        // cells per plate edge
constexpr double kTissueContactSpacing = 0.1;  // mm, finer than reach: a plate's own faces are near
constexpr int kTissueContactPlateNodes = (kTissueContactCells + 1) * (kTissueContactCells + 1);
constexpr int kTissueContactPlateFaces = 2 * kTissueContactCells * kTissueContactCells;

/// Plate A (nodes and faces first) in z = 0 wound towards +z, plate B at rest in z = 1
/// wound towards −z: they face each other. Links along every triangle edge, stiffness 10;
/// `fixA` fixes plate A.
SpringModel tissueContactPlates(bool fixA = false) {
  SpringModel model;
  const int m = kTissueContactCells + 1;
  const auto index = [m](int plate, int i, int j) { return plate * m * m + i + m * j; };
  for (int plate = 0; plate < 2; ++plate)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i)
        model.addNode(Vec3(i * kTissueContactSpacing, j * kTissueContactSpacing, plate));
  for (int plate = 0; plate < 2; ++plate)
    for (int j = 0; j < kTissueContactCells; ++j)
      for (int i = 0; i < kTissueContactCells; ++i) {
        const int a = index(plate, i, j), b = index(plate, i + 1, j);
        const int c = index(plate, i + 1, j + 1), d = index(plate, i, j + 1);
        if (plate == 0) {
          model.addTriangle(a, b, c);
          model.addTriangle(a, c, d);
        } else {
          model.addTriangle(a, c, b);
          model.addTriangle(a, d, c);
        }
        model.addLink(a, b, 10.0);
        model.addLink(a, d, 10.0);
        model.addLink(a, c, 10.0);
        if (i + 1 == kTissueContactCells) model.addLink(b, c, 10.0);
        if (j + 1 == kTissueContactCells) model.addLink(d, c, 10.0);
      }
  if (fixA)
    for (int i = 0; i < kTissueContactPlateNodes; ++i) model.setFixed(i);
  model.finalize();
  return model;
}

/// The plates' rest positions with plate B moved to height z (mm).
Points tissueContactPlateBAt(const SpringModel& model, double z) {
  Points x = model.restPositions();
  x.rightCols(kTissueContactPlateNodes).row(2).setConstant(z);
  return x;
}

bool tissueContactInA(int nodeOrFace, int perPlate) { return nodeOrFace < perPlate; }

TEST(TissueContact, PlatesBuildAsIntended) {
  const SpringModel model = tissueContactPlates();
  EXPECT_EQ(model.nodeCount(), 2 * kTissueContactPlateNodes);
  EXPECT_EQ(static_cast<int>(model.triangles().size()), 2 * kTissueContactPlateFaces);
  const TissueContact contact(model, {});
  EXPECT_EQ(static_cast<int>(contact.surfaceNodes().size()), model.nodeCount());
  // 0 means 20 times the stiffest link
  EXPECT_DOUBLE_EQ(contact.stiffness(), 200.0);
}

TEST(TissueContact, NearPairsEveryNodeWithAFaceOfTheOtherPlate) {
  const SpringModel model = tissueContactPlates();
  const TissueContact contact(model, {});
  const Points x = tissueContactPlateBAt(model, 0.05);
  const std::vector<TissueContactPair> pairs = contact.near(x);
  ASSERT_EQ(static_cast<int>(pairs.size()), model.nodeCount());
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    const TissueContactPair& pair = pairs[p];
    EXPECT_EQ(pair.node, static_cast<int>(p)) << "one pair per node, in node order";
    EXPECT_NE(tissueContactInA(pair.node, kTissueContactPlateNodes),
              tissueContactInA(pair.face, kTissueContactPlateFaces))
        << "node " << pair.node << " paired with face " << pair.face << " of its own plate";
    // and the face is right across the gap
    const auto& t = model.triangles()[static_cast<std::size_t>(pair.face)];
    const PointTriangleClosest q =
        closestPointTriangle(x.col(pair.node), x.col(t[0]), x.col(t[1]), x.col(t[2]));
    EXPECT_NEAR(q.distance, 0.05, 1e-12) << "node " << pair.node;
  }
}

TEST(TissueContact, PlatesApartOrAtRestGiveNoPairs) {
  const SpringModel model = tissueContactPlates();
  const TissueContact contact(model, {});
  EXPECT_TRUE(contact.near(tissueContactPlateBAt(model, 0.5)).empty());
  EXPECT_TRUE(contact.near(model.restPositions()).empty());
  // the same contact object, after the plates came near: the grid follows the positions
  EXPECT_FALSE(contact.near(tissueContactPlateBAt(model, 0.05)).empty());
  EXPECT_TRUE(contact.near(tissueContactPlateBAt(model, 0.5)).empty());
}

TEST(TissueContact, AKeptGridFindsWhatAFreshOneFinds) {
  // the grid built with B out of reach serves while no node moves half the slack (= reach)
  // from there; pairs that came within reach meanwhile are still found
  const SpringModel model = tissueContactPlates();
  const TissueContactParams params;
  const TissueContact kept(model, params);
  const Points built = tissueContactPlateBAt(model, 0.14);
  ASSERT_TRUE(kept.near(built).empty());
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::size_t found = 0;
  for (int trial = 0; trial < 20; ++trial) {
    SCOPED_TRACE(trial);
    // every node moved by less than half the slack, B mostly down towards A
    Points x = built;
    for (Eigen::Index i = 0; i < x.cols(); ++i) {
      Vec3 move(u(rng), u(rng), u(rng));
      if (i >= kTissueContactPlateNodes) move.z() = -1.0;
      x.col(i) += 0.49 * params.reach * move.normalized();
    }
    const TissueContact fresh(model, params);
    const std::vector<TissueContactPair> pairs = kept.near(x);
    EXPECT_EQ(pairs, fresh.near(x));
    EXPECT_EQ(kept.violations(x), fresh.violations(x));
    found += pairs.size();
  }
  EXPECT_GT(found, 0u);

  // a move past half the slack rebuilds it: from B 0.45 mm away to 0.05 mm, A's nodes find
  // B's faces, which were nowhere near A when the grid was built
  const TissueContact far(model, params);
  ASSERT_TRUE(far.near(tissueContactPlateBAt(model, 0.45)).empty());
  const Points close = tissueContactPlateBAt(model, 0.05);
  const std::vector<TissueContactPair> pairs = far.near(close);
  EXPECT_EQ(static_cast<int>(pairs.size()), model.nodeCount());
  EXPECT_EQ(pairs, TissueContact(model, params).near(close));
}

// Plate B brought down onto A 5 µm a query, from 0.2025 mm (clear of A by more than 1.5 reach:
// the queries that follow within a quarter reach of there are answered at once), on through
// 0.15 mm (no longer clear: every query looks again) into reach and past it: at every height the
// kept object gives the pairs and violations a fresh one gives, and the pairs do come.
TEST(TissueContact, QueriesWhileTheTissueStaysNearWhereItWasClearFindWhatAFreshOneFinds) {
  const SpringModel model = tissueContactPlates();
  const TissueContactParams params;
  const TissueContact kept(model, params);
  std::size_t found = 0;
  for (int k = 0; k <= 40; ++k) {
    const double z = 0.2025 - 0.005 * k;  // never at the reach itself
    SCOPED_TRACE(z);
    const Points x = tissueContactPlateBAt(model, z);
    const TissueContact fresh(model, params);
    const std::vector<TissueContactPair> pairs = kept.near(x);
    EXPECT_EQ(pairs, fresh.near(x));
    EXPECT_EQ(kept.violations(x), fresh.violations(x));
    EXPECT_EQ(pairs.empty(), z >= params.reach);
    found += pairs.size();
  }
  EXPECT_GT(found, 0u);
}

/// Contact on the plates with the rest-distance rule at `selfDistance` (mm).
TissueContact plateContactWithSelfDistance(const SpringModel& model, double selfDistance) {
  TissueContactParams params;
  params.selfDistance = selfDistance;
  return TissueContact(model, params);
}

// Without a self distance a plate still never touches itself: every one of its faces within
// reach of a node has a corner within three links of it (its own stretch of wall), while the
// other plate, joined to it by no link, is found as before.
TEST(TissueContact, WithoutSelfDistanceAPlateLeavesItsOwnWallAndFindsTheOther) {
  const SpringModel model = tissueContactPlates();
  const TissueContact contact = plateContactWithSelfDistance(model, 0.0);
  EXPECT_TRUE(contact.near(tissueContactPlateBAt(model, 0.5)).empty());
  const std::vector<TissueContactPair> pairs = contact.near(tissueContactPlateBAt(model, 0.05));
  EXPECT_EQ(static_cast<int>(pairs.size()), model.nodeCount());
  for (const TissueContactPair& pair : pairs)
    EXPECT_NE(tissueContactInA(pair.node, kTissueContactPlateNodes),
              tissueContactInA(pair.face, kTissueContactPlateFaces));
}

// The rest-distance rule: with a self distance past the plates' 1 mm at rest, the two plates
// are one stretch of wall to each other, and brought within 0.05 mm they still never pair (at
// the default 0.3 mm every node pairs: NearPairsEveryNodeWithAFaceOfTheOtherPlate).
TEST(TissueContact, ASelfDistancePastTheRestGapKeepsThePlatesFromPairing) {
  const SpringModel model = tissueContactPlates();
  const TissueContact contact = plateContactWithSelfDistance(model, 1.1);
  EXPECT_TRUE(contact.near(tissueContactPlateBAt(model, 0.05)).empty());
}

TEST(TissueContact, ViolationsAreNodesWithinHalfTheThicknessOrBehind) {
  const SpringModel model = tissueContactPlates();
  TissueContactParams params;
  params.thickness = 0.01;
  const TissueContact contact(model, params);
  // in front by more than half the thickness: none
  EXPECT_TRUE(contact.violations(tissueContactPlateBAt(model, 0.05)).empty());
  EXPECT_TRUE(contact.violations(tissueContactPlateBAt(model, 0.006)).empty());
  // within half the thickness in front, and pushed through: every node of both plates
  for (double z : {0.004, -0.02}) {
    SCOPED_TRACE(z);
    const std::vector<TissueContactPair> pairs = contact.violations(tissueContactPlateBAt(model, z));
    ASSERT_EQ(static_cast<int>(pairs.size()), model.nodeCount());
    for (const TissueContactPair& pair : pairs)
      EXPECT_NE(tissueContactInA(pair.node, kTissueContactPlateNodes),
                tissueContactInA(pair.face, kTissueContactPlateFaces));
  }
}

TEST(TissueContact, SpringsPushOutOfTheWoundSide) {
  const SpringModel model = tissueContactPlates();
  TissueContactParams params;
  params.thickness = 0.01;
  params.stiffness = 123.0;
  const TissueContact contact(model, params);
  for (double z : {0.05, -0.02}) {
    SCOPED_TRACE(z);
    const Points x = tissueContactPlateBAt(model, z);
    const std::vector<TissueContactPair> pairs = contact.near(x);
    ASSERT_EQ(static_cast<int>(pairs.size()), model.nodeCount());
    for (const TissueContactPair& pair : pairs) {
      const PointSpring s = contact.spring(pair, x);
      const bool nodeInA = tissueContactInA(pair.node, kTissueContactPlateNodes);
      // A is wound towards +z, B towards −z
      const Vec3 out = nodeInA ? Vec3(-Vec3::UnitZ()) : Vec3(Vec3::UnitZ());
      EXPECT_LT((s.normal - out).norm(), 1e-12) << "node " << pair.node;
      EXPECT_EQ(s.nodes[0], pair.node);
      EXPECT_EQ(s.size(), 4);
      EXPECT_EQ(s.gap, 0.01);
      EXPECT_EQ(s.k, 123.0);
      EXPECT_NEAR(s.weights[0] + s.weights[1] + s.weights[2] + s.weights[3], 0.0, 1e-12);
      // n·d is the node's signed distance in front of the face
      const Vec3 d = pointSpringOffset(s, x);
      const double front = z;  // B above A by z; both faces look at the other plate
      EXPECT_NEAR(s.normal.dot(d), front, 1e-12) << "node " << pair.node;
      // where the node is behind, the spring pushes it out along the normal
      const Vec3 f = pointSpringForce(s, d);
      if (front < s.gap) {
        EXPECT_NEAR(f.dot(out), 123.0 * (0.01 - front), 1e-9);
      } else {
        EXPECT_TRUE(f.isZero(0.0));
      }
    }
  }
}

TEST(TissueContact, PlatePulledThroughAFixedPlateStaysInFront) {
  // plate A fixed; every node of plate B pulled by a two-sided term towards 0.2 mm behind A;
  // the contact terms found at the start keep B in front of A by the thickness, less what
  // the pull's force compresses the contact by
  const SpringModel fixedA = tissueContactPlates(true);
  TissueContactParams params;
  params.thickness = 0.01;
  const TissueContact contact(fixedA, params);
  SpringState state = SpringState::atRest(fixedA);
  state.x = tissueContactPlateBAt(fixedA, 0.05);

  const double pull = 10.0;
  SpringControls controls;
  for (int i = kTissueContactPlateNodes; i < fixedA.nodeCount(); ++i) {
    PointSpring s;
    s.nodes[0] = i;
    s.weights[0] = 1.0;
    s.anchor = Vec3(state.x(0, i), state.x(1, i), -0.2);
    s.k = pull;
    controls.springs.push_back(s);
  }
  const std::vector<TissueContactPair> pairs = contact.near(state.x);
  ASSERT_EQ(static_cast<int>(pairs.size()), fixedA.nodeCount());
  for (const TissueContactPair& pair : pairs) controls.springs.push_back(contact.spring(pair, state.x));

  for (const char* name : {"newton", "reference"}) {
    SCOPED_TRACE(name);
    SpringState solved = state;
    auto solver = makeSolver(name);
    SolveBudget budget;
    budget.maxIterations = 100;
    budget.residualTolerance = 1e-9;
    const SolveReport r = solver->solve(fixedA, solved, controls, budget);
    EXPECT_EQ(r.status, SolveStatus::Converged);
    EXPECT_LE(relativeResidual(fixedA, solved.x, controls), 1e-9);
    for (int i = kTissueContactPlateNodes; i < fixedA.nodeCount(); ++i) {
      // A lies in z = 0 facing +z: B's signed distance in front of it is its height
      const double front = solved.x(2, i);
      const double force = pull * (front + 0.2);
      EXPECT_GE(front, params.thickness - force / contact.stiffness()) << "node " << i;
      // and the pull did bring it into contact
      EXPECT_LT(front, params.thickness) << "node " << i;
    }
    // A did not move
    EXPECT_EQ(solved.x.leftCols(kTissueContactPlateNodes), state.x.leftCols(kTissueContactPlateNodes));
  }
}

}  // namespace
}  // namespace microsim::sim::collide
