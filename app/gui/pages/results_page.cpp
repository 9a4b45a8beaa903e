#include "gui/pages/results_page.h"

#include "gui/metric_vocabulary.h"
#include "gui/number_format.h"
#include "gui/pages/end_product_panel.h"
#include "gui/pages/feedback_text.h"
#include "gui/pages/pierce_image.h"
#include "gui/settings/tunables.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPixmap>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace microsim::gui {

ResultsPage::ResultsPage(QWidget* parent) : QWidget(parent) {
  setObjectName(QStringLiteral("resultsPage"));
  heading_ = new QLabel(this);
  score_ = new QLabel(this);
  score_->setObjectName(QStringLiteral("scoreLabel"));
  verdict_ = new QLabel(this);
  verdict_->setObjectName(QStringLiteral("verdictLabel"));
  message_ = new QLabel(this);
  message_->setWordWrap(true);
  message_->setObjectName(QStringLiteral("resultsMessage"));
  metrics_ = new QTableWidget(0, 4, this);
  metrics_->setObjectName(QStringLiteral("metricTable"));
  metrics_->setHorizontalHeaderLabels({tr("Metric"), tr("Value"), tr("Points"), tr("Advice")});
  // names, values and points on one line each; the advice takes the rest and wraps
  for (int column = 0; column < 3; ++column)
    metrics_->horizontalHeader()->setSectionResizeMode(column, QHeaderView::ResizeToContents);
  metrics_->horizontalHeader()->setSectionResizeMode(3, QHeaderView::Stretch);
  metrics_->verticalHeader()->hide();
  metrics_->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  metrics_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  metrics_->setWordWrap(true);
  pierces_ = new QLabel(this);
  pierces_->setObjectName(QStringLiteral("pierceImage"));
  pierces_->setAlignment(Qt::AlignCenter);
  endProduct_ = new EndProductPanel(Qt::Horizontal, this);
  auto* retry = new QPushButton(tr("Retry"), this);
  retry->setObjectName(QStringLiteral("retryButton"));
  auto* back = new QPushButton(tr("Back to the lessons"), this);
  back->setObjectName(QStringLiteral("backButton"));

  auto* top = new QHBoxLayout;
  top->addWidget(score_);
  top->addWidget(verdict_);
  top->addStretch(1);
  auto* body = new QHBoxLayout;
  body->addWidget(metrics_, 3);
  auto* right = new QVBoxLayout;
  auto* pierceCaption = new QLabel(tr("<b>Pierce angles</b> (0° = perpendicular; red entry, blue exit)"), this);
  pierceCaption->setWordWrap(true);  // longer in German and Spanish than the column is wide
  right->addWidget(pierceCaption);
  right->addWidget(pierces_, 1);
  body->addLayout(right, 2);
  auto* buttons = new QHBoxLayout;
  buttons->addStretch(1);
  buttons->addWidget(back);
  buttons->addWidget(retry);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(heading_);
  layout->addLayout(top);
  layout->addWidget(message_);
  layout->addLayout(body, 1);
  layout->addWidget(endProduct_);
  layout->addLayout(buttons);

  connect(retry, &QPushButton::clicked, this, &ResultsPage::retry);
  connect(back, &QPushButton::clicked, this, &ResultsPage::back);
}

QString ResultsPage::scoreText() const { return NumberFormat::number(result_.score.score, 0); }

void ResultsPage::show(const AttemptResult& result, const QString& lessonTitle) {
  result_ = result;
  const QString mode = result.mode == assessment::AttemptMode::Test ? tr("Test") : tr("Learn");
  heading_->setText(tr("<h2>%1 — %2</h2>").arg(lessonTitle.toHtmlEscaped(), mode));
  metrics_->setRowCount(0);
  if (!result.scored) {
    score_->setText(tr("<span style='font-size:28pt'>–</span>"));
    verdict_->setText(tr("Not scored"));
    message_->setText(result.problem ? AttemptPage::describe(*result.problem) : QString());
    pierces_->clear();
    endProduct_->clear();
    return;
  }
  const assessment::AttemptScore& s = result.score;
  score_->setText(tr("<span style='font-size:28pt'><b>%1</b> / 100</span>").arg(scoreText()));
  verdict_->setText(s.passed ? tr("<span style='color:#1b7f3a; font-size:16pt'>Passed</span>")
                             : tr("<span style='color:#b00020; font-size:16pt'>Not passed yet</span>"));

  QStringList notes;
  for (const std::string& never : s.neverEvents) notes << FeedbackText::advice(never);
  if (s.truncated) notes << tr("Scored from an incomplete recording.");
  if (result.problem) notes << AttemptPage::describe(*result.problem);
  message_->setText(notes.join(QLatin1Char('\n')));

  const QString units = settings::Tunables::value(settings::unitsKey()).toString();
  metrics_->setRowCount(static_cast<int>(s.metrics.size()));
  for (std::size_t i = 0; i < s.metrics.size(); ++i) {
    const assessment::MetricScore& m = s.metrics[i];
    const int row = static_cast<int>(i);
    metrics_->setItem(row, 0, new QTableWidgetItem(MetricVocabulary::metricLabel(m.key)));
    metrics_->setItem(row, 1, new QTableWidgetItem(tr("%1 (target %2)").arg(
                                  NumberFormat::value(m.value, m.unit, units), NumberFormat::value(m.target, m.unit, units))));
    metrics_->setItem(row, 2, new QTableWidgetItem(NumberFormat::percent(m.points)));
    metrics_->setItem(row, 3, new QTableWidgetItem(m.feedback.empty() ? tr("Good.") : FeedbackText::advice(m.feedback)));
  }
  pierces_->setPixmap(QPixmap::fromImage(drawPierceAngles(result.vessels, result.pierces, QSize(420, 260))));
  endProduct_->setEndProduct({s.pierces, s.stitches, s.endProduct}, true);
}

}  // namespace microsim::gui
