#pragma once
// The finished anastomosis opened: cut along the vessel's axis and laid flat, the view the
// Anastomosis Lapse Index is counted on (assessment's scoring/end_product.h).
//
//   across   the circumference, 0° at the left edge to 360° at the right, 0° toward the
//            microscope; the front wall is 0–90° and 270–360°, the back wall 90–270°
//            (shaded darker), both named under the wall;
//   down     the axis: the suture line runs across the middle, end 1 above it and end 2
//            below; a passage lies on its end's side, as far from the line as its bite in
//            wall thicknesses (4 walls at the wall's edge);
//   stitches each passage a dot, the thread a line from one to the other across the suture
//            line (across the 0°/360° seam the short way round), labelled S1, S2, ...;
//   errors   a marker of its kind's shape and colour at its angle, on its passage if it has
//            one (else on the suture line), numbered as the error list numbers them; a
//            second error at the same place stacks away from the line. Errors that are not
//            located (a wall tear, a broken thread) are named in a line under the legend.
// Under the wall the legend names each error kind drawn, in words (i18n/end_product_words.h).
//
// Labels are placed as the pierce image places them (pierce_image.h): beside their mark where
// they cover no dot, marker or other label, else further away, inside the wall.

#include "microsim/assessment/scoring/end_product.h"
#include "microsim/assessment/scoring/pierce_metrics.h"
#include "microsim/assessment/scoring/stitch_metrics.h"

#include <QCoreApplication>
#include <QImage>
#include <QLineF>
#include <QRectF>
#include <QSize>
#include <QString>

#include <vector>

namespace microsim::gui {

/// What the opened view draws: an attempt's passages and stitches and its errors.
struct OpenedVessel {
  std::vector<assessment::PierceMetrics> passages;  ///< pierceMetrics order
  std::vector<assessment::StitchMetrics> stitches;  ///< stitchMetrics(passages)
  std::vector<assessment::EndProductError> errors;  ///< numbered 1, 2, ... in this order
};

/// Where everything is drawn, in image pixels.
struct OpenedVesselLayout {
  QRectF wall;  ///< the opened wall: its left edge 0°, its right edge 360°
  double sutureLineY = 0.0;
  std::vector<QPointF> passages;  ///< parallel to OpenedVessel::passages; NaN where not located
  /// each stitch's thread from passage to passage, the short way round: two pieces, leaving
  /// one edge and entering at the other, where it crosses the 0°/360° seam (clip to `wall`)
  std::vector<QLineF> threads;

  struct Mark {
    int error = 0;  ///< index into OpenedVessel::errors
    QPointF at;     ///< the marker's centre
    QString label;  ///< its number, "1" for the first error
    QRectF labelRect;
  };
  std::vector<Mark> marks;  ///< the located errors, in error order

  struct StitchLabel {
    QPointF at;  ///< where its thread crosses the suture line
    QString label;
    QRectF labelRect;
  };
  std::vector<StitchLabel> stitchLabels;

  struct Text {
    QString text;
    QRectF rect;
  };
  std::vector<Text> axisLabels;  ///< 0°, 90°, 180°, 270°, 360° above the wall
  std::vector<Text> wallNames;   ///< front, back, front under the wall; the ends at its left

  struct LegendEntry {
    assessment::EndProductErrorKind kind;
    QPointF marker;  ///< the sample marker's centre
    Text text;       ///< the kind in words
  };
  std::vector<LegendEntry> legend;  ///< each kind drawn, once, in kind order
  std::vector<int> unlocated;       ///< errors with no angle, in error order
  Text unlocatedText;               ///< "Not located: 3 wall tear, ..."; empty when none
};

class OpenedVesselImage {
  Q_DECLARE_TR_FUNCTIONS(microsim::gui::OpenedVesselImage)

 public:
  static OpenedVesselLayout layOut(const OpenedVessel& vessel, QSize size);
  /// The drawing laid out for `size`, with `pixelRatio` pixels to each of its units (paper
  /// wants more than a screen).
  static QImage draw(const OpenedVessel& vessel, QSize size, qreal pixelRatio = 1.0);
};

}  // namespace microsim::gui
