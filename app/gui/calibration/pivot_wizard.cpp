#include "gui/calibration/pivot_wizard.h"

#include "gui/number_format.h"

#include "tracking/tracker_source.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>

namespace microsim::gui {

class PivotWizard::CollectWizardPage : public QWizardPage {
 public:
  explicit CollectWizardPage(PivotWizard* wizard) : wizard_(wizard) {
    setTitle(PivotWizard::tr("Pivot the tool"));
    setSubTitle(PivotWizard::tr("Hold the tip still in the divot and tilt the tool in every direction "
                                "(at least %1°). Poses are collected automatically.")
                    .arg(NumberFormat::number(wizard->collector_.options().solve.minSpreadDeg, 0)));
    progress_ = new QProgressBar(this);
    progress_->setRange(0, wizard->collector_.options().targetPoses);
    spread_ = new QLabel(this);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(progress_);
    layout->addWidget(spread_);
    layout->addStretch();
    refresh();
  }

  bool isComplete() const override { return wizard_->collector_.ready(); }

  void refresh() {
    const calibration::PivotCollector& c = wizard_->collector_;
    progress_->setValue(std::min(c.count(), progress_->maximum()));
    spread_->setText(c.spreadEnough() ? PivotWizard::tr("Spread %1° — enough").arg(NumberFormat::number(c.spreadDeg(), 1))
                                      : PivotWizard::tr("Spread %1° — tilt further").arg(NumberFormat::number(c.spreadDeg(), 1)));
    Q_EMIT completeChanged();
  }

 private:
  PivotWizard* wizard_;
  QProgressBar* progress_;
  QLabel* spread_;
};

class PivotWizard::ResultWizardPage : public QWizardPage {
 public:
  explicit ResultWizardPage(PivotWizard* wizard) : wizard_(wizard) {
    setTitle(PivotWizard::tr("Tip offset"));
    summary_ = new QLabel(this);
    summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    verdict_ = new QLabel(this);
    verdict_->setWordWrap(true);
    auto* redo = new QPushButton(PivotWizard::tr("Collect again"), this);
    connect(redo, &QPushButton::clicked, wizard, &PivotWizard::redo);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(summary_);
    layout->addWidget(verdict_);
    layout->addWidget(redo, 0, Qt::AlignLeft);
    layout->addStretch();
  }

  void initializePage() override {
    wizard_->result_ = wizard_->collector_.solve();
    const calibration::PivotResult& r = wizard_->result_;
    summary_->setText(PivotWizard::tr("Tip (tool frame): %1, %2, %3 mm\nPivot (tracker frame): %4, %5, %6 mm\n"
                                      "RMS error %7 mm, largest %8 mm\n%9 poses, spread %10°")
                          .arg(NumberFormat::number(r.tipOffset.x(), 2))
                          .arg(NumberFormat::number(r.tipOffset.y(), 2))
                          .arg(NumberFormat::number(r.tipOffset.z(), 2))
                          .arg(NumberFormat::number(r.pivot.x(), 2))
                          .arg(NumberFormat::number(r.pivot.y(), 2))
                          .arg(NumberFormat::number(r.pivot.z(), 2))
                          .arg(NumberFormat::number(r.rmsError, 3))
                          .arg(NumberFormat::number(r.maxError, 3))
                          .arg(r.poseCount)
                          .arg(NumberFormat::number(r.spreadDeg, 1)));
    verdict_->setText(PivotWizard::describe(r.status));
    Q_EMIT wizard_->solved(r);
  }

  bool isComplete() const override { return wizard_->result_.accepted(); }

 private:
  PivotWizard* wizard_;
  QLabel* summary_;
  QLabel* verdict_;
};

PivotWizard::PivotWizard(tracking::TrackerSource* source, calibration::PivotCollectorOptions options, QWidget* parent)
    : QWizard(parent), source_(source), collector_(options) {
  setWindowTitle(tr("Pivot calibration"));
  setOption(QWizard::NoBackButtonOnLastPage, false);

  // the device and the hand
  auto* device = new QWizardPage(this);
  device->setTitle(tr("Tool"));
  device->setSubTitle(tr("Choose the tracked device of the tool to calibrate."));
  deviceBox_ = new QComboBox(device);
  deviceBox_->setEditable(true);
  handBox_ = new QComboBox(device);
  handBox_->addItem(tr("Left hand"), static_cast<int>(sim::Hand::Left));
  handBox_->addItem(tr("Right hand"), static_cast<int>(sim::Hand::Right));
  auto* form = new QFormLayout(device);
  form->addRow(tr("Device:"), deviceBox_);
  form->addRow(tr("Hand:"), handBox_);
  setPage(DevicePage, device);

  collectPage_ = new CollectWizardPage(this);
  setPage(CollectPage, collectPage_);
  resultPage_ = new ResultWizardPage(this);
  setPage(ResultPage, resultPage_);

  // collect while the collection page is shown
  connect(this, &QWizard::currentIdChanged, this, [this](int id) {
    if (id == CollectPage) {
      collector_.reset();
      collectPage_->refresh();
    }
  });
  if (source_ != nullptr) connect(source_, &tracking::TrackerSource::poseAccepted, this, &PivotWizard::onPose);
}

void PivotWizard::setDevice(const QString& device, sim::Hand hand) {
  if (deviceBox_->findText(device) < 0) deviceBox_->addItem(device);
  deviceBox_->setCurrentText(device);
  handBox_->setCurrentIndex(handBox_->findData(static_cast<int>(hand)));
}

QString PivotWizard::device() const { return deviceBox_->currentText(); }

sim::Hand PivotWizard::hand() const { return static_cast<sim::Hand>(handBox_->currentData().toInt()); }

QString PivotWizard::describe(calibration::PivotStatus status) {
  switch (status) {
    case calibration::PivotStatus::Ok: return tr("Accepted: the error is within the threshold.");
    case calibration::PivotStatus::TooFewPoses: return tr("Too few poses: collect again.");
    case calibration::PivotStatus::NonFinite: return tr("The tracker sent invalid poses: collect again.");
    case calibration::PivotStatus::InsufficientSpread: return tr("The tool was not tilted enough: collect again.");
    case calibration::PivotStatus::RmsAboveThreshold:
      return tr("The error is above the threshold (the tip slipped or the tool bent): collect again.");
  }
  return {};
}

void PivotWizard::onPose(const tracking::RawPose& pose) {
  const QString name = QString::fromStdString(pose.device);
  if (deviceBox_->findText(name) < 0) deviceBox_->addItem(name);
  if (currentId() != CollectPage || name != device() || !pose.hasRotation) return;
  if (collector_.count() >= collector_.options().targetPoses && collector_.ready()) return;
  if (collector_.add(Eigen::Isometry3d(pose.matrix))) {
    collectPage_->refresh();
    Q_EMIT collectionChanged(collector_.count(), collector_.spreadDeg());
  }
}

void PivotWizard::redo() {
  if (currentId() == ResultPage) back();
}

}  // namespace microsim::gui
