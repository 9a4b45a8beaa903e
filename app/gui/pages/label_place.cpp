#include "gui/pages/label_place.h"

#include <algorithm>
#include <array>

namespace microsim::gui {

QRectF freeLabelPlace(QPointF at, QSizeF extent, double clearance, bool above,
                      const std::vector<QRectF>& taken, const QRectF& bounds) {
  const double w = extent.width();
  const double h = extent.height();
  std::vector<QRectF> candidates;
  for (int ring = 0; ring < 6; ++ring) {
    const double rise = ring * (h + 1.0);
    const std::array<double, 2> tops =
        above ? std::array<double, 2>{at.y() - clearance - h - rise, at.y() + clearance + rise}
              : std::array<double, 2>{at.y() + clearance + rise, at.y() - clearance - h - rise};
    for (const double top : tops) {
      candidates.emplace_back(at.x() + clearance, top, w, h);      // right of the mark
      candidates.emplace_back(at.x() - clearance - w, top, w, h);  // left of it
    }
  }
  for (const QRectF& c : candidates) {
    if (!bounds.contains(c)) continue;
    if (std::none_of(taken.begin(), taken.end(), [&c](const QRectF& t) { return t.intersects(c); }))
      return c;
  }
  return candidates.front();
}

}  // namespace microsim::gui
