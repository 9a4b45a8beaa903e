#include "gui/calibration/closure_dialog.h"

#include "tracking/tracker_source.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>

namespace microsim::gui {

ClosureDialog::ClosureDialog(tracking::TrackerSource* source, double minSpan, QWidget* parent)
    : QDialog(parent), source_(source), minSpan_(minSpan) {
  setWindowTitle(tr("Forceps closure"));
  auto* hint = new QLabel(tr("Open the jaws fully, then squeeze them shut a few times."), this);
  hint->setWordWrap(true);
  channelBox_ = new QComboBox(this);
  channelBox_->setEditable(true);
  label_ = new QLabel(this);
  auto* reset = new QPushButton(tr("Start again"), this);
  buttons_ = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  auto* form = new QFormLayout(this);
  form->addRow(hint);
  form->addRow(tr("Channel:"), channelBox_);
  form->addRow(label_);
  form->addRow(reset);
  form->addRow(buttons_);
  connect(buttons_, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(reset, &QPushButton::clicked, this, [this] {
    range_.reset();
    showRange();
  });
  connect(channelBox_, &QComboBox::currentTextChanged, this, [this] {
    range_.reset();
    showRange();
  });
  if (source_ != nullptr) connect(source_, &tracking::TrackerSource::channelAccepted, this, &ClosureDialog::onValue);
  showRange();
}

void ClosureDialog::setChannel(const QString& channel) {
  if (channelBox_->findText(channel) < 0) channelBox_->addItem(channel);
  channelBox_->setCurrentText(channel);
}

QString ClosureDialog::channel() const { return channelBox_->currentText(); }

void ClosureDialog::onValue(const tracking::ChannelValue& value) {
  const QString name = QString::fromStdString(value.channel);
  if (channelBox_->findText(name) < 0) channelBox_->addItem(name);
  if (name != channel()) return;
  if (range_.add(value.value)) showRange();
}

void ClosureDialog::showRange() {
  label_->setText(range_.count() == 0 ? tr("No reading yet.")
                                      : tr("Open %1 · closed %2 (%n reading(s))", nullptr, range_.count())
                                            .arg(range_.open(), 0, 'g', 5)
                                            .arg(range_.closed(), 0, 'g', 5));
  buttons_->button(QDialogButtonBox::Ok)->setEnabled(range_.usable(minSpan_));
}

}  // namespace microsim::gui
