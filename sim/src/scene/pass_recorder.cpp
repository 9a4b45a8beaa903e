#include "scene/pass_recorder.h"

#include "microsim/sim/suture/suture_model.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace microsim::sim {

namespace {

/// How far the tools open their jaws at the needle beside the walls (closure 1 − this): just
/// past letting go at the scenes' close_at of 0.8, about 0.2 mm between the tips.
constexpr double kSlightOpening = 0.25;

/// How far a tool draws back along its jaws, from the tips toward the hinge, to leave the
/// needle or before it comes down onto it (mm): the jaws' tips then clear the needle.
constexpr double kToolDrawBackMm = 1.5;

Eigen::Isometry3d blend(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, double f) {
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.linear() =
      Eigen::Quaterniond(a.linear()).slerp(f, Eigen::Quaterniond(b.linear())).toRotationMatrix();
  out.translation() = (1.0 - f) * a.translation() + f * b.translation();
  return out;
}

class FrameWriter {
 public:
  FrameWriter(double dt, Recording& out) : dt_(dt), out_(out) {}

  void hand(Hand h, Instrument instrument, const Eigen::Isometry3d& pose, double closure) {
    HandInput& in = frame_.hand(h);
    in.instrument = instrument;
    in.tracked = true;
    in.position = pose.translation();
    in.orientation = Eigen::Quaterniond(pose.linear()).normalized();
    in.closure = closure;
  }
  void emit() {
    frame_.time = static_cast<double>(out_.frames.size()) * dt_;
    out_.frames.push_back(frame_);
  }
  int steps(double seconds) const {
    return std::max(1, static_cast<int>(std::lround(seconds / dt_)));
  }

 private:
  double dt_;
  Recording& out_;
  InputFrame frame_;
};

}  // namespace

Recording recordPass(const SceneDef& scene, const PassPlan& plan) {
  Recording rec;
  rec.metadata = plan.metadata;
  const StitchGeometry& g = plan.circle;
  const suture::SutureModel needle(scene.needle->suture);
  // both tools take the needle across its plane, jaws (the tool's +x, from the tips back to
  // the hinge) along the needle frame's normal: the one direction that does not turn as the
  // needle turns, so the jaws stay beside the arc rather than sweep through the walls
  const auto gripAt = [&](int node) {
    Eigen::Isometry3d grip = Eigen::Isometry3d::Identity();
    grip.linear() = Eigen::AngleAxisd(-0.5 * std::numbers::pi, Vec3::UnitY()).toRotationMatrix();
    grip.translation() = needle.needleShape().col(std::min(node, needle.needleLinks()));
    return grip;
  };
  const Eigen::Isometry3d holderGrip = gripAt(plan.gripNode);
  const Eigen::Isometry3d forcepsGrip = gripAt(plan.pullGripNode);
  const Eigen::Isometry3d& park = plan.forcepsWaits;
  const Eigen::Isometry3d& parkRight = plan.holderGoes;
  FrameWriter w(1.0 / scene.step.rateHz, rec);
  const double start = plan.startDeg * kRadiansPerDegree;
  const double stop = plan.handOverDeg * kRadiansPerDegree;

  // 1. the holder goes to the needle where it lies and closes on it
  const Eigen::Isometry3d lying = scene.needle->pose;
  for (int k = 0, n = w.steps(0.1); k < n; ++k) {
    w.hand(Hand::Left, Instrument::Forceps, park, 0.0);
    w.hand(Hand::Right, Instrument::NeedleHolder, lying * holderGrip, 0.0);
    w.emit();
  }
  for (int k = 1, n = w.steps(0.1); k <= n; ++k) {
    w.hand(Hand::Right, Instrument::NeedleHolder, lying * holderGrip, static_cast<double>(k) / n);
    w.emit();
  }

  // 2. carries it to the start of the arc
  const Eigen::Isometry3d first = needleOnPassCircle(g, start);
  for (int k = 1, n = w.steps(0.5); k <= n; ++k) {
    w.hand(Hand::Right, Instrument::NeedleHolder,
           blend(lying, first, static_cast<double>(k) / n) * holderGrip, 1.0);
    w.emit();
  }

  // 3. turns it about the circle's centre through the tissue
  for (int k = 1, n = w.steps(plan.passSeconds); k <= n; ++k) {
    const double psi = start + (stop - start) * k / n;
    w.hand(Hand::Right, Instrument::NeedleHolder, needleOnPassCircle(g, psi) * holderGrip, 1.0);
    w.emit();
  }

  // 4. the forceps takes the needle behind its tip, then the holder lets go, as hands pass a
  // needle: the forceps comes from where it waited to beside the needle, its jaws in line with
  // the place it will take, slides down onto it along its jaws and closes; only then does the
  // holder open and draw back along its own jaws (the needle leaves between their tips) and go
  // aside. The needle is held all the while. (Before, the holder let go first and both tools
  // jumped 3–4 mm in one frame: no hand moves so, and the needle, held by nothing, moved the
  // holes it was in; the solves of those frames started far from balance.)
  const Eigen::Isometry3d last = needleOnPassCircle(g, stop);
  const Eigen::Isometry3d holderAt = last * holderGrip;
  const Eigen::Isometry3d forcepsAt = last * forcepsGrip;
  const auto drawnBack = [](const Eigen::Isometry3d& tool) {
    Eigen::Isometry3d back = tool;
    back.translation() += kToolDrawBackMm * tool.linear().col(0);
    return back;
  };
  const double slight = 1.0 - kSlightOpening;
  for (int k = 1, n = w.steps(0.2); k <= n; ++k) {
    const double f = static_cast<double>(k) / n;
    w.hand(Hand::Left, Instrument::Forceps, blend(park, drawnBack(forcepsAt), f), f * slight);
    w.emit();
  }
  for (int k = 1, n = w.steps(0.2); k <= n; ++k) {
    w.hand(Hand::Left, Instrument::Forceps,
           blend(drawnBack(forcepsAt), forcepsAt, static_cast<double>(k) / n), slight);
    w.emit();
  }
  for (int k = 1, n = w.steps(0.1); k <= n; ++k) {
    w.hand(Hand::Left, Instrument::Forceps, forcepsAt,
           1.0 - kSlightOpening * (1.0 - static_cast<double>(k) / n));
    w.emit();
  }
  for (int k = 1, n = w.steps(0.1); k <= n; ++k) {
    // opened no further than it takes to let go (a closure just under close_at): a jaw opened
    // wide would swing down into the wall below
    w.hand(Hand::Right, Instrument::NeedleHolder, holderAt, 1.0 - kSlightOpening * k / n);
    w.emit();
  }
  for (int k = 1, n = w.steps(0.2); k <= n; ++k) {
    w.hand(Hand::Right, Instrument::NeedleHolder,
           blend(holderAt, drawnBack(holderAt), static_cast<double>(k) / n), slight);
    w.emit();
  }
  for (int k = 1, n = w.steps(0.2); k <= n; ++k) {
    const double f = static_cast<double>(k) / n;
    w.hand(Hand::Right, Instrument::NeedleHolder, blend(drawnBack(holderAt), parkRight, f),
           (1.0 - f) * slight);
    w.emit();
  }
  const double out = plan.pullOutDeg * kRadiansPerDegree;
  for (int k = 1, n = w.steps(1.2); k <= n; ++k) {
    const double psi = stop + (out - stop) * k / n;
    w.hand(Hand::Left, Instrument::Forceps, needleOnPassCircle(g, psi) * forcepsGrip, 1.0);
    w.emit();
  }
  const Eigen::Isometry3d free = needleOnPassCircle(g, out);
  for (int k = 1, n = w.steps(1.0); k <= n; ++k) {
    Eigen::Isometry3d pulled = free;
    pulled.translation() += (plan.pullMm * k / n) * plan.pullDirection;
    w.hand(Hand::Left, Instrument::Forceps, pulled * forcepsGrip, 1.0);
    w.emit();
  }

  // 5. lets go
  Eigen::Isometry3d done = free;
  done.translation() += plan.pullMm * plan.pullDirection;
  for (int k = 1, n = w.steps(0.1); k <= n; ++k) {
    w.hand(Hand::Left, Instrument::Forceps, done * forcepsGrip, 1.0 - static_cast<double>(k) / n);
    w.emit();
  }
  return rec;
}

}  // namespace microsim::sim
