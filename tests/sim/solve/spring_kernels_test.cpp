#include "microsim/sim/solve/spring_kernels.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <cmath>

namespace microsim::sim {
namespace {

Link makeLink(double k, double rest, StiffnessLaw law = StiffnessLaw::Constant, double gain = 0.0) {
  Link l;
  l.a = 0;
  l.b = 1;
  l.k = k;
  l.rest = rest;
  l.law = law;
  l.gain = gain;
  return l;
}

// central differences of the energy and of the force with respect to x_a
void checkAgainstFiniteDifferences(const Link& link, const Vec3& xa, const Vec3& xb) {
  const double h = 1e-6;
  const Vec3 f = linkForce(link, xa, xb);
  Eigen::Matrix3d hessianFd;
  for (int d = 0; d < 3; ++d) {
    Vec3 plus = xa, minus = xa;
    plus[d] += h;
    minus[d] -= h;
    const double dE = (linkEnergy(link, plus, xb) - linkEnergy(link, minus, xb)) / (2 * h);
    EXPECT_NEAR(f[d], -dE, 1e-6 * (1.0 + f.norm())) << "force = -dE/dx_a, axis " << d;
    hessianFd.col(d) = -(linkForce(link, plus, xb) - linkForce(link, minus, xb)) / (2 * h);
  }
  const Eigen::Matrix3d hessian = linkHessian(link, xa, xb, false);
  EXPECT_LT((hessian - hessianFd).norm(), 1e-5 * (1.0 + hessian.norm()));
  EXPECT_LT((hessian - hessian.transpose()).norm(), 1e-12 * (1.0 + hessian.norm()));
}

TEST(SpringKernels, ConstantLawMatchesFiniteDifferencesInTensionAndCompression) {
  const Link link = makeLink(7.0, 1.3);
  checkAgainstFiniteDifferences(link, Vec3(0.1, -0.2, 0.3), Vec3(1.5, 0.7, -0.4));  // stretched
  checkAgainstFiniteDifferences(link, Vec3(0.1, -0.2, 0.3), Vec3(0.6, 0.1, 0.2));   // compressed
}

TEST(SpringKernels, StiffeningLawMatchesFiniteDifferences) {
  const Link link = makeLink(3.0, 0.8, StiffnessLaw::Stiffening, 40.0);
  checkAgainstFiniteDifferences(link, Vec3(0, 0, 0), Vec3(1.1, 0.3, 0.2));
  checkAgainstFiniteDifferences(link, Vec3(0, 0, 0), Vec3(0.3, 0.2, 0.1));
  // T = k0 Δ (1 + gain (Δ/r)²)
  const double l = 1.2, r = 0.8, d = l - r;
  EXPECT_NEAR(linkForce(link, Vec3::Zero(), Vec3(l, 0, 0)).x(), 3.0 * d * (1 + 40.0 * d * d / (r * r)),
              1e-12);
}

TEST(SpringKernels, ExponentialLawMatchesFiniteDifferences) {
  // b = 6, the vessel wall's exponent: stretched to strain 0.25 and 0.6, and compressed
  const Link link = makeLink(3.0, 0.8, StiffnessLaw::Exponential, 6.0);
  checkAgainstFiniteDifferences(link, Vec3(0, 0, 0), Vec3(0.9, 0.4, 0.2));
  checkAgainstFiniteDifferences(link, Vec3(0, 0, 0), Vec3(1.2, 0.5, 0.3));
  checkAgainstFiniteDifferences(link, Vec3(0, 0, 0), Vec3(0.3, 0.2, 0.1));
  // T = k0 r (e^{b s} − 1)/b, T' = k0 e^{b s}, E = k0 r² (e^{b s} − 1 − b s)/b²
  const double k = 3.0, r = 0.8, b = 6.0, l = 1.1, s = (l - r) / r;
  const Vec3 xb(l, 0, 0);
  EXPECT_NEAR(linkForce(link, Vec3::Zero(), xb).x(), k * r * std::expm1(b * s) / b, 1e-12);
  EXPECT_NEAR(linkHessian(link, Vec3::Zero(), xb).coeff(0, 0), k * std::exp(b * s), 1e-12);
  EXPECT_NEAR(linkEnergy(link, Vec3::Zero(), xb), k * r * r * (std::expm1(b * s) - b * s) / (b * b),
              1e-12);
}

TEST(SpringKernels, ExponentialLawIsContinuousWithItsSlopeAtZeroStrain) {
  // T and T' meet the constant law's k0 Δ and k0 at Δ = 0 from both sides
  const double k = 7.0, r = 0.5;
  const Stiffening c = stiffeningCoefficient(makeLink(k, r, StiffnessLaw::Exponential, 8.0));
  for (double h : {1e-9, 1e-7, 1e-5}) {
    const double d = (r + h) - r;  // the stretch the kernels see
    EXPECT_NEAR(springTension(k, r, c, r + h), k * d, k * d * (c.beta * d + 1e-12));  // k d (1 + βd/2 + …)
    EXPECT_NEAR(springTension(k, r, c, r - h), -k * h, 1e-12);
    EXPECT_NEAR(springTensionDerivative(k, r, c, r + h), k, 1e-3 * k);
    EXPECT_DOUBLE_EQ(springTensionDerivative(k, r, c, r - h), k);
    EXPECT_NEAR(springEnergy(k, r, c, r + h), 0.5 * k * d * d, 1e-4 * k * d * d);
  }
  EXPECT_DOUBLE_EQ(springTension(k, r, c, r), 0.0);
  EXPECT_DOUBLE_EQ(springEnergy(k, r, c, r), 0.0);
  // across the series/expm1 switch of the energy (x = βΔ = 0.01) the energy is smooth
  const double dSwitch = 0.01 / c.beta;
  EXPECT_NEAR(springEnergy(k, r, c, r + dSwitch * (1 - 1e-12)), springEnergy(k, r, c, r + dSwitch * (1 + 1e-12)),
              1e-10 * springEnergy(k, r, c, r + dSwitch));
}

TEST(SpringKernels, ExponentialLawContinuesLinearlyPastItsKneeWithoutOverflow) {
  // strain 5 is the knee: beyond it T grows with the knee's slope, E and T stay finite
  const double k = 2.0, r = 1.0, b = 8.0;
  const Link link = makeLink(k, r, StiffnessLaw::Exponential, b);
  const Stiffening c = stiffeningCoefficient(link);
  const double knee = r * (1.0 + kExpStrainCap);
  const double slope = springTensionDerivative(k, r, c, knee);
  EXPECT_NEAR(slope, k * std::exp(b * kExpStrainCap), 1e-6 * slope);
  EXPECT_DOUBLE_EQ(springTensionDerivative(k, r, c, knee + 3.0), slope);
  EXPECT_NEAR(springTension(k, r, c, knee + 3.0), springTension(k, r, c, knee) + 3.0 * slope, 1e-9 * slope);
  checkAgainstFiniteDifferences(link, Vec3(0, 0, 0), Vec3(knee + 0.5, 0.1, 0));
  EXPECT_TRUE(std::isfinite(linkEnergy(link, Vec3::Zero(), Vec3(1e6, 0, 0))));
  EXPECT_TRUE(linkForce(link, Vec3::Zero(), Vec3(1e6, 0, 0)).allFinite());
  // a huge exponent is capped at kExpMaxExponent before the strain cap
  const Link steep = makeLink(k, r, StiffnessLaw::Exponential, 1e4);
  EXPECT_TRUE(linkHessian(steep, Vec3::Zero(), Vec3(3.0, 0, 0)).allFinite());
  EXPECT_NEAR(linkHessian(steep, Vec3::Zero(), Vec3(3.0, 0, 0)).coeff(0, 0), k * std::exp(kExpMaxExponent),
              1e-9 * k * std::exp(kExpMaxExponent));
  // b = 0 or a zero rest length is the constant law
  EXPECT_TRUE(stiffeningCoefficient(makeLink(k, r, StiffnessLaw::Exponential, 0.0)).linear());
  EXPECT_TRUE(stiffeningCoefficient(makeLink(k, 0.0, StiffnessLaw::Exponential, 6.0)).linear());
}

TEST(SpringKernels, ForceIsHookesLaw) {
  const Link link = makeLink(10.0, 1.0);
  const Vec3 f = linkForce(link, Vec3::Zero(), Vec3(0, 0, 3.0));
  EXPECT_DOUBLE_EQ(f.z(), 20.0);  // pulled towards b by k (l − r)
  EXPECT_DOUBLE_EQ(linkEnergy(link, Vec3::Zero(), Vec3(0, 0, 3.0)), 20.0);
}

TEST(SpringKernels, ClampedHessianIsPositiveSemidefinite) {
  const Link link = makeLink(5.0, 2.0);
  const Eigen::Matrix3d raw = linkHessian(link, Vec3::Zero(), Vec3(0.5, 0.1, 0), false);
  const Eigen::Matrix3d clamped = linkHessian(link, Vec3::Zero(), Vec3(0.5, 0.1, 0), true);
  EXPECT_LT(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(raw).eigenvalues().minCoeff(), 0.0);
  EXPECT_GE(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(clamped).eigenvalues().minCoeff(), -1e-12);
}

TEST(SpringKernels, ZeroLengthSpringsAndCoincidentNodesStayFinite) {
  const Link zeroRest = makeLink(4.0, 0.0);
  EXPECT_TRUE(linkForce(zeroRest, Vec3::Zero(), Vec3(0, 1e-15, 0)).allFinite());
  EXPECT_NEAR(linkForce(zeroRest, Vec3::Zero(), Vec3(0, 2, 0)).y(), 8.0, 1e-12);
  checkAgainstFiniteDifferences(zeroRest, Vec3(0.2, 0, 0), Vec3(0.3, 0.4, -0.1));
  const Link nearZero = makeLink(4.0, 1e-9, StiffnessLaw::Stiffening, 100.0);
  EXPECT_TRUE(linkForce(nearZero, Vec3::Zero(), Vec3(0, 1, 0)).allFinite());
  // coincident nodes of a spring with rest > 0: no direction, no force, finite Hessian
  const Link positive = makeLink(4.0, 1.0);
  EXPECT_EQ(linkForce(positive, Vec3::Ones(), Vec3::Ones()), Vec3::Zero());
  EXPECT_TRUE(linkHessian(positive, Vec3::Ones(), Vec3::Ones(), true).allFinite());
  EXPECT_DOUBLE_EQ(linkEnergy(positive, Vec3::Ones(), Vec3::Ones()), 2.0);
}

TEST(SpringKernels, TotalsAndRelativeResidual) {
  SpringModel model;
  model.addNode(Vec3(0, 0, 0));
  model.addNode(Vec3(1, 0, 0));
  model.addNode(Vec3(2, 0, 0));
  model.addLink(0, 1, 10.0);
  model.addLink(1, 2, 30.0);
  model.setFixed(0);
  model.finalize();
  SpringControls controls;
  controls.add(2, Vec3(2.5, 0, 0));
  Points x = model.restPositions();
  x.col(2) = Vec3(2.5, 0, 0);

  Points f;
  totalForces(model, x, f);
  EXPECT_NEAR(f.col(1).x(), 15.0, 1e-12);  // 30 · 0.5 towards node 2
  EXPECT_NEAR(f.col(0).norm() + f.col(1).norm() + f.col(2).norm(), 30.0, 1e-12);
  EXPECT_DOUBLE_EQ(forceScale(model, controls), 30.0 * 0.5);
  EXPECT_NEAR(relativeResidual(model, x, controls), 1.0, 1e-12);
  EXPECT_NEAR(totalEnergy(model, x, freeMask(model, controls)), 0.5 * 30 * 0.25, 1e-12);

  // gravity only: the scale is the heaviest weight
  model.gravity = Vec3(0, 0, -9810);
  EXPECT_DOUBLE_EQ(forceScale(model, SpringControls{}), 9810.0);
}

// springTerms is springTension and springEnergy in one call: the same bits, for every law, on both
// sides of rest, of the series' switch, and of the exponential's knee
TEST(SpringKernels, SpringTermsGiveTheSeparateKernelsToTheBit) {
  const double k = 3.7, r = 0.13;
  const Stiffening laws[] = {{}, {0.0, 6.0 / r}, {40.0 / (r * r), 0.0}, {0.0, 400.0 / r}};
  for (const Stiffening& c : laws) {
    const double knee = c.beta > 0.0 ? detail::springExpKnee(r, c.beta) : 1.0;
    const double switchAt = c.beta > 0.0 ? detail::kSeriesBelow / c.beta : 0.0;
    for (const double l :
         {0.0, 0.5 * r, r, r + 1e-9, r + switchAt * (1 - 1e-9), r + switchAt,
          r + switchAt * (1 + 1e-9), 1.3 * r, r + knee, r + knee * (1 + 1e-9), 9.0 * r}) {
      const SpringTerms t = springTerms(k, r, c, l);
      EXPECT_EQ(t.tension, springTension(k, r, c, l)) << "length " << l << " beta " << c.beta;
      EXPECT_EQ(t.energy, springEnergy(k, r, c, l)) << "length " << l << " beta " << c.beta;
    }
  }
}

}  // namespace
}  // namespace microsim::sim
