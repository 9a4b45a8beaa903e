#include "microsim/sim/suture/knot_diagram.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace microsim::sim::suture {

namespace {

using Vec2 = Eigen::Vector2d;

// a crossing this far (relative to the mean link) from another, or from a segment's end, is as
// good as on it; an angle with this |sin| (≈ 14°) is transverse enough
constexpr double kDiagramClearance = 0.02;
constexpr double kDiagramTransverseSin = 0.25;

// one straight piece of the picture: a link, or an end's extension to the far circle
struct DiagramSegment {
  Vec2 a;
  Vec2 b;
  Vec3 direction;       // in space, along the curve
  double depthA = 0.0;  // x·d at a and at b; the extensions lie above everything
  double depthB = 0.0;
  double at = 0.0;  // curve parameter of a
  bool closure = false;
};

double crossOf(const Vec2& p, const Vec2& q) {
  return p.x() * q.y() - p.y() * q.x();
}

// (cell key, segment) entries in key order, then segment order within a key (the order
// std::sort gives the pairs), by a counting sort over the keys' range while that range is
// small beside the entries (a knot's links crowd a few cells), else by std::sort (a long
// thread laid out straight spans many empty cells)
void sortByCell(std::vector<std::pair<long long, std::size_t>>& filed) {
  if (filed.empty()) {
    return;
  }
  const auto [lowest, highest] = std::minmax_element(
      filed.begin(), filed.end(), [](const auto& l, const auto& r) { return l.first < r.first; });
  const long long low = lowest->first;
  const auto span = static_cast<unsigned long long>(highest->first - low);
  if (span >= 8 * filed.size()) {
    std::sort(filed.begin(), filed.end());
    return;
  }
  // entries are filed in segment order, so a stable placement keeps segments ordered per key
  std::vector<std::size_t> start(span + 2, 0);
  for (const auto& f : filed) {
    ++start[static_cast<std::size_t>(f.first - low) + 1];
  }
  for (std::size_t k = 1; k < start.size(); ++k) {
    start[k] += start[k - 1];
  }
  std::vector<std::pair<long long, std::size_t>> sorted(filed.size());
  for (const auto& f : filed) {
    sorted[start[static_cast<std::size_t>(f.first - low)]++] = f;
  }
  filed.swap(sorted);
}

}  // namespace

KnotDiagram projectKnot(const Points& x, std::span<const int> anchors, const Vec3& direction) {
  KnotDiagram diagram;
  const Eigen::Index m = x.cols();
  diagram.direction = direction.normalized();
  if (m < 2) {
    return diagram;
  }
  const Vec3 d = diagram.direction;
  // a right-handed picture frame (e1, e2, d)
  const Vec3 helper = std::abs(d.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 e1 = (helper - helper.dot(d) * d).normalized();
  const Vec3 e2 = d.cross(e1);

  // the picture's points, its centre and the far circle
  std::vector<Vec2> p(static_cast<std::size_t>(m));
  Vec2 centre = Vec2::Zero();
  double linkSum = 0.0;
  for (Eigen::Index i = 0; i < m; ++i) {
    p[static_cast<std::size_t>(i)] = Vec2(x.col(i).dot(e1), x.col(i).dot(e2));
    centre += p[static_cast<std::size_t>(i)];
    if (i > 0) {
      linkSum += (x.col(i) - x.col(i - 1)).norm();
    }
  }
  centre /= static_cast<double>(m);
  double radius = 0.0;
  double top = -1e300;
  for (Eigen::Index i = 0; i < m; ++i) {
    radius = std::max(radius, (p[static_cast<std::size_t>(i)] - centre).norm());
    top = std::max(top, x.col(i).dot(d));
  }
  const double meanLink = linkSum / static_cast<double>(m - 1);
  const double farRadius = 2.0 * radius + meanLink + 1.0;
  const double clearance = kDiagramClearance * std::max(meanLink, 1e-9);
  const auto outward = [&](const Vec2& q) {
    const Vec2 r = q - centre;
    const double n = r.norm();
    return n > 1e-12 * (radius + 1.0) ? Vec2(r / n) : Vec2(1.0, 0.0);
  };
  const auto lift = [&](const Vec2& v) { return Vec3(v.x() * e1 + v.y() * e2); };

  // the links, and the two extensions (walked from the far circle in, and from the end out)
  std::vector<DiagramSegment> segments;
  segments.reserve(static_cast<std::size_t>(m + 1));
  const double above = top + 1.0;
  {
    const Vec2 start = p.front();
    const Vec2 far = centre + farRadius * outward(start);
    segments.push_back({far, start, lift(start - far), above, above, -1.0, true});
  }
  for (Eigen::Index i = 0; i + 1 < m; ++i) {
    const auto k = static_cast<std::size_t>(i);
    segments.push_back({p[k], p[k + 1], x.col(i + 1) - x.col(i), x.col(i).dot(d),
                        x.col(i + 1).dot(d), static_cast<double>(i), false});
  }
  {
    const Vec2 end = p.back();
    const Vec2 far = centre + farRadius * outward(end);
    segments.push_back({end, far, lift(far - end), above, above, static_cast<double>(m - 1), true});
  }

  // one pair of segments: do their pictures cross, and how clearly
  std::vector<Vec2> points;  // where each crossing is in the picture
  double worst = 1.0;
  const auto testPair = [&](std::size_t i, std::size_t j) {
    const DiagramSegment& si = segments[i];
    const DiagramSegment& sj = segments[j];
    const Vec2 r = si.b - si.a;
    const Vec2 q = sj.b - sj.a;
    const double denominator = crossOf(r, q);
    // most pairs that share a cell do not cross: the two orientation tests reject them before
    // any square root (the clearance of a parallel pair is the one test that needs the lengths)
    const double sq = r.squaredNorm() * q.squaredNorm();
    if (denominator * denominator > 1e-28 * sq) {
      const Vec2 w = sj.a - si.a;
      const double ti = crossOf(w, q) / denominator;
      const double tj = crossOf(w, r) / denominator;
      if (ti < 0.0 || ti >= 1.0 || tj < 0.0 || tj >= 1.0) {
        return;
      }
    }
    const double scale = r.norm() * q.norm();
    if (std::abs(denominator) <= 1e-14 * scale || scale == 0.0) {
      // parallel pictures: overlapping ones hide which passes where
      const Vec2 w = sj.a - si.a;
      if (scale > 0.0 && std::abs(crossOf(w, r)) <= clearance * r.norm()) {
        const double u0 = w.dot(r) / r.squaredNorm();
        const double u1 = (sj.b - si.a).dot(r) / r.squaredNorm();
        if (std::max(u0, u1) >= 0.0 && std::min(u0, u1) <= 1.0) {
          worst = 0.0;
        }
      }
      return;
    }
    const Vec2 w = sj.a - si.a;
    const double ti = crossOf(w, q) / denominator;
    const double tj = crossOf(w, r) / denominator;
    if (ti < 0.0 || ti >= 1.0 || tj < 0.0 || tj >= 1.0) {
      return;
    }
    const double depthI = si.depthA + ti * (si.depthB - si.depthA);
    const double depthJ = sj.depthA + tj * (sj.depthB - sj.depthA);
    const bool iOver = depthI >= depthJ;
    const Vec3& over = iOver ? si.direction : sj.direction;
    const Vec3& under = iOver ? sj.direction : si.direction;
    KnotCrossing c;
    c.overAt = iOver ? si.at + ti : sj.at + tj;
    c.underAt = iOver ? sj.at + tj : si.at + ti;
    c.sign = over.cross(under).dot(d) >= 0.0 ? 1 : -1;
    c.withClosure = si.closure || sj.closure;
    diagram.closureCrossings += c.withClosure ? 1 : 0;
    diagram.crossings.push_back(c);
    const Vec2 at = si.a + ti * r;
    points.push_back(at);

    // margins: the angle, and the distance to either segment's ends
    const double sinAngle = std::abs(denominator) / scale;
    worst = std::min(worst, sinAngle / kDiagramTransverseSin);
    if (!si.closure && !sj.closure) {
      const double ends =
          std::min({ti * r.norm(), (1.0 - ti) * r.norm(), tj * q.norm(), (1.0 - tj) * q.norm()});
      worst = std::min(worst, ends / clearance);
    }
  };

  // candidate pairs from a grid of cells one and a half mean links wide: a link is filed under
  // every cell its box touches, and a pair is tested in the first cell the two share, so the work
  // follows the links and the crossings, not their square; the cells are numbered row by row
  // over the links' extent, so the entries sort by counting. The two extensions are long: each
  // is tested against every link whose box reaches it.
  const std::size_t count = segments.size();
  const std::size_t firstLink = 1;
  const std::size_t lastLink = count - 2;
  const double cell = 1.5 * std::max(meanLink, 1e-9);
  struct CellRange {
    long long x0, y0, x1, y1;
  };
  std::vector<CellRange> ranges(count);
  std::vector<std::pair<long long, std::size_t>> filed;
  filed.reserve(4 * count);
  const auto cellOf = [&](double v) { return static_cast<long long>(std::floor(v / cell)); };
  for (std::size_t k = firstLink; k <= lastLink; ++k) {
    const DiagramSegment& g = segments[k];
    ranges[k] = {cellOf(std::min(g.a.x(), g.b.x()) - centre.x()),
                 cellOf(std::min(g.a.y(), g.b.y()) - centre.y()),
                 cellOf(std::max(g.a.x(), g.b.x()) - centre.x()),
                 cellOf(std::max(g.a.y(), g.b.y()) - centre.y())};
  }
  // a cell's key counts the cells row by row from the lowest one the links touch
  long long lowX = ranges[firstLink].x0, lowY = ranges[firstLink].y0, highY = ranges[firstLink].y1;
  for (std::size_t k = firstLink; k <= lastLink; ++k) {
    lowX = std::min(lowX, ranges[k].x0);
    lowY = std::min(lowY, ranges[k].y0);
    highY = std::max(highY, ranges[k].y1);
  }
  const long long row = highY - lowY + 1;
  const auto keyOf = [&](long long cx, long long cy) { return (cx - lowX) * row + (cy - lowY); };
  for (std::size_t k = firstLink; k <= lastLink; ++k) {
    const CellRange& r = ranges[k];
    for (long long cx = r.x0; cx <= r.x1; ++cx) {
      for (long long cy = r.y0; cy <= r.y1; ++cy) {
        filed.emplace_back(keyOf(cx, cy), k);
      }
    }
  }
  sortByCell(filed);
  for (std::size_t from = 0; from < filed.size();) {
    std::size_t to = from + 1;
    while (to < filed.size() && filed[to].first == filed[from].first) {
      ++to;
    }
    for (std::size_t u = from; u < to; ++u) {
      for (std::size_t v = u + 1; v < to; ++v) {
        const std::size_t i = filed[u].second;
        const std::size_t j = filed[v].second;
        if (j == i + 1 || i == j + 1) {
          continue;  // neighbours share a node
        }
        // the first cell both boxes share
        const long long cx = std::max(ranges[i].x0, ranges[j].x0);
        const long long cy = std::max(ranges[i].y0, ranges[j].y0);
        if (keyOf(cx, cy) == filed[from].first) {
          testPair(std::min(i, j), std::max(i, j));
        }
      }
    }
    from = to;
  }
  for (const std::size_t e : {std::size_t{0}, count - 1}) {
    // a link whose box (grown by the clearance) misses the extension's can neither cross it
    // nor lie along it
    const DiagramSegment& ext = segments[e];
    const Vec2 low = ext.a.cwiseMin(ext.b) - Vec2::Constant(clearance);
    const Vec2 high = ext.a.cwiseMax(ext.b) + Vec2::Constant(clearance);
    for (std::size_t k = firstLink; k <= lastLink; ++k) {
      const DiagramSegment& g = segments[k];
      if (k + 1 == e || e + 1 == k || g.a.cwiseMax(g.b).x() < low.x() ||
          g.a.cwiseMax(g.b).y() < low.y() || g.a.cwiseMin(g.b).x() > high.x() ||
          g.a.cwiseMin(g.b).y() > high.y()) {
        continue;
      }
      testPair(std::min(e, k), std::max(e, k));
    }
  }

  // three strands through one point show as crossings on top of each other
  for (std::size_t k = 0; k < points.size(); ++k) {
    for (std::size_t l = k + 1; l < points.size(); ++l) {
      worst = std::min(worst, (points[k] - points[l]).norm() / clearance);
    }
  }
  diagram.quality = std::clamp(worst, 0.0, 1.0);

  // the Gauss word: each crossing passed twice, anchors once, in curve order
  diagram.word.reserve(2 * diagram.crossings.size() + anchors.size());
  for (std::size_t k = 0; k < diagram.crossings.size(); ++k) {
    const KnotCrossing& c = diagram.crossings[k];
    diagram.word.push_back({static_cast<int>(k), true, c.overAt});
    diagram.word.push_back({static_cast<int>(k), false, c.underAt});
  }
  for (const int a : anchors) {
    if (a >= 0 && a < m) {
      diagram.word.push_back({-1, false, static_cast<double>(a)});
    }
  }
  std::stable_sort(diagram.word.begin(), diagram.word.end(),
                   [](const GaussEntry& l, const GaussEntry& r) { return l.at < r.at; });
  return diagram;
}

std::vector<Vec3> knotViewDirections(const Points& x) {
  // the principal frame of the points, smallest spread first
  Eigen::Matrix3d frame = Eigen::Matrix3d::Identity();
  if (x.cols() >= 2) {
    const Vec3 mean = x.rowwise().mean();
    const Eigen::Matrix3Xd centred = x.colwise() - mean;
    const Eigen::Matrix3d covariance = centred * centred.transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
    if (solver.info() == Eigen::Success) {
      frame = solver.eigenvectors();  // columns in increasing eigenvalue
    }
  }
  const Vec3 a = frame.col(0);
  const Vec3 b = frame.col(1);
  const Vec3 c = frame.col(2);
  std::vector<Vec3> directions = {a,
                                  b,
                                  c,
                                  (a + b).normalized(),
                                  (a - b).normalized(),
                                  (a + c).normalized(),
                                  (a - c).normalized(),
                                  (b + c).normalized(),
                                  (b - c).normalized(),
                                  (a + b + c).normalized(),
                                  (a + b - c).normalized(),
                                  (a - b + c).normalized(),
                                  (a - b - c).normalized()};
  return directions;
}

}  // namespace microsim::sim::suture
