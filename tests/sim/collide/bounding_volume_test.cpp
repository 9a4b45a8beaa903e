#include "microsim/sim/collide/bounding_volume.h"

#include "sim/collide/brute_force.h"

#include <gtest/gtest.h>

namespace microsim::sim::collide {
namespace {

using brute::cubePoint;
using Eigen::Vector3d;
using brute::latticePoint;

// the smallest sphere through the candidates (edge diameters, circumsphere) holding all three
double bruteMinimalRadius(const Vector3d& a, const Vector3d& b, const Vector3d& c) {
  const std::array<Vector3d, 3> v{a, b, c};
  double best = std::numeric_limits<double>::infinity();
  const auto holdsAll = [&](const Vector3d& centre, double r) {
    for (const Vector3d& p : v)
      if ((p - centre).norm() > r * (1 + 1e-9) + 1e-12) return false;
    return true;
  };
  for (int i = 0; i < 3; ++i) {
    const Vector3d centre = 0.5 * (v[i] + v[(i + 1) % 3]);
    const double r = 0.5 * (v[i] - v[(i + 1) % 3]).norm();
    if (holdsAll(centre, r)) best = std::min(best, r);
  }
  // circumcentre: in the plane, equidistant from all three (least squares on 2 equations)
  const Vector3d ab = b - a, ac = c - a;
  Eigen::Matrix3d m;
  m.row(0) = ab.transpose();
  m.row(1) = ac.transpose();
  m.row(2) = ab.cross(ac).transpose();
  if (std::abs(m.determinant()) > 1e-12) {
    const Vector3d rhs(0.5 * ab.squaredNorm(), 0.5 * ac.squaredNorm(), 0.0);
    const Vector3d centre = a + m.partialPivLu().solve(rhs);
    const double r = (a - centre).norm();
    if (holdsAll(centre, r)) best = std::min(best, r);
  }
  return best;
}

TEST(BoundingVolume, TriangleSphereIsSmallestAndEncloses) {
  std::mt19937 rng(41);
  for (int i = 0; i < 4000; ++i) {
    const bool lattice = i % 2 == 1;
    const Vector3d a = lattice ? latticePoint(rng) : cubePoint(rng);
    const Vector3d b = lattice ? latticePoint(rng) : cubePoint(rng);
    const Vector3d c = lattice ? latticePoint(rng) : cubePoint(rng);
    const Sphere s = fitSphere(a, b, c);
    for (const Vector3d* p : {&a, &b, &c}) EXPECT_LE((*p - s.centre).norm(), s.radius);
    EXPECT_NEAR(s.radius, bruteMinimalRadius(a, b, c), 1e-9);
  }
}

TEST(BoundingVolume, SegmentSphereAndBoxes) {
  const Sphere s = fitSphere(Vector3d(0, 0, 0), Vector3d(2, 0, 0));
  EXPECT_TRUE(s.centre.isApprox(Vector3d(1, 0, 0)));
  EXPECT_NEAR(s.radius, 1.0, 1e-11);
  const Aabb box = fitAabb(Vector3d(0, 1, 2), Vector3d(-1, 3, 0), Vector3d(2, 0, 1));
  EXPECT_LT((box.lo - Vector3d(-1, 0, 0)).norm(), 1e-10);
  EXPECT_LT((box.hi - Vector3d(2, 3, 2)).norm(), 1e-10);
  EXPECT_TRUE(near(box, Vector3d(3, 3, 2), 1.0));
  EXPECT_FALSE(near(box, Vector3d(3, 4, 2), 1.0));
  EXPECT_TRUE(overlaps(box, Aabb{Vector3d(2.5, 0, 0), Vector3d(3, 1, 1)}, 0.5));
  EXPECT_FALSE(overlaps(box, Aabb{Vector3d(2.5, 0, 0), Vector3d(3, 1, 1)}, 0.4));
}

TEST(BoundingVolume, MergedSphereEnclosesBothAndIsSmallest) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> radius(0.0, 1.0);
  for (int i = 0; i < 2000; ++i) {
    const Sphere s{cubePoint(rng), radius(rng)};
    const Sphere t{cubePoint(rng), radius(rng)};
    const Sphere m = mergeSpheres(s, t);
    for (const Sphere* child : {&s, &t})
      EXPECT_LE((child->centre - m.centre).norm() + child->radius, m.radius);
    const double d = (s.centre - t.centre).norm();
    const double smallest = std::max({s.radius, t.radius, 0.5 * (d + s.radius + t.radius)});
    EXPECT_NEAR(m.radius, smallest, 1e-9);
  }
}

}  // namespace
}  // namespace microsim::sim::collide
