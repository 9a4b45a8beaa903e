#pragma once
// Motion scaling: how many mm the hand moves for one mm of the tools in the scene
// (calibration::MotionScaling, z = a + (y − a) / h), and the scene point a that stays
// fixed. A microscope's magnification makes h > 1 natural (finer motion in the scene).

#include <Eigen/Core>

#include <QDialog>

class QDoubleSpinBox;

namespace microsim::gui {

class MotionScalingDialog : public QDialog {
  Q_OBJECT

 public:
  MotionScalingDialog(double handPerScene, const Eigen::Vector3d& anchor, QWidget* parent = nullptr);

  double handPerScene() const;
  Eigen::Vector3d anchor() const;  ///< mm, scene frame

 private:
  QDoubleSpinBox* ratio_ = nullptr;
  QDoubleSpinBox* anchor_[3] = {};
};

}  // namespace microsim::gui
