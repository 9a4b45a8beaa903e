// The one vocabulary: every key the scoring can produce has a label in every shipped
// language, and the results page and the review page name a metric alike.
#include "gui/metric_vocabulary.h"

#include "gui/pages/results_page.h"
#include "gui/review/attempt_detail_view.h"
#include "microsim/assessment/scoring/metrics.h"
#include "microsim/assessment/scoring/pierce_fields.h"

#include <QCoreApplication>
#include <QTableWidget>
#include <QTranslator>

#include <gtest/gtest.h>

#include <string>
#include <string_view>

namespace microsim::gui {
namespace {

QString vocabularyKey(std::string_view key) { return QString::fromUtf8(key.data(), qsizetype(key.size())); }

// the labels of every metric and pierce field in the language whose catalogue is installed
QStringList everyLabel() {
  QStringList labels;
  for (const assessment::MetricInfo& m : assessment::metricCatalogue()) labels << MetricVocabulary::metricLabel(m.key);
  for (const assessment::PierceField& f : assessment::pierceFields()) labels << MetricVocabulary::pierceFieldLabel(f.key);
  return labels;
}

TEST(MetricVocabulary, EveryScoredMetricAndPierceFieldHasALabel) {
  ASSERT_FALSE(assessment::metricCatalogue().empty());
  for (const assessment::MetricInfo& m : assessment::metricCatalogue()) {
    EXPECT_TRUE(MetricVocabulary::hasMetricLabel(m.key)) << m.key;
    EXPECT_FALSE(MetricVocabulary::metricLabel(m.key).isEmpty()) << m.key;
    EXPECT_NE(MetricVocabulary::metricLabel(m.key), vocabularyKey(m.key)) << m.key;
  }
  ASSERT_FALSE(assessment::pierceFields().empty());
  for (const assessment::PierceField& f : assessment::pierceFields()) {
    EXPECT_TRUE(MetricVocabulary::hasPierceFieldLabel(f.key)) << f.key;
    EXPECT_NE(MetricVocabulary::pierceFieldLabel(f.key), vocabularyKey(f.key)) << f.key;
  }
  // a key from a newer rubric comes back as it is
  EXPECT_FALSE(MetricVocabulary::hasMetricLabel("knot_tension"));
  EXPECT_EQ(MetricVocabulary::metricLabel(std::string_view("knot_tension")), QStringLiteral("knot_tension"));
}

TEST(MetricVocabulary, EveryLabelIsTranslatedIntoGermanAndSpanish) {
  const QStringList english = everyLabel();
  for (const QString& language : {QStringLiteral("de"), QStringLiteral("es")}) {
    QTranslator translator;
    ASSERT_TRUE(translator.load(QStringLiteral(":/i18n/microsim_") + language));
    QCoreApplication::installTranslator(&translator);
    const QStringList translated = everyLabel();
    QCoreApplication::removeTranslator(&translator);
    ASSERT_EQ(translated.size(), english.size());
    for (qsizetype i = 0; i < english.size(); ++i) {
      EXPECT_FALSE(translated[i].isEmpty()) << language.toStdString() << ": " << english[i].toStdString();
      EXPECT_NE(translated[i], english[i]) << language.toStdString() << " has no text for "
                                           << english[i].toStdString();
    }
  }
}

TEST(MetricVocabulary, PierceColumnTitlesCarryTheUnit) {
  EXPECT_EQ(MetricVocabulary::pierceFieldTitle("entry_angle_deg"), QStringLiteral("Entry angle (°)"));
  EXPECT_EQ(MetricVocabulary::pierceFieldTitle("bite_mm"), QStringLiteral("Bite (mm)"));
  EXPECT_EQ(MetricVocabulary::pierceFieldTitle("back_wall"), QStringLiteral("Back wall"));
}

TEST(MetricVocabulary, ResultsAndReviewPagesShowTheSameLabelForEachMetric) {
  // one attempt that measured every metric, as the results page gets it and as the history
  // gives it back to the review page
  AttemptResult result;
  result.scored = true;
  assessment::AttemptDetail detail;
  for (const assessment::MetricInfo& m : assessment::metricCatalogue()) {
    assessment::MetricScore score;
    score.key = std::string(m.key);
    score.unit = std::string(m.unit);
    score.value = 1.0;
    result.score.metrics.push_back(score);
    assessment::StoredMetric stored;
    stored.key = vocabularyKey(m.key);
    stored.unit = vocabularyKey(m.unit);
    stored.value = 1.0;
    detail.metrics << stored;
  }
  ResultsPage results;
  results.show(result, QStringLiteral("Lesson"));
  AttemptDetailView review;
  review.setAttempt(detail, QStringLiteral("Ana"), QStringLiteral("Lesson"), QString(), false);

  const auto* resultsTable = results.findChild<QTableWidget*>(QStringLiteral("metricTable"));
  ASSERT_NE(resultsTable, nullptr);
  const QTableWidget* reviewTable = review.metricsTable();
  const int rows = int(assessment::metricCatalogue().size());
  ASSERT_EQ(resultsTable->rowCount(), rows);
  ASSERT_EQ(reviewTable->rowCount(), rows);
  for (int row = 0; row < rows; ++row) {
    const std::string_view key = assessment::metricCatalogue()[std::size_t(row)].key;
    EXPECT_EQ(resultsTable->item(row, 0)->text(), reviewTable->item(row, 0)->text()) << key;
    EXPECT_EQ(reviewTable->item(row, 0)->text(), MetricVocabulary::metricLabel(key)) << key;
  }
  EXPECT_EQ(MetricVocabulary::metricLabel(std::string_view("bite_symmetry")), QStringLiteral("Bite asymmetry"));
}

}  // namespace
}  // namespace microsim::gui
