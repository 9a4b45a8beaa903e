#include "microsim/sim/solve/exponential.h"

#include <gtest/gtest.h>

#include <cmath>

namespace microsim::sim::detail {
namespace {

constexpr double kUlp = 0x1p-52;

// relative error against the long double library (64-bit mantissa: 11 bits to spare)
double relativeError(double got, long double truth) {
  return static_cast<double>(std::fabs((static_cast<long double>(got) - truth) / truth));
}

// the wall law's range (x = b·strain from 0 to the knee's 50) and a little below zero
TEST(Exponential, WithinTwoUlpOfTheTrueExponentialOverTheLawsRange) {
  double worst = 0.0;
  for (int i = 0; i <= 200000; ++i) {
    const double x = -1.0 + 51.0 * i / 200000.0;
    worst = std::max(worst, relativeError(exponential(x), std::exp(static_cast<long double>(x))));
  }
  EXPECT_LE(worst, 2.0 * kUlp);
  EXPECT_EQ(exponential(0.0), 1.0);
}

TEST(Exponential, MinusOneKeepsSmallArgumentsToFourUlp) {
  double worst = 0.0;
  for (int i = 0; i <= 200000; ++i) {
    const double x = -1.0 + 51.0 * i / 200000.0;
    if (x == 0.0) continue;
    worst = std::max(
        worst, relativeError(exponentialMinusOne(x), std::expm1(static_cast<long double>(x))));
  }
  // tiny strains, where e^x − 1 computed as e^x then − 1 would keep no digit
  for (int i = 0; i < 100; ++i) {
    const double x = 1e-14 * std::pow(1.37, i);  // up to 0.34
    worst = std::max(
        worst, relativeError(exponentialMinusOne(x), std::expm1(static_cast<long double>(x))));
  }
  EXPECT_LE(worst, 4.0 * kUlp);
  EXPECT_EQ(exponentialMinusOne(0.0), 0.0);
}

TEST(Exponential, PowersOfTwoAreExact) {
  for (int k = -1022; k <= 1023; k += 7) EXPECT_EQ(powerOfTwo(k), std::ldexp(1.0, k)) << k;
}

}  // namespace
}  // namespace microsim::sim::detail
