#pragma once
// Forceps closure range, with any TrackerSource: choose the grip channel, open the jaws
// fully, then squeeze them shut a few times; the channel's extremes (calibration::
// ClosureRange, open = the extreme nearer the first reading) become the 0..1 mapping.
// OK is enabled once the range spans at least minSpan (channel unit).

#include "calibration/closure_range.h"

#include <QDialog>
#include <QPointer>

class QComboBox;
class QDialogButtonBox;
class QLabel;

namespace microsim::tracking {
class TrackerSource;
struct ChannelValue;
}  // namespace microsim::tracking

namespace microsim::gui {

class ClosureDialog : public QDialog {
  Q_OBJECT

 public:
  explicit ClosureDialog(tracking::TrackerSource* source, double minSpan = 1e-6, QWidget* parent = nullptr);

  void setChannel(const QString& channel);
  QString channel() const;
  const calibration::ClosureRange& range() const { return range_; }

 private:
  void onValue(const tracking::ChannelValue& value);
  void showRange();

  QPointer<tracking::TrackerSource> source_;
  double minSpan_;
  calibration::ClosureRange range_;
  QComboBox* channelBox_ = nullptr;
  QLabel* label_ = nullptr;
  QDialogButtonBox* buttons_ = nullptr;
};

}  // namespace microsim::gui
