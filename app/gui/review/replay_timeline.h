#pragma once
// The replay's event timeline: one lane each for pierces, grasps, tissue, knots and errors
// (replay_marks.h), a coloured tick per event at its time, the playhead across them. A tooltip
// names the event under the cursor; a click on one asks to seek to it.

#include "gui/review/replay_marks.h"

#include <QColor>
#include <QRect>
#include <QString>
#include <QWidget>

#include <vector>

namespace microsim::gui {

class ReplayTimeline : public QWidget {
  Q_OBJECT

 public:
  explicit ReplayTimeline(QWidget* parent = nullptr);

  /// The marks of a replay `frameCount` frames long.
  void setMarks(std::vector<ReplayMark> marks, int frameCount);
  void clear();
  /// Where the playhead is drawn (a replay position).
  void setPosition(int position);

  const std::vector<ReplayMark>& marks() const { return marks_; }
  /// The rectangle mark `index` is drawn in (what a click on it hits).
  QRect markRect(int index) const;
  /// The mark at `point`, the nearest in its lane within a few pixels; -1 for none.
  int markAt(QPoint point) const;

  static QColor colour(ReplayMarkKind kind);
  /// What a mark's tooltip says.
  static QString describe(const ReplayMark& mark);
  static QString laneName(ReplayLane lane);

  QSize sizeHint() const override;
  QSize minimumSizeHint() const override;

 Q_SIGNALS:
  /// The mark at replay position `position` was clicked.
  void markClicked(int position);

 protected:
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  bool event(QEvent* event) override;

 private:
  int xOf(int position) const;
  QRect laneRect(ReplayLane lane) const;
  int laneAt(int y) const;

  std::vector<ReplayMark> marks_;
  int frameCount_ = 0;
  int position_ = 0;
};

}  // namespace microsim::gui
