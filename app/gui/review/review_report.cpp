#include "gui/review/review_report.h"

#include "gui/pages/end_product_panel.h"
#include "gui/review/review_charts.h"
#include "gui/review/review_text.h"
#include "gui/save_file.h"

#include "microsim/assessment/storage/attempts_csv.h"

#include <QChart>
#include <QDateTime>
#include <QGraphicsScene>
#include <QLocale>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>

#include <algorithm>
#include <functional>
#include <memory>

namespace microsim::gui {
namespace {

// draws the report on pages of `page` size (device units); `newPage` starts the next one
class ReportPainter {
 public:
  ReportPainter(QPainter& painter, QRectF page, std::function<void()> newPage)
      : p_(painter), page_(page), newPage_(std::move(newPage)), y_(page.top()) {
    line_ = QFontMetricsF(p_.font(), p_.device()).height();
  }

  double lineHeight() const { return line_; }

  // moves to the next page unless `height` fits below
  void reserve(double height) {
    if (y_ + height <= page_.bottom()) return;
    newPage_();
    y_ = page_.top();
  }

  void text(const QString& s, double pointSize, bool bold = false) {
    QFont f = p_.font();
    f.setPointSizeF(pointSize);
    f.setBold(bold);
    p_.setFont(f);
    const double h = QFontMetricsF(f, p_.device()).height();
    reserve(h);
    p_.drawText(QRectF(page_.left(), y_, page_.width(), h), Qt::AlignLeft | Qt::AlignVCenter, s);
    y_ += h;
  }

  // one table row; `widths` are fractions of the page width
  void row(const QStringList& cells, const QList<double>& widths, bool bold) {
    QFont f = p_.font();
    f.setPointSizeF(9);
    f.setBold(bold);
    p_.setFont(f);
    const double h = QFontMetricsF(f, p_.device()).height() * 1.3;
    reserve(h);
    double x = page_.left();
    for (int i = 0; i < cells.size() && i < widths.size(); ++i) {
      const double w = widths[i] * page_.width();
      p_.drawText(QRectF(x, y_, w, h), Qt::AlignLeft | Qt::AlignVCenter,
                  QFontMetricsF(f, p_.device()).elidedText(cells[i], Qt::ElideRight, w * 0.95));
      x += w;
    }
    y_ += h;
    if (bold) p_.drawLine(QPointF(page_.left(), y_), QPointF(page_.right(), y_));
  }

  void chart(QChart* chart) {
    const double h = page_.width() * 0.45;
    reserve(h);
    // a chart lays itself out in a scene; rendered as vectors into the target
    QGraphicsScene scene;
    scene.addItem(chart);
    chart->resize(800, 360);
    chart->setBackgroundRoundness(0);
    QCoreApplication::sendPostedEvents();
    scene.render(&p_, QRectF(page_.left(), y_, page_.width(), h), chart->rect());
    scene.removeItem(chart);
    y_ += h;
  }

  // a picture `widthFraction` of the page wide, its aspect kept
  void image(const QImage& picture, double widthFraction) {
    const double w = page_.width() * widthFraction;
    const double h = w * picture.height() / std::max(1, picture.width());
    reserve(h);
    p_.drawImage(QRectF(page_.left(), y_, w, h), picture);
    y_ += h;
  }

  void newPage() {
    newPage_();
    y_ = page_.top();
  }

  void space(double lines) { y_ += lines * line_; }

 private:
  QPainter& p_;
  QRectF page_;
  std::function<void()> newPage_;
  double y_;
  double line_;
};

QString fail(QString* error, const QString& message) {
  if (error) *error = message;
  return message;
}

}  // namespace

bool ReviewReport::writeCsv(assessment::HistoryDatabase& history, const assessment::Viewer& viewer,
                            const QString& path, QString* error) {
  SaveFile file(path);
  QString why;
  if (!file.open(why)) {
    fail(error, tr("Cannot write %1: %2").arg(path, why));
    return false;
  }
  const assessment::HistoryStatus status = assessment::exportAttemptsCsv(history, viewer, *file.device());
  if (!status.ok()) {
    file.cancel();
    fail(error, status.error == assessment::HistoryError::Forbidden
                    ? tr("You may not export these attempts.")
                    : tr("The export failed: %1").arg(status.driverMessage));
    return false;
  }
  if (!file.commit(why)) {
    fail(error, tr("Cannot write %1: %2").arg(path, why));
    return false;
  }
  return true;
}

bool ReviewReport::writePdf(const TraineeReport& report, const ReviewCatalog& catalog, const QString& path,
                            QString* error) {
  // through a SaveFile: QPdfWriter's own file would drop a full disk's error
  SaveFile file(path);
  QString why;
  if (!file.open(why)) {
    fail(error, tr("Cannot write %1: %2").arg(path, why));
    return false;
  }
  QPdfWriter writer(file.device());
  writer.setPageSize(QPageSize(QPageSize::A4));
  writer.setPageMargins(QMarginsF(15, 15, 15, 15), QPageLayout::Millimeter);
  writer.setResolution(300);
  writer.setTitle(tr("Training report: %1").arg(report.trainee.name));
  writer.setCreator(QStringLiteral("microsim"));
  QPainter painter;
  if (!painter.begin(&writer)) {
    file.cancel();
    fail(error, tr("Cannot write %1.").arg(path));
    return false;
  }
  const QRectF page = writer.pageLayout().paintRectPixels(writer.resolution()).translated(
      -writer.pageLayout().paintRectPixels(writer.resolution()).topLeft());
  ReportPainter r(painter, page, [&writer] { writer.newPage(); });
  const QLocale locale;

  // header
  r.text(tr("Training report: %1").arg(report.trainee.name), 18, true);
  if (!report.trainee.group.isEmpty()) r.text(tr("Group: %1").arg(report.trainee.group), 11);
  r.text(tr("Printed %1").arg(locale.toString(QDateTime::currentDateTime(), QLocale::LongFormat)), 9);
  r.space(1);

  // every attempt
  const QList<double> widths{0.06, 0.26, 0.2, 0.1, 0.14, 0.1, 0.14};
  r.text(tr("Attempts"), 13, true);
  r.row({tr("#"), tr("Lesson"), tr("Started"), tr("Mode"), tr("Status"), tr("Score"), tr("Passed")}, widths, true);
  int number = 0;
  for (const assessment::AttemptSummary& a : report.attempts) {
    const ReviewLesson* lesson = catalog.lesson(a.lesson);
    r.row({QString::number(++number), lesson ? lesson->title : a.lesson,
           locale.toString(a.started.toLocalTime(), QLocale::ShortFormat), ReviewText::mode(a.mode),
           ReviewText::status(a.status), a.score ? locale.toString(*a.score, 'f', 1) : QStringLiteral("–"),
           a.score ? (a.passed ? tr("yes") : tr("no")) : QString()},
          widths, false);
  }
  if (report.attempts.isEmpty()) r.text(tr("No attempts yet."), 10);

  // per lesson, the score chart with its pass mark
  for (const ReviewLesson& lesson : catalog.lessons(report.attempts)) {
    const QList<assessment::AttemptSummary> done = finishedAttempts(report.attempts, report.trainee.id, lesson.id);
    if (done.isEmpty()) continue;
    QList<double> scores;
    for (const assessment::AttemptSummary& a : done) scores << *a.score;
    const assessment::Rubric* rubric = catalog.rubric(lesson.id);
    std::unique_ptr<QChart> chart(
        ReviewCharts::scoreChart(scores, rubric ? std::optional<double>(rubric->passMark) : std::nullopt));
    chart->setTitle(lesson.title);
    r.space(1);
    r.chart(chart.get());
  }
  // the end products with errors, each opened and listed
  bool first = true;
  number = 0;
  for (const assessment::AttemptSummary& a : report.attempts) {
    ++number;
    const auto it = report.endProducts.constFind(a.id);
    if (it == report.endProducts.constEnd() || it->errors.empty()) continue;
    if (first) {
      r.newPage();
      r.text(tr("End product"), 13, true);
      r.text(tr("Each vessel cut along its axis and laid flat: 0° faces the microscope, the back "
                "wall is shaded."),
             9);
      first = false;
    }
    const ReviewLesson* lesson = catalog.lesson(a.lesson);
    r.space(0.5);
    r.text(tr("Attempt %1: %2, %3")
               .arg(number)
               .arg(lesson ? lesson->title : a.lesson,
                    locale.toString(a.started.toLocalTime(), QLocale::ShortFormat)),
           11, true);
    // as on the screen, at three pixels to each of the screen's, so that it stays sharp on paper
    const QImage picture = OpenedVesselImage::draw(*it, EndProductPanel::imageSize(), 3.0);
    r.image(picture, 0.8);
    const QList<double> errorWidths{0.06, 0.3, 0.32, 0.32};
    r.row(EndProductPanel::columnTitles(), errorWidths, true);
    for (std::size_t i = 0; i < it->errors.size(); ++i)
      r.row(EndProductPanel::rowTexts(i, it->errors[i]), errorWidths, false);
  }

  if (!painter.end() || !file.commit(why)) {
    file.cancel();
    fail(error, why.isEmpty() ? tr("Cannot write %1.").arg(path) : tr("Cannot write %1: %2").arg(path, why));
    return false;
  }
  return true;
}

}  // namespace microsim::gui
