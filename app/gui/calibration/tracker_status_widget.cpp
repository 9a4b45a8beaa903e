#include "gui/calibration/tracker_status_widget.h"

#include "gui/number_format.h"

#include "tracking/tracker_source.h"

namespace microsim::gui {

TrackerStatusWidget::TrackerStatusWidget(QWidget* parent) : QLabel(parent) {
  timer_.setInterval(500);
  connect(&timer_, &QTimer::timeout, this, &TrackerStatusWidget::refresh);
  refresh();
}

void TrackerStatusWidget::setSource(tracking::TrackerSource* source) {
  source_ = source;
  if (source_ != nullptr) {
    connect(source_, &tracking::TrackerSource::connectedChanged, this, &TrackerStatusWidget::refresh);
    timer_.start();
  } else {
    timer_.stop();
  }
  refresh();
}

QString TrackerStatusWidget::describe(const tracking::TrackerStatus& s) {
  QString line = s.connected ? tr("Tracker connected") : tr("Tracker not connected");
  line += QStringLiteral(" · ") + tr("%1 Hz").arg(NumberFormat::number(s.rateHz, 0));
  line += QStringLiteral(" · ") + tr("%n dropped", nullptr, static_cast<int>(s.dropped()));
  if (!s.lastError.isEmpty()) line += QStringLiteral(" · ") + s.lastError;
  return line;
}

void TrackerStatusWidget::refresh() {
  if (source_ == nullptr) {
    setText(tr("No tracker"));
    setToolTip({});
    return;
  }
  const tracking::TrackerStatus s = source_->status();
  setText(describe(s));
  QStringList reasons;
  for (int r = 0; r < tracking::kRejectionCount; ++r) {
    const auto reason = static_cast<tracking::Rejection>(r);
    if (s.rejected[reason] > 0)
      reasons << QStringLiteral("%1: %2").arg(QLatin1String(tracking::rejectionKey(reason))).arg(s.rejected[reason]);
  }
  setToolTip(reasons.join(QLatin1Char('\n')));
}

}  // namespace microsim::gui
