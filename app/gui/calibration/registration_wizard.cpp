#include "gui/calibration/registration_wizard.h"

#include "gui/number_format.h"

#include "tracking/tracker_source.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace microsim::gui {

namespace {

enum Column { RoleColumn, SceneX, SceneY, SceneZ, TrackerX, TrackerY, TrackerZ, ColumnCount };
constexpr std::size_t kAveragedPoses = 10;

}  // namespace

class RegistrationWizard::PointsWizardPage : public QWizardPage {
 public:
  explicit PointsWizardPage(RegistrationWizard* wizard) : wizard_(wizard) {
    setTitle(RegistrationWizard::tr("Points"));
    setSubTitle(RegistrationWizard::tr("Type each point's scene position, hold the tip on it and press Touch. "
                                       "Three fiducials at least; check points measure the error elsewhere."));
    auto* add = new QPushButton(RegistrationWizard::tr("Add point"), this);
    auto* touch = new QPushButton(RegistrationWizard::tr("Touch"), this);
    connect(add, &QPushButton::clicked, wizard, [wizard] { wizard->addPoint(Role::Fiducial, Eigen::Vector3d::Zero()); });
    connect(touch, &QPushButton::clicked, wizard, [wizard] { wizard->touch(wizard->table_->currentRow()); });
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(add);
    buttons->addWidget(touch);
    buttons->addStretch();
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(wizard->table_);
    layout->addLayout(buttons);
  }

  bool isComplete() const override {
    int fiducials = 0;
    for (int r = 0; r < wizard_->table_->rowCount(); ++r)
      if (wizard_->roleOf(r) == Role::Fiducial && wizard_->touched(r)) ++fiducials;
    return fiducials >= 3;
  }
  void changed() { Q_EMIT completeChanged(); }

 private:
  RegistrationWizard* wizard_;
};

class RegistrationWizard::ResultWizardPage : public QWizardPage {
 public:
  explicit ResultWizardPage(RegistrationWizard* wizard) : wizard_(wizard) {
    setTitle(RegistrationWizard::tr("Registration"));
    label_ = new QLabel(this);
    label_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    label_->setWordWrap(true);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(label_);
    layout->addStretch();
  }
  void initializePage() override {
    wizard_->solve();
    const calibration::RegistrationResult& r = wizard_->result_;
    QString text = RegistrationWizard::describe(r.status);
    if (r.ok()) {
      text += QLatin1Char('\n') + RegistrationWizard::tr("FRE (fit): %1 mm RMS, %2 mm largest")
                                      .arg(NumberFormat::number(r.freRms, 2))
                                      .arg(NumberFormat::number(r.freMax, 2));
      text += QLatin1Char('\n') + (r.checkCount > 0 ? RegistrationWizard::tr("TRE (%n check point(s)): %1 mm RMS, %2 mm largest",
                                                                             nullptr, r.checkCount)
                                                          .arg(NumberFormat::number(r.treRms, 2))
                                                          .arg(NumberFormat::number(r.treMax, 2))
                                                    : RegistrationWizard::tr("No check points: the TRE is unknown."));
    }
    label_->setText(text);
  }
  bool isComplete() const override { return wizard_->result_.ok(); }

 private:
  RegistrationWizard* wizard_;
  QLabel* label_;
};

RegistrationWizard::RegistrationWizard(tracking::TrackerSource* source, const QString& device,
                                       const Eigen::Vector3d& tipOffset, QWidget* parent)
    : QWizard(parent), source_(source), device_(device), tipOffset_(tipOffset) {
  setWindowTitle(tr("Registration"));
  table_ = new QTableWidget(0, ColumnCount, this);
  table_->setHorizontalHeaderLabels({tr("Role"), tr("Scene x"), tr("Scene y"), tr("Scene z"), tr("Tracker x"),
                                     tr("Tracker y"), tr("Tracker z")});
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  pointsPage_ = new PointsWizardPage(this);
  setPage(PointsPage, pointsPage_);
  setPage(ResultPage, new ResultWizardPage(this));
  connect(table_, &QTableWidget::itemChanged, this, [this] { pointsPage_->changed(); });
  if (source_ != nullptr) connect(source_, &tracking::TrackerSource::poseAccepted, this, &RegistrationWizard::onPose);
}

RegistrationWizard::Role RegistrationWizard::roleOf(int row) const {
  const auto* box = qobject_cast<QComboBox*>(table_->cellWidget(row, RoleColumn));
  return box != nullptr && box->currentIndex() == 1 ? Role::Check : Role::Fiducial;
}

bool RegistrationWizard::touched(int row) const {
  const QTableWidgetItem* item = table_->item(row, TrackerX);
  return item != nullptr && !item->text().isEmpty();
}

int RegistrationWizard::addPoint(Role role, const Eigen::Vector3d& scene) {
  const int row = table_->rowCount();
  table_->insertRow(row);
  auto* box = new QComboBox(table_);
  box->addItems({tr("Fiducial"), tr("Check point")});
  box->setCurrentIndex(role == Role::Check ? 1 : 0);
  connect(box, &QComboBox::currentIndexChanged, this, [this] { pointsPage_->changed(); });
  table_->setCellWidget(row, RoleColumn, box);
  for (int c = 0; c < 3; ++c) table_->setItem(row, SceneX + c, new QTableWidgetItem(QString::number(scene(c))));
  for (int c = 0; c < 3; ++c) {
    auto* item = new QTableWidgetItem;
    item->setFlags(item->flags() & ~Qt::ItemIsEditable);
    table_->setItem(row, TrackerX + c, item);
  }
  table_->setCurrentCell(row, SceneX);
  pointsPage_->changed();
  return row;
}

bool RegistrationWizard::touch(int row) {
  if (row < 0 || row >= table_->rowCount() || recentTips_.empty()) return false;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : recentTips_) mean += p;
  setTracker(row, mean / static_cast<double>(recentTips_.size()));
  return true;
}

void RegistrationWizard::setTracker(int row, const Eigen::Vector3d& tracker) {
  for (int c = 0; c < 3; ++c) table_->item(row, TrackerX + c)->setText(QString::number(tracker(c), 'f', 3));
  pointsPage_->changed();
}

void RegistrationWizard::onPose(const tracking::RawPose& pose) {
  if (QString::fromStdString(pose.device) != device_) return;
  const Eigen::Vector3d tip = pose.matrix.topLeftCorner<3, 3>() * tipOffset_ + pose.matrix.topRightCorner<3, 1>();
  recentTips_.push_back(tip);
  while (recentTips_.size() > kAveragedPoses) recentTips_.pop_front();
}

void RegistrationWizard::solve() {
  std::vector<Eigen::Vector3d> ft, fs, ct, cs;
  for (int r = 0; r < table_->rowCount(); ++r) {
    if (!touched(r)) continue;
    Eigen::Vector3d scene, tracker;
    for (int c = 0; c < 3; ++c) {
      scene(c) = table_->item(r, SceneX + c)->text().toDouble();
      tracker(c) = table_->item(r, TrackerX + c)->text().toDouble();
    }
    (roleOf(r) == Role::Fiducial ? ft : ct).push_back(tracker);
    (roleOf(r) == Role::Fiducial ? fs : cs).push_back(scene);
  }
  const auto matrix = [](const std::vector<Eigen::Vector3d>& v) {
    Eigen::Matrix3Xd m(3, static_cast<Eigen::Index>(v.size()));
    for (std::size_t i = 0; i < v.size(); ++i) m.col(static_cast<Eigen::Index>(i)) = v[i];
    return m;
  };
  result_ = calibration::registerPoints(matrix(ft), matrix(fs), matrix(ct), matrix(cs));
}

QString RegistrationWizard::describe(calibration::RegistrationStatus status) {
  switch (status) {
    case calibration::RegistrationStatus::Ok: return tr("Registered.");
    case calibration::RegistrationStatus::TooFewFiducials: return tr("Touch at least three fiducials.");
    case calibration::RegistrationStatus::SizeMismatch: return tr("Every point needs both positions.");
    case calibration::RegistrationStatus::NonFinite: return tr("A position is not a number.");
    case calibration::RegistrationStatus::Collinear: return tr("The fiducials lie on one line: spread them out.");
  }
  return {};
}

}  // namespace microsim::gui
