#pragma once
// Where a label beside a mark covers nothing already drawn: the pierce image and the opened
// vessel place their labels so, and their tests check that no two overlap.

#include <QPointF>
#include <QRectF>
#include <QSizeF>

#include <vector>

namespace microsim::gui {

/// The first place for a label of `extent` beside the mark at `at`, `clearance` pixels
/// from its centre, that intersects none of `taken` and lies inside `bounds`: beside the mark
/// on the preferred side (above or below; right, then left) first, then the other side,
/// then stacked further away; the first place when none is free.
QRectF freeLabelPlace(QPointF at, QSizeF extent, double clearance, bool above,
                      const std::vector<QRectF>& taken, const QRectF& bounds);

}  // namespace microsim::gui
