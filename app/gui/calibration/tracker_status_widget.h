#pragma once
// The status-bar line of a tracker source: connected or not, pose rate, dropped (refused)
// messages, and the last link error, refreshed twice a second from TrackerSource::status().

#include <QLabel>
#include <QPointer>
#include <QTimer>

namespace microsim::tracking {
class TrackerSource;
struct TrackerStatus;
}  // namespace microsim::tracking

namespace microsim::gui {

class TrackerStatusWidget : public QLabel {
  Q_OBJECT

 public:
  explicit TrackerStatusWidget(QWidget* parent = nullptr);

  /// Shows `source` (nullptr: "no tracker"); the widget does not own it.
  void setSource(tracking::TrackerSource* source);
  /// Re-reads the status now (the timer does it every 500 ms).
  void refresh();

  /// The line for a status (also its tooltip lists the refusals by reason).
  static QString describe(const tracking::TrackerStatus& status);

 private:
  QPointer<tracking::TrackerSource> source_;
  QTimer timer_;
};

}  // namespace microsim::gui
