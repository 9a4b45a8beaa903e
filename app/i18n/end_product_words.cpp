#include "i18n/end_product_words.h"

namespace microsim::i18n {

QString EndProductWords::kind(assessment::EndProductErrorKind kind) {
  using K = assessment::EndProductErrorKind;
  switch (kind) {
    case K::SutureLineDisruption:
      return tr("suture-line disruption");
    case K::BackWallStitch:
      return tr("back-wall stitch");
    case K::ObliqueStitch:
      return tr("oblique stitch");
    case K::WideBite:
      return tr("wide bite");
    case K::PartialThicknessBite:
      return tr("partial-thickness bite");
    case K::UnequalSpacing:
      return tr("unequal spacing");
    case K::WallTear:
      return tr("wall tear");
    case K::OverTightStitch:
      return tr("over-tight stitch");
    case K::ThreadInLumen:
      return tr("thread in the lumen");
    case K::LargeEdgeOverlap:
      return tr("large edge overlap");
  }
  return {};
}

}  // namespace microsim::i18n
