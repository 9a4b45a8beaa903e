#include "gui/calibration/latency_dialog.h"

#include "gui/number_format.h"

#include "tracking/tracker_source.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>

namespace microsim::gui {

namespace {

void remember(QComboBox* box, const QString& name) {
  if (box->findText(name) < 0) box->addItem(name);
}

}  // namespace

LatencyDialog::LatencyDialog(tracking::TrackerSource* tracked, tracking::TrackerSource* reference, QWidget* parent)
    : QDialog(parent), tracked_(tracked), reference_(reference) {
  setWindowTitle(tr("Latency"));
  auto* hint = new QLabel(tr("Hold the tool and the reference together and move them briskly in every direction "
                             "for about ten seconds."),
                          this);
  hint->setWordWrap(true);
  trackedBox_ = new QComboBox(this);
  trackedBox_->setEditable(true);
  referenceBox_ = new QComboBox(this);
  referenceBox_->setEditable(true);
  record_ = new QPushButton(tr("Record"), this);
  label_ = new QLabel(this);
  buttons_ = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  buttons_->button(QDialogButtonBox::Ok)->setEnabled(false);
  auto* form = new QFormLayout(this);
  form->addRow(hint);
  form->addRow(tr("Tracked device:"), trackedBox_);
  form->addRow(tr("Reference device:"), referenceBox_);
  form->addRow(record_);
  form->addRow(label_);
  form->addRow(buttons_);
  connect(buttons_, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(record_, &QPushButton::clicked, this, [this] {
    if (recording_)
      stopRecording();
    else
      startRecording();
  });
  if (tracked_ != nullptr)
    connect(tracked_, &tracking::TrackerSource::poseAccepted, this,
            [this](const tracking::RawPose& p) { onPose(p, false); });
  if (reference_ != nullptr && reference_ != tracked_)
    connect(reference_, &tracking::TrackerSource::poseAccepted, this,
            [this](const tracking::RawPose& p) { onPose(p, true); });
  clock_.start();
}

void LatencyDialog::setDevices(const QString& tracked, const QString& reference) {
  remember(trackedBox_, tracked);
  trackedBox_->setCurrentText(tracked);
  remember(referenceBox_, reference);
  referenceBox_->setCurrentText(reference);
}

void LatencyDialog::startRecording() {
  trackedPath_.clear();
  referencePath_.clear();
  recording_ = true;
  record_->setText(tr("Stop and estimate"));
  label_->setText(tr("Recording…"));
  buttons_->button(QDialogButtonBox::Ok)->setEnabled(false);
}

const calibration::LatencyResult& LatencyDialog::stopRecording() {
  recording_ = false;
  record_->setText(tr("Record"));
  result_ = calibration::estimateLatency(calibration::speedSignal(referencePath_), calibration::speedSignal(trackedPath_));
  switch (result_.status) {
    case calibration::LatencyStatus::Ok:
      label_->setText(tr("Latency %1 ms (correlation %2)").arg(NumberFormat::number(result_.latency * 1000.0, 1)).arg(NumberFormat::number(result_.correlation, 2)));
      break;
    case calibration::LatencyStatus::TooShort: label_->setText(tr("Too short: record longer.")); break;
    case calibration::LatencyStatus::NonFinite: label_->setText(tr("The devices sent invalid samples.")); break;
    case calibration::LatencyStatus::Flat: label_->setText(tr("No motion: move the tool.")); break;
    case calibration::LatencyStatus::WeakCorrelation:
      label_->setText(tr("The motions do not match (correlation %1): move them together.").arg(NumberFormat::number(result_.correlation, 2)));
      break;
  }
  buttons_->button(QDialogButtonBox::Ok)->setEnabled(result_.ok());
  return result_;
}

void LatencyDialog::onPose(const tracking::RawPose& pose, bool fromReference) {
  const QString name = QString::fromStdString(pose.device);
  // with one source, the device name tells which is which
  const bool isTracked = !fromReference && name == trackedBox_->currentText();
  const bool isReference = (fromReference || reference_ == tracked_) && name == referenceBox_->currentText();
  remember(fromReference ? referenceBox_ : trackedBox_, name);
  if (reference_ == tracked_) remember(referenceBox_, name);
  if (!recording_) return;
  // one source: its own timestamps; two: this program's receive clock, common to both
  const double t = reference_ == tracked_ ? pose.time : static_cast<double>(clock_.nsecsElapsed()) * 1e-9;
  const calibration::TimedPosition sample{t, pose.matrix.topRightCorner<3, 1>()};
  if (isTracked) trackedPath_.push_back(sample);
  if (isReference) referencePath_.push_back(sample);
}

}  // namespace microsim::gui
