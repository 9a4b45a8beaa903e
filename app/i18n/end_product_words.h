#pragma once
// The end product's error kinds (assessment's scoring/end_product.h) in words, for every
// program: `microsim-cli score` prints them, the results page, the review and its PDF show
// them. The engine hands out kinds; the words are written once, here.

#include "microsim/assessment/scoring/end_product.h"

#include <QCoreApplication>
#include <QString>

namespace microsim::i18n {

class EndProductWords {
  Q_DECLARE_TR_FUNCTIONS(microsim::i18n::EndProductWords)

 public:
  /// "back-wall stitch" for EndProductErrorKind::BackWallStitch, lower case as in a sentence.
  static QString kind(assessment::EndProductErrorKind kind);
};

}  // namespace microsim::i18n
