#pragma once
// Threads tied in known knots, built from curves in code (tori, helices, trochoids), for the
// knot recognition tests, the scene's knot tests and `bench suture`'s knot rows. Every piece is
// sampled at about `kKnotTestLink` mm per link, as the suture's own links are; evenlySpaced()
// resamples a thread into equal links, as a suture's rest lengths are.

#include "microsim/sim/suture/knot_recognition.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <vector>

namespace microsim::sim::suture::knot_test {

inline constexpr double kKnotTestLink = 0.05;

/// A thread under construction: nodes appended piece by piece.
class ThreadBuilder {
 public:
  /// Appends the curve f(t), t from t0 to t1, sampled finely enough for kKnotTestLink links.
  ThreadBuilder& curve(const std::function<Vec3(double)>& f, double t0, double t1) {
    // the curve's length, from a fine sampling
    double length = 0.0;
    constexpr int kFine = 2000;
    for (int k = 1; k <= kFine; ++k) {
      length += (f(t0 + (t1 - t0) * k / kFine) - f(t0 + (t1 - t0) * (k - 1) / kFine)).norm();
    }
    const int links = std::max(1, static_cast<int>(std::ceil(length / kKnotTestLink)));
    for (int k = nodes_.empty() ? 0 : 1; k <= links; ++k) {
      nodes_.push_back(f(t0 + (t1 - t0) * k / links));
    }
    return *this;
  }
  /// Starts the thread at `p`.
  ThreadBuilder& start(const Vec3& p) {
    nodes_.push_back(p);
    return *this;
  }
  /// Appends a straight piece from the last node to `to`.
  ThreadBuilder& lineTo(const Vec3& to) {
    const Vec3 from = nodes_.back();
    return curve([from, to](double t) { return Vec3(from + t * (to - from)); }, 0.0, 1.0);
  }
  /// Marks the last node as held (a pierce).
  ThreadBuilder& anchor() {
    anchors_.push_back(static_cast<int>(nodes_.size()) - 1);
    return *this;
  }
  Vec3 last() const { return nodes_.back(); }
  Points points() const {
    Points x(3, static_cast<Eigen::Index>(nodes_.size()));
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      x.col(static_cast<Eigen::Index>(i)) = nodes_[i];
    }
    return x;
  }
  const std::vector<int>& anchors() const { return anchors_; }

 private:
  std::vector<Vec3> nodes_;
  std::vector<int> anchors_;
};

/// An overhand throw of `wraps` wraps in one strand: the (2, 2·wraps + 1) torus knot (radii 1 and
/// 0.5 mm, centred at `centre`) cut open where it is outermost, walked from its left end to its
/// right end, the cut facing −y. Its tube turns about the direction of travel (+φ) as
/// outside → top → inside, a left-handed screw; `mirror` flips z for a right-handed one. A
/// left-handed trefoil's crossings are all negative, so `mirror` gives Handedness::Right.
inline std::function<Vec3(double)> overhandCurve(int wraps, bool mirror, const Vec3& centre) {
  const int q = 2 * wraps + 1;
  const double h = mirror ? -1.0 : 1.0;
  return [q, h, centre](double phi) {
    const double r = 1.0 + 0.5 * std::cos(q * phi);
    // cut point (φ = 0, outermost) turned to face −y
    const Vec3 p(r * std::cos(2.0 * phi), r * std::sin(2.0 * phi), h * 0.5 * std::sin(q * phi));
    return Vec3(centre + Vec3(p.y(), -p.x(), p.z()));
  };
}

/// Throws in a row in one strand, left to right along x, 4 mm apart: for each, its wraps and
/// whether it is right-handed. Tails 3 mm long on either side, along the row's bottom line.
inline ThreadBuilder throwsInARow(const std::vector<std::pair<int, bool>>& throws) {
  constexpr double kGap = 0.08;  // the cut, in φ: the arc's ends sit 2·0.08·1.5 mm apart
  const double bottom = -1.5;
  ThreadBuilder b;
  b.start(Vec3(-3.3, bottom - 0.3, 0.0));
  for (std::size_t k = 0; k < throws.size(); ++k) {
    const auto f = overhandCurve(throws[k].first, throws[k].second, Vec3(4.0 * static_cast<double>(k), 0.0, 0.0));
    // walked from φ = 2π − gap (left end) back to φ = gap (right end)
    b.lineTo(f(2.0 * std::numbers::pi - kGap));
    b.curve(f, 2.0 * std::numbers::pi - kGap, kGap);
  }
  const double right = 4.0 * static_cast<double>(throws.size() - 1);
  b.lineTo(Vec3(right + 3.3, bottom - 0.3, 0.0));
  return b;
}

/// The stitch: the thread comes down (needle side) at x = +0.4, passes through the tissue below
/// z = 0 between two pierces (the anchors) and comes up (tail side) at x = −0.4. Above the
/// tissue the two strands twist about the z axis on a 0.25 mm radius for `turns` turns between
/// z = 0.5 and z = 0.5 + 0.4·turns: right-handed about +z when `rightScrew`. The needle strand
/// runs down and the tail strand up, so a right-handed screw's crossings are negative
/// (Handedness::Left): for strands running the same way they would be positive.
/// `hitch`: the needle strand stays straight on the axis and only the tail strand winds.
/// `lift` (mm) moves the twist up the strands, as a thread drawn through the knot does.
inline ThreadBuilder stitchTwist(double turns, bool rightScrew, bool hitch = false, double lift = 0.0) {
  const double radius = 0.25;
  const double low = 0.5 + lift;
  const double high = low + 0.4 * std::max(turns, 0.05);
  const double screw = rightScrew ? 1.0 : -1.0;
  const auto angle = [=](double z) { return screw * 2.0 * std::numbers::pi * turns * (z - low) / (high - low); };
  const double needleRadius = hitch ? 0.0 : radius;
  const auto needle = [=](double z) {
    return Vec3(needleRadius * std::cos(angle(z)), needleRadius * std::sin(angle(z)), z);
  };
  const auto tail = [=](double z) {
    const double a = angle(z) + std::numbers::pi;
    return Vec3(radius * std::cos(a), radius * std::sin(a), z);
  };
  const double end = angle(high);
  ThreadBuilder b;
  // needle side: from far above, out along the twist's last angle, down through the twist
  b.curve([&](double t) {
    return Vec3(needle(high) + (1.0 - t) * Vec3(2.0 * std::cos(end), 2.0 * std::sin(end), 2.0));
  }, 0.0, 1.0);
  b.curve(needle, high, low);
  b.lineTo(Vec3(needleRadius, 0.0, 0.25 + lift)).lineTo(Vec3(0.4, 0.0, 0.0)).anchor();
  // through the tissue: a bight below z = 0
  b.curve([](double t) { return Vec3(0.4 * std::cos(t), 0.0, -0.4 * std::sin(t)); }, 0.0, std::numbers::pi);
  b.anchor();
  // tail side: up into the twist, through it, and away opposite the needle strand
  b.lineTo(Vec3(-radius, 0.0, 0.25 + lift)).lineTo(tail(low));
  b.curve(tail, low, high);
  b.curve([&](double t) {
    return Vec3(tail(high) + t * Vec3(-2.0 * std::cos(end), -2.0 * std::sin(end), 2.0));
  }, 0.0, 1.0);
  return b;
}

/// The figure-eight knot, x = (2 + cos 2t) cos 3t, y = (2 + cos 2t) sin 3t, z = sin 4t, cut
/// open where it is outermost (t = 0), its ends led 3 mm out along x: its crossings have both
/// signs, so no throw accounts for them (KnotType::Unknown).
inline ThreadBuilder figureEight() {
  const auto f = [](double t) {
    return Vec3((2.0 + std::cos(2.0 * t)) * std::cos(3.0 * t),
                (2.0 + std::cos(2.0 * t)) * std::sin(3.0 * t), std::sin(4.0 * t));
  };
  ThreadBuilder b;
  b.start(f(0.03) + Vec3(3.0, 0.0, 0.0));
  b.lineTo(f(0.03));
  b.curve(f, 0.03, 2.0 * std::numbers::pi - 0.03);
  b.lineTo(f(-0.03) + Vec3(3.0, 0.0, 0.0));
  return b;
}

/// `x` (3 by m) scaled by `scale` about its first node and resampled into `links` links of
/// equal length along it: a thread a SutureModel of that length and link count can hold at rest.
inline Points evenlySpaced(const Points& x, double scale, int links) {
  std::vector<double> arc(static_cast<std::size_t>(x.cols()), 0.0);
  for (Eigen::Index i = 1; i < x.cols(); ++i) {
    arc[static_cast<std::size_t>(i)] = arc[static_cast<std::size_t>(i - 1)] + (x.col(i) - x.col(i - 1)).norm();
  }
  Points out(3, links + 1);
  std::size_t seg = 0;
  for (int k = 0; k <= links; ++k) {
    const double s = arc.back() * k / links;
    while (seg + 2 < arc.size() && arc[seg + 1] < s) {
      ++seg;
    }
    const double span = arc[seg + 1] - arc[seg];
    const double t = span > 0.0 ? std::clamp((s - arc[seg]) / span, 0.0, 1.0) : 0.0;
    const Vec3 p = x.col(static_cast<Eigen::Index>(seg)) +
                   t * (x.col(static_cast<Eigen::Index>(seg + 1)) - x.col(static_cast<Eigen::Index>(seg)));
    out.col(k) = x.col(0) + scale * (p - x.col(0));
  }
  return out;
}

/// Arc length of the polyline `x` (mm).
inline double polylineLength(const Points& x) {
  return (x.rightCols(x.cols() - 1) - x.leftCols(x.cols() - 1)).colwise().norm().sum();
}

/// Loops (curls) along a straight thread: a trochoid x = t − 1.6 sin t, y = 1.6 cos t, bobbing
/// in z, `loops` loops of about 2 mm, starting at `start` and running along +x.
inline std::function<Vec3(double)> curls(const Vec3& start) {
  return [start](double t) {
    return Vec3(start + 0.4 * Vec3(t - 1.6 * std::sin(t), 1.6 * std::cos(t) - 1.6, 0.8 * std::sin(t)));
  };
}

/// `first`, then `rest`: a degenerate direction put ahead of the usual ones.
inline std::vector<Vec3> withFirst(const Vec3& first, std::vector<Vec3> rest) {
  rest.insert(rest.begin(), first);
  return rest;
}

/// A random rigid motion, reproducible from `seed`.
inline Eigen::Isometry3d randomRigidMotion(unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
  q.normalize();
  Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
  m.linear() = q.toRotationMatrix();
  m.translation() = Vec3(normal(rng), normal(rng), normal(rng)) * 5.0;
  return m;
}

inline Points moved(const Points& x, const Eigen::Isometry3d& m) {
  return (m.linear() * x).colwise() + m.translation();
}

}  // namespace microsim::sim::suture::knot_test
