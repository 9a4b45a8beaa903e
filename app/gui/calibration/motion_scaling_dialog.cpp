#include "gui/calibration/motion_scaling_dialog.h"

#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>

namespace microsim::gui {

MotionScalingDialog::MotionScalingDialog(double handPerScene, const Eigen::Vector3d& anchor, QWidget* parent)
    : QDialog(parent) {
  setWindowTitle(tr("Motion scaling"));
  ratio_ = new QDoubleSpinBox(this);
  ratio_->setRange(0.1, 20.0);
  ratio_->setDecimals(2);
  ratio_->setSingleStep(0.25);
  ratio_->setValue(handPerScene);
  ratio_->setSuffix(tr(" mm per mm"));
  auto* anchorRow = new QHBoxLayout;
  for (int i = 0; i < 3; ++i) {
    anchor_[i] = new QDoubleSpinBox(this);
    anchor_[i]->setRange(-1000.0, 1000.0);
    anchor_[i]->setDecimals(2);
    anchor_[i]->setValue(anchor(i));
    anchor_[i]->setSuffix(tr(" mm"));
    anchorRow->addWidget(anchor_[i]);
  }
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* form = new QFormLayout(this);
  form->addRow(tr("Hand motion per scene motion:"), ratio_);
  form->addRow(tr("Fixed scene point (x, y, z):"), anchorRow);
  form->addRow(buttons);
}

double MotionScalingDialog::handPerScene() const { return ratio_->value(); }

Eigen::Vector3d MotionScalingDialog::anchor() const {
  return {anchor_[0]->value(), anchor_[1]->value(), anchor_[2]->value()};
}

}  // namespace microsim::gui
