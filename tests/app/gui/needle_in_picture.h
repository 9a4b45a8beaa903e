#pragma once
// Finding the needle in a grabbed picture of the viewport, as a person finds it by eye: the
// only bright, polished, colourless thing in the field (the forceps are matte, the thread is
// dark blue, the tissue red, the marks green, the tip markers small rings). Used by the hands
// tests to aim at the needle where it is drawn, never where the engine keeps its nodes.
//
// Units: pixels of the grabbed image.

#include <QImage>
#include <QPoint>
#include <QRect>
#include <QRegion>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <deque>
#include <optional>
#include <vector>

namespace microsim::testing::picture {

/// Bright and without colour: the polished needle. Matte jaws stay below the brightness,
/// tissue, thread, drape and marks fail the colourless test.
inline bool looksLikeNeedle(QRgb c) {
  const int lo = std::min({qRed(c), qGreen(c), qBlue(c)});
  const int hi = std::max({qRed(c), qGreen(c), qBlue(c)});
  return lo >= 150 && hi - lo <= 22;
}

/// Dark blue or near black: the thread.
inline bool looksLikeThread(QRgb c) {
  const int r = qRed(c), g = qGreen(c), b = qBlue(c);
  return (b > r + 50 && b > g + 35) || std::max({r, g, b}) < 45;
}

/// The needle's pixels along its length from one starting place: each pixel with its
/// distance from the start, walked through the needle's pixels (gaps of up to three pixels,
/// where a jaw or a mark's line crosses it, are stepped over).
struct NeedleWalk {
  std::vector<QPoint> pixels;
  std::vector<int> distance;

  bool empty() const { return pixels.empty(); }
  /// the pixel farthest along the needle from the start
  QPoint farthest() const {
    return pixels[static_cast<std::size_t>(std::max_element(distance.begin(), distance.end()) - distance.begin())];
  }
  int length() const { return empty() ? 0 : *std::max_element(distance.begin(), distance.end()); }
  /// the pixel whose distance along the needle is nearest `d`
  QPoint at(int d) const {
    std::size_t best = 0;
    for (std::size_t i = 0; i < pixels.size(); ++i)
      if (std::abs(distance[i] - d) < std::abs(distance[best] - d)) best = i;
    return pixels[best];
  }
};

/// Walks the needle's pixels from every needle pixel within `seedRadius` of `from`, outside
/// `ignore` (the side-view inset, the overlay's text).
inline NeedleWalk walkNeedle(const QImage& image, QPoint from, int seedRadius, const QRegion& ignore) {
  const int w = image.width(), h = image.height();
  std::vector<int> dist(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), -1);
  const auto index = [w](int x, int y) { return static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x); };
  const auto needle = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < w && y < h && !ignore.contains(QPoint(x, y)) && looksLikeNeedle(image.pixel(x, y));
  };
  constexpr int kGap = 4;
  std::deque<QPoint> queue;
  for (int y = from.y() - seedRadius; y <= from.y() + seedRadius; ++y)
    for (int x = from.x() - seedRadius; x <= from.x() + seedRadius; ++x)
      if (needle(x, y) && (QPoint(x, y) - from).manhattanLength() <= seedRadius) {
        dist[index(x, y)] = 0;
        queue.emplace_back(x, y);
      }
  NeedleWalk walk;
  while (!queue.empty()) {
    const QPoint p = queue.front();
    queue.pop_front();
    const int d = dist[index(p.x(), p.y())];
    walk.pixels.push_back(p);
    walk.distance.push_back(d);
    for (int dy = -kGap; dy <= kGap; ++dy)
      for (int dx = -kGap; dx <= kGap; ++dx) {
        const int x = p.x() + dx, y = p.y() + dy;
        if (!needle(x, y) || dist[index(x, y)] >= 0) continue;
        dist[index(x, y)] = d + 1;
        queue.emplace_back(x, y);
      }
  }
  return walk;
}

/// The patch of at least `minPixels` needle pixels nearest `at`, outside `ignore` (a glint on
/// the tissue or a jaw is smaller); empty when none.
inline NeedleWalk nearestNeedlePatch(const QImage& image, QPoint at, const QRegion& ignore, std::size_t minPixels) {
  std::vector<QPoint> candidates;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      if (!ignore.contains(QPoint(x, y)) && looksLikeNeedle(image.pixel(x, y))) candidates.emplace_back(x, y);
  std::sort(candidates.begin(), candidates.end(),
            [at](QPoint a, QPoint b) { return (a - at).manhattanLength() < (b - at).manhattanLength(); });
  std::vector<bool> seen(static_cast<std::size_t>(image.width()) * static_cast<std::size_t>(image.height()), false);
  for (const QPoint& c : candidates) {
    if (seen[static_cast<std::size_t>(c.y()) * static_cast<std::size_t>(image.width()) + static_cast<std::size_t>(c.x())]) continue;
    NeedleWalk patch = walkNeedle(image, c, 0, ignore);
    if (patch.pixels.size() >= minPixels) return patch;
    for (const QPoint& p : patch.pixels)
      seen[static_cast<std::size_t>(p.y()) * static_cast<std::size_t>(image.width()) + static_cast<std::size_t>(p.x())] = true;
  }
  return {};
}

/// The largest patch of needle pixels in the picture, outside `ignore`; empty when none.
inline NeedleWalk largestNeedlePatch(const QImage& image, const QRegion& ignore) {
  NeedleWalk best;
  std::vector<bool> seen(static_cast<std::size_t>(image.width()) * static_cast<std::size_t>(image.height()), false);
  for (int y = 0; y < image.height(); y += 2)
    for (int x = 0; x < image.width(); x += 2) {
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width()) + static_cast<std::size_t>(x);
      if (seen[i] || ignore.contains(QPoint(x, y)) || !looksLikeNeedle(image.pixel(x, y))) continue;
      NeedleWalk patch = walkNeedle(image, {x, y}, 0, ignore);
      for (const QPoint& p : patch.pixels)
        seen[static_cast<std::size_t>(p.y()) * static_cast<std::size_t>(image.width()) + static_cast<std::size_t>(p.x())] = true;
      if (patch.pixels.size() > best.pixels.size()) best = std::move(patch);
    }
  return best;
}

/// Thread pixels within `radius` of `at`.
inline int threadPixelsNear(const QImage& image, QPoint at, int radius) {
  int count = 0;
  for (int y = std::max(0, at.y() - radius); y <= std::min(image.height() - 1, at.y() + radius); ++y)
    for (int x = std::max(0, at.x() - radius); x <= std::min(image.width() - 1, at.x() + radius); ++x)
      count += looksLikeThread(image.pixel(x, y)) ? 1 : 0;
  return count;
}

/// The needle: its back end (where the thread leaves it, and the jaws hold it) and its point,
/// each a far end of the needle's drawn arc.
struct NeedleEnds {
  QPoint back;
  QPoint point;
  NeedleWalk fromBack;  ///< the needle walked from its back end
};

/// Lying free it is the largest bright patch; held, the patch nearest the jaws (`nearJaws`, where
/// the tool is drawn), which also break a tie of thread pixels: the jaws hold the back.
inline std::optional<NeedleEnds> findNeedle(const QImage& image, const QRegion& ignore, std::optional<QPoint> nearJaws = {}) {
  constexpr std::size_t kSmallest = 30;  // pixels: a needle 1.5 mm long is hundreds
  const NeedleWalk patch = nearJaws ? nearestNeedlePatch(image, *nearJaws, ignore, kSmallest) : largestNeedlePatch(image, ignore);
  if (patch.pixels.size() < kSmallest) return std::nullopt;
  const QPoint one = walkNeedle(image, patch.pixels.front(), 0, ignore).farthest();
  const NeedleWalk fromOne = walkNeedle(image, one, 0, ignore);
  const QPoint other = fromOne.farthest();
  const int threadAtOne = threadPixelsNear(image, one, 6), threadAtOther = threadPixelsNear(image, other, 6);
  const bool oneIsBack = threadAtOne != threadAtOther || !nearJaws
                             ? threadAtOne >= threadAtOther
                             : (one - *nearJaws).manhattanLength() <= (other - *nearJaws).manhattanLength();
  NeedleEnds ends{oneIsBack ? one : other, oneIsBack ? other : one, {}};
  ends.fromBack = oneIsBack ? fromOne : walkNeedle(image, other, 0, ignore);
  return ends;
}

/// The radius (pixels) of the circle that best fits the walked needle's pixels (least
/// squares on x² + y² + Dx + Ey + F = 0, an algebraic fit: exact for pixels on a circle).
inline double fittedRadius(const NeedleWalk& walk) {
  Eigen::MatrixX3d a(static_cast<Eigen::Index>(walk.pixels.size()), 3);
  Eigen::VectorXd b(a.rows());
  for (Eigen::Index i = 0; i < a.rows(); ++i) {
    const QPoint& p = walk.pixels[static_cast<std::size_t>(i)];
    a.row(i) << p.x(), p.y(), 1.0;
    b(i) = -(static_cast<double>(p.x()) * p.x() + static_cast<double>(p.y()) * p.y());
  }
  const Eigen::Vector3d def = a.colPivHouseholderQr().solve(b);
  const double cx = -def(0) / 2.0, cy = -def(1) / 2.0;
  return std::sqrt(cx * cx + cy * cy - def(2));
}

}  // namespace microsim::testing::picture
