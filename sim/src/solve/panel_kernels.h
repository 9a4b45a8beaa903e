#pragma once
// The dense kernels of the supernodal Cholesky factorisation (supernodal_cholesky.h): products
// of 3-row slices of row-major panels, and the 3 by 3 pivot blocks.
//
// Why hand-written. Eigen's dynamic-size products choose their blocking by the CPU's cache sizes
// at run time, so the order of a sum, and its last bit, could differ between machines; the
// engine's replays must not (README, "Determinism"). Here the order is fixed by the code:
//   s(a, b) = Σ_{k even} p_a[k] q_b[k]  +  Σ_{k odd} p_a[k] q_b[k],
// each sum in increasing k, the even and odd ones in the two lanes of a pair of doubles (so
// SSE2, which every x86-64 CPU has, does two multiply-adds an instruction), added last. The
// compiler may vectorise or not: the rounding is the same (-ffp-contract=off, no reassociation).
// A 3 by 3 output block keeps 9 pairs of sums in registers while it reads 3 rows of each
// operand: 6 loads for 18 products. The lanes are GCC/Clang vector extensions, which compile to
// SSE2 on x86-64 and to NEON elsewhere.
//
// Layout. A panel is row-major: entry (i, k) at p[i·ld + k]. A "slice" is 3 consecutive rows
// (one node's x, y, z), starting at a row's first entry.

#include <cmath>
#include <cstring>

namespace microsim::sim::detail::panel {

using Pair = double __attribute__((vector_size(16)));

inline Pair loadPair(const double* p) {
  Pair v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

inline void storePair(double* p, Pair v) {
  std::memcpy(p, &v, sizeof v);
}

/// (a[0] + a[1], b[0] + b[1]): the lanes' sums of two pairs.
inline Pair laneSums(Pair a, Pair b) {
  return __builtin_shufflevector(a, b, 0, 2) + __builtin_shufflevector(a, b, 1, 3);
}

/// dst(a, b) −= Σ_{k<n} p[a·ld + k] q[b·ld + k] for a, b < 3: the 3 by 3 block P Qᵀ of two
/// slices (rows ld apart) taken from dst (rows ldd apart).
inline void subtractProduct(const double* p, const double* q, int ld, int n, double* dst, int ldd) {
  Pair s00{}, s01{}, s02{}, s10{}, s11{}, s12{}, s20{}, s21{}, s22{};
  const double *p0 = p, *p1 = p + ld, *p2 = p + 2 * ld;
  const double *q0 = q, *q1 = q + ld, *q2 = q + 2 * ld;
  int k = 0;
  for (; k + 1 < n; k += 2) {
    const Pair a0 = loadPair(p0 + k), a1 = loadPair(p1 + k), a2 = loadPair(p2 + k);
    const Pair b0 = loadPair(q0 + k), b1 = loadPair(q1 + k), b2 = loadPair(q2 + k);
    s00 += a0 * b0;
    s01 += a0 * b1;
    s02 += a0 * b2;
    s10 += a1 * b0;
    s11 += a1 * b1;
    s12 += a1 * b2;
    s20 += a2 * b0;
    s21 += a2 * b1;
    s22 += a2 * b2;
  }
  if (k < n) {
    // an odd last column joins the even lane
    const double a0 = p0[k], a1 = p1[k], a2 = p2[k], b0 = q0[k], b1 = q1[k], b2 = q2[k];
    s00[0] += a0 * b0;
    s01[0] += a0 * b1;
    s02[0] += a0 * b2;
    s10[0] += a1 * b0;
    s11[0] += a1 * b1;
    s12[0] += a1 * b2;
    s20[0] += a2 * b0;
    s21[0] += a2 * b1;
    s22[0] += a2 * b2;
  }
  // the lanes' sums, two entries at a time
  double* d1 = dst + ldd;
  double* d2 = d1 + ldd;
  const Pair last = laneSums(s02, s12);
  storePair(dst, loadPair(dst) - laneSums(s00, s01));
  storePair(d1, loadPair(d1) - laneSums(s10, s11));
  storePair(d2, loadPair(d2) - laneSums(s20, s21));
  dst[2] -= last[0];
  d1[2] -= last[1];
  d2[2] -= s22[0] + s22[1];
}

/// y(a) −= Σ_{k<n} p[a·ld + k] v[k] for a < 3: a slice times a vector.
inline void subtractSliceTimes(const double* p, int ld, const double* v, int n, double* y) {
  Pair s0{}, s1{}, s2{};
  const double *p0 = p, *p1 = p + ld, *p2 = p + 2 * ld;
  int k = 0;
  for (; k + 1 < n; k += 2) {
    const Pair b = loadPair(v + k);
    s0 += loadPair(p0 + k) * b;
    s1 += loadPair(p1 + k) * b;
    s2 += loadPair(p2 + k) * b;
  }
  if (k < n) {
    s0[0] += p0[k] * v[k];
    s1[0] += p1[k] * v[k];
    s2[0] += p2[k] * v[k];
  }
  const Pair first = laneSums(s0, s1);
  y[0] -= first[0];
  y[1] -= first[1];
  y[2] -= s2[0] + s2[1];
}

/// t[k] += (p[k] x[0] + p[ld + k] x[1]) + p[2·ld + k] x[2] for k < n: a slice's transpose times
/// a 3-vector.
inline void addSliceTransposedTimes(const double* p, int ld, const double* x, int n, double* t) {
  const double *p0 = p, *p1 = p + ld, *p2 = p + 2 * ld;
  const Pair x0 = {x[0], x[0]}, x1 = {x[1], x[1]}, x2 = {x[2], x[2]};
  int k = 0;
  for (; k + 1 < n; k += 2)
    storePair(t + k, loadPair(t + k) +
                         ((loadPair(p0 + k) * x0 + loadPair(p1 + k) * x1) + loadPair(p2 + k) * x2));
  if (k < n) t[k] += (p0[k] * x[0] + p1[k] * x[1]) + p2[k] * x[2];
}

/// The 3 by 3 pivot block x (rows ld apart; its lower triangle) into its Cholesky factor L
/// (x = L Lᵀ, L lower, in place), the inverses of L's diagonal into inv; false when x is not
/// positive definite.
inline bool factorPivot(double* x, int ld, double* inv) {
  double* x1 = x + ld;
  double* x2 = x1 + ld;
  const double d0 = x[0];
  if (!(d0 > 0.0)) return false;
  const double l00 = std::sqrt(d0), i0 = 1.0 / l00;
  const double l10 = x1[0] * i0, l20 = x2[0] * i0;
  const double d1 = x1[1] - l10 * l10;
  if (!(d1 > 0.0)) return false;
  const double l11 = std::sqrt(d1), i1 = 1.0 / l11;
  const double l21 = (x2[1] - l20 * l10) * i1;
  const double d2 = (x2[2] - l20 * l20) - l21 * l21;
  if (!(d2 > 0.0)) return false;
  const double l22 = std::sqrt(d2);
  x[0] = l00;
  x1[0] = l10;
  x1[1] = l11;
  x2[0] = l20;
  x2[1] = l21;
  x2[2] = l22;
  inv[0] = i0;
  inv[1] = i1;
  inv[2] = 1.0 / l22;
  return true;
}

/// y = y L⁻ᵀ for a pivot's factor L (lower, with the inverses of its diagonal): 3 by 3 blocks,
/// rows ld apart.
inline void solveAgainstPivot(const double* l, const double* inv, double* y, int ld) {
  const double l10 = l[ld], l20 = l[2 * ld], l21 = l[2 * ld + 1];
  for (int c = 0; c < 3; ++c) {
    double* yc = y + c * ld;
    const double y0 = yc[0] * inv[0];
    const double y1 = (yc[1] - y0 * l10) * inv[1];
    const double y2 = ((yc[2] - y0 * l20) - y1 * l21) * inv[2];
    yc[0] = y0;
    yc[1] = y1;
    yc[2] = y2;
  }
}

/// v = L⁻¹ v for a pivot's factor L (rows ld apart) and a 3-vector v.
inline void forwardPivot(const double* l, int ld, const double* inv, double* v) {
  v[0] = v[0] * inv[0];
  v[1] = (v[1] - l[ld] * v[0]) * inv[1];
  v[2] = ((v[2] - l[2 * ld] * v[0]) - l[2 * ld + 1] * v[1]) * inv[2];
}

/// v = L⁻ᵀ (v − t) for a pivot's factor L (rows ld apart) and 3-vectors v, t.
inline void backwardPivot(const double* l, int ld, const double* inv, const double* t, double* v) {
  v[2] = (v[2] - t[2]) * inv[2];
  v[1] = ((v[1] - t[1]) - l[2 * ld + 1] * v[2]) * inv[1];
  v[0] = (((v[0] - t[0]) - l[ld] * v[1]) - l[2 * ld] * v[2]) * inv[0];
}

}  // namespace microsim::sim::detail::panel
