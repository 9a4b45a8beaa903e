#pragma once
// e^x and e^x − 1 for the exponential wall law, in plain double arithmetic.
//
// Why not libm's. glibc picks its exp and expm1 at load time by what the CPU offers: on a
// CPU with FMA it runs variants whose last bit can differ from the plain ones (the stitch's
// replay hash moved when the plain ones were forced, GLIBC_TUNABLES=glibc.cpu.hwcaps=
// -AVX2,-FMA,-AVX), so a replay's states would depend on the machine that scores it; and
// those variants, called from our SSE2 code, cost the spring law a third of a stitch's
// tissue time (perf, session 21), several times what their instruction counts say. Here
// the same source gives the same bits wherever it is built with the project's flags
// (no contraction into FMA, -ffp-contract=off), and inlines.
//
// Method (as fdlibm's): x = k ln2 + r with |r| ≤ ln2 / 2, ln2 split in two so that k ln2
// is exact in its high part; e^r − 1 by its Taylor series to r¹³/13! in Horner form (the
// first term left out, r¹⁴/14! < 5·10⁻¹⁸ relative, below half an ulp); then
// e^x = 2^k (1 + p) and e^x − 1 = 2^k (p + (1 − 2^−k)), whose (1 − 2^−k) is exact, so
// neither loses the small result to cancellation. e^x is within 2 ulp of the true value,
// e^x − 1 within 4 (tests, against the long double library over the law's range). Defined
// for |x| ≤ 700.

#include <bit>
#include <cmath>
#include <cstdint>

namespace microsim::sim::detail {

/// e^r − 1 for |r| ≤ ln2 / 2 (the reduced argument).
inline double expm1Reduced(double r) {
  // 1/n! as r (1 + r/2 (1 + r/3 (… (1 + r/13)))): the factors 1/n are rounded constants
  double t = 1.0 + r * (1.0 / 13.0);
  t = 1.0 + r * (1.0 / 12.0) * t;
  t = 1.0 + r * (1.0 / 11.0) * t;
  t = 1.0 + r * (1.0 / 10.0) * t;
  t = 1.0 + r * (1.0 / 9.0) * t;
  t = 1.0 + r * (1.0 / 8.0) * t;
  t = 1.0 + r * (1.0 / 7.0) * t;
  t = 1.0 + r * (1.0 / 6.0) * t;
  t = 1.0 + r * (1.0 / 5.0) * t;
  t = 1.0 + r * (1.0 / 4.0) * t;
  t = 1.0 + r * (1.0 / 3.0) * t;
  t = 1.0 + r * 0.5 * t;
  return r * t;
}

inline constexpr double kLn2High = 6.93147180369123816490e-01;  // ln2's leading 32 bits
inline constexpr double kLn2Low = 1.90821492927058770002e-10;   // ln2 − kLn2High
inline constexpr double kInvLn2 = 1.44269504088896338700e+00;
inline constexpr double kHalfLn2 = 0.5 * 0.6931471805599453;

/// x = k ln2 + r: k (the nearest integer to x / ln2) and r (|r| ≤ ln2 / 2 up to rounding).
inline double reduceByLn2(double x, int& k) {
  const double q = x * kInvLn2;
  k = static_cast<int>(q + (q < 0.0 ? -0.5 : 0.5));  // rounds half away from zero
  return (x - k * kLn2High) - k * kLn2Low;
}

/// 2^k, exactly, for −1022 ≤ k ≤ 1023 (built from its bits: ldexp is a library call).
inline double powerOfTwo(int k) {
  return std::bit_cast<double>(static_cast<std::uint64_t>(k + 1023) << 52);
}

/// e^x (|x| ≤ 700).
inline double exponential(double x) {
  int k = 0;
  const double r = reduceByLn2(x, k);
  return (1.0 + expm1Reduced(r)) * powerOfTwo(k);
}

/// e^x − 1 (|x| ≤ 700), accurate for small x too.
inline double exponentialMinusOne(double x) {
  if (std::abs(x) <= kHalfLn2) return expm1Reduced(x);
  int k = 0;
  const double r = reduceByLn2(x, k);
  const double p = expm1Reduced(r);
  if (k < 1 || k > 60) return (1.0 + p) * powerOfTwo(k) - 1.0;
  return (p + (1.0 - powerOfTwo(-k))) * powerOfTwo(k);
}

}  // namespace microsim::sim::detail
