// Every feedback key a shipped rubric can give has words on both pages that show it: the
// advice on the results page (FeedbackText) and the sentence on the review page (ReviewText),
// in English, German and Spanish. A key without words would reach the trainee as
// "knot.not_secure".
#include "gui/pages/feedback_text.h"
#include "gui/review/review_text.h"
#include "microsim/assessment/scoring/rubric.h"

#include <QCoreApplication>
#include <QDir>
#include <QTranslator>

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <variant>

namespace microsim::gui {
namespace {

std::set<std::string> shippedFeedbackKeys() {
  std::set<std::string> keys;
  const QDir rubrics(QStringLiteral(MICROSIM_SOURCE_DIR "/resources/rubrics"));
  const QStringList files = rubrics.entryList({QStringLiteral("*.json")}, QDir::Files);
  EXPECT_GE(files.size(), 5);
  for (const QString& file : files) {
    const auto loaded = assessment::loadRubric(rubrics.filePath(file).toStdString());
    EXPECT_TRUE(std::holds_alternative<assessment::Rubric>(loaded)) << file.toStdString();
    if (!std::holds_alternative<assessment::Rubric>(loaded)) continue;
    const auto& rubric = std::get<assessment::Rubric>(loaded);
    for (const assessment::RubricMetric& m : rubric.metrics)
      for (const std::string& key : {m.feedbackAbove, m.feedbackBelow})
        if (!key.empty()) keys.insert(key);
    for (const assessment::NeverEvent& n : rubric.neverEvents) keys.insert(n.feedback);
  }
  return keys;
}

TEST(RubricFeedbackWords, EveryShippedFeedbackKeyHasAdviceAndAReviewSentence) {
  const std::set<std::string> keys = shippedFeedbackKeys();
  ASSERT_TRUE(keys.count("knot.not_secure"));
  ASSERT_TRUE(keys.count("never.knot_slipped"));
  for (const std::string& key : keys) {
    EXPECT_NE(FeedbackText::advice(key), QString::fromStdString(key)) << key;
    EXPECT_NE(ReviewText::feedback(QString::fromStdString(key)), QString::fromStdString(key))
        << key;
  }
}

TEST(RubricFeedbackWords, EveryShippedFeedbackKeyIsTranslated) {
  const std::set<std::string> keys = shippedFeedbackKeys();
  for (const QString& language : {QStringLiteral("de"), QStringLiteral("es")}) {
    QTranslator translator;
    ASSERT_TRUE(translator.load(QStringLiteral(":/i18n/microsim_") + language));
    for (const std::string& key : keys) {
      const QString advice = FeedbackText::advice(key);
      const QString sentence = ReviewText::feedback(QString::fromStdString(key));
      QCoreApplication::installTranslator(&translator);
      const QString translatedAdvice = FeedbackText::advice(key);
      const QString translatedSentence = ReviewText::feedback(QString::fromStdString(key));
      QCoreApplication::removeTranslator(&translator);
      EXPECT_NE(translatedAdvice, advice) << language.toStdString() << ": " << key;
      EXPECT_NE(translatedSentence, sentence) << language.toStdString() << ": " << key;
    }
  }
}

}  // namespace
}  // namespace microsim::gui
