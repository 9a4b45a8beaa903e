#pragma once
// After an attempt: the score and whether it passed, each metric with its value, target and
// the advice for its feedback key (feedback_text.h), never-events, the pierce angles drawn
// on the vessel (pierce_image.h), the finished anastomosis opened with its errors marked and
// listed (end_product_panel.h), and Retry / Back to the lessons.

#include "gui/pages/attempt_page.h"

#include <QWidget>

class QLabel;
class QTableWidget;

namespace microsim::gui {

class EndProductPanel;

class ResultsPage : public QWidget {
  Q_OBJECT

 public:
  explicit ResultsPage(QWidget* parent = nullptr);

  void show(const AttemptResult& result, const QString& lessonTitle);
  const AttemptResult& result() const { return result_; }
  /// The score as shown (for tests): "87" etc.
  QString scoreText() const;

 Q_SIGNALS:
  void retry();
  void back();

 private:
  AttemptResult result_;
  QLabel* heading_ = nullptr;
  QLabel* score_ = nullptr;
  QLabel* verdict_ = nullptr;
  QLabel* message_ = nullptr;
  QTableWidget* metrics_ = nullptr;
  QLabel* pierces_ = nullptr;
  EndProductPanel* endProduct_ = nullptr;
};

}  // namespace microsim::gui
