#include "microsim/sim/scene/stitch_script.h"

#include "microsim/sim/suture/suture_model.h"

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

namespace microsim::sim {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

struct Ends {
  const SceneVessel* a = nullptr;
  const SceneVessel* b = nullptr;
};

Ends severedEnds(const SceneDef& scene) {
  Ends out;
  for (const SceneVessel& v : scene.vessels) {
    if (v.end == 0 && !out.a) out.a = &v;
    if (v.end == 1 && out.a && v.object == out.a->object) out.b = &v;
  }
  return out;
}

struct Pass {
  StitchGeometry g;
  double half = 0.0;    // g/2 + b
  double aOut = 0.0;
  double aIn = 0.0;
  double lift = 0.0;    // C's height above the outer wall: h
};

std::optional<Pass> pass(const SceneDef& scene, const StitchScriptDef& def) {
  const Ends ends = severedEnds(scene);
  if (!ends.a || !ends.b || !scene.needle || !scene.forceps[0] || !scene.forceps[1] ||
      scene.needle->suture.needleShape != suture::NeedleShape::Curved)
    return std::nullopt;
  const VesselDef& va = ends.a->def;
  const VesselDef& vb = ends.b->def;
  const Vec3 cutA = va.origin + va.length * va.direction;
  const Vec3 cutB = vb.origin + vb.length * vb.direction;
  Pass p;
  p.g.eu = va.direction.normalized();

  // the vessel's top reference, turned by π/P about the axis onto a face centre
  Vec3 ref = Vec3::UnitZ() - Vec3::UnitZ().dot(p.g.eu) * p.g.eu;
  if (ref.norm() < 1e-9) ref = Vec3::UnitX() - Vec3::UnitX().dot(p.g.eu) * p.g.eu;
  ref.normalize();
  const double phi = std::numbers::pi / va.nodesPerRing;
  p.g.ew = Eigen::AngleAxisd(phi, p.g.eu) * ref;
  p.aOut = va.radius * std::cos(phi);
  p.aIn = (va.radius - va.wallThickness) * std::cos(phi);
  p.g.radius = scene.needle->suture.needleRadius;
  p.half = 0.5 * (cutB - cutA).norm() + def.biteMm;
  if (p.half >= p.g.radius) return std::nullopt;
  p.lift = std::sqrt(p.g.radius * p.g.radius - p.half * p.half);
  if (p.aOut + p.lift - p.g.radius >= p.aIn) return std::nullopt;  // never reaches the lumen
  p.g.center = 0.5 * (cutA + cutB) + (p.aOut + p.lift) * p.g.ew;
  return p;
}

Eigen::Isometry3d blend(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, double f) {
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.linear() = Eigen::Quaterniond(a.linear()).slerp(f, Eigen::Quaterniond(b.linear())).toRotationMatrix();
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
  int steps(double seconds) const { return std::max(1, static_cast<int>(std::lround(seconds / dt_))); }

 private:
  double dt_;
  Recording& out_;
  InputFrame frame_;
};

}  // namespace

Eigen::Isometry3d needleOnPassCircle(const StitchGeometry& g, double psi) {
  const double c = std::cos(psi);
  const double s = std::sin(psi);
  Eigen::Matrix3d r;
  r.col(0) = -c * g.eu - s * g.ew;
  r.col(1) = -s * g.eu + c * g.ew;
  r.col(2) = r.col(0).cross(r.col(1));
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = r;
  pose.translation() = g.center + g.radius * (s * g.eu - c * g.ew);
  return pose;
}

std::optional<StitchGeometry> stitchGeometry(const SceneDef& scene, const StitchScriptDef& def) {
  const std::optional<Pass> p = pass(scene, def);
  if (!p) return std::nullopt;
  return p->g;
}

std::vector<ExpectedPierce> stitchPierces(const SceneDef& scene, const StitchScriptDef& def) {
  const std::optional<Pass> p = pass(scene, def);
  if (!p) return {};
  const double r = p->g.radius;
  const double outer = std::asin(p->half / r);
  const double inner = std::acos((p->aOut + p->lift - p->aIn) / r);
  const double psis[4] = {-outer, -inner, inner, outer};
  std::vector<ExpectedPierce> out;
  for (int k = 0; k < 4; ++k) {
    ExpectedPierce e;
    const double psi = psis[k];
    e.point = p->g.center + r * (std::sin(psi) * p->g.eu - std::cos(psi) * p->g.ew);
    e.angleDeg = std::acos(std::min(1.0, std::abs(std::sin(psi)))) / kDeg;
    e.entry = k == 0 || k == 2;
    e.end = k < 2 ? 0 : 1;
    out.push_back(e);
  }
  return out;
}

/// How far the tools open their jaws at the needle beside the walls (closure 1 − this): just
/// past letting go at the scenes' close_at of 0.8, about 0.2 mm between the tips.
constexpr double kStitchSlightOpening = 0.25;

/// How far a tool draws back along its jaws, from the tips toward the hinge, to leave the
/// needle or before it comes down onto it (mm): the jaws' tips then clear the needle.
constexpr double kStitchToolDrawBackMm = 1.5;

Recording scriptedStitch(const SceneDef& scene, const StitchScriptDef& def) {
  Recording rec;
  const std::optional<Pass> p = pass(scene, def);
  if (!p) return rec;
  rec.metadata = R"({"script":"stitch","version":1})";
  const StitchGeometry& g = p->g;
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
  const Eigen::Isometry3d holderGrip = gripAt(def.gripNode);
  const Eigen::Isometry3d forcepsGrip = gripAt(def.pullGripNode);
  Eigen::Isometry3d park = Eigen::Isometry3d::Identity();
  park.translation() = g.center + 4.0 * g.ew - 3.0 * g.eu;
  Eigen::Isometry3d parkRight = park;
  parkRight.translation() = g.center + 4.0 * g.ew + 3.0 * g.eu;
  FrameWriter w(1.0 / scene.step.rateHz, rec);
  const double start = def.startDeg * kDeg;
  const double stop = def.endDeg * kDeg;

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
    w.hand(Hand::Right, Instrument::NeedleHolder, blend(lying, first, static_cast<double>(k) / n) * holderGrip, 1.0);
    w.emit();
  }

  // 3. turns it about C through both ends
  for (int k = 1, n = w.steps(def.passSeconds); k <= n; ++k) {
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
    back.translation() += kStitchToolDrawBackMm * tool.linear().col(0);
    return back;
  };
  const double slight = 1.0 - kStitchSlightOpening;
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
           1.0 - kStitchSlightOpening * (1.0 - static_cast<double>(k) / n));
    w.emit();
  }
  for (int k = 1, n = w.steps(0.1); k <= n; ++k) {
    // opened no further than it takes to let go (a closure just under close_at): a jaw opened
    // wide would swing down into the wall below
    w.hand(Hand::Right, Instrument::NeedleHolder, holderAt, 1.0 - kStitchSlightOpening * k / n);
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
  const double out = def.pullOutDeg * kDeg;
  for (int k = 1, n = w.steps(1.2); k <= n; ++k) {
    const double psi = stop + (out - stop) * k / n;
    w.hand(Hand::Left, Instrument::Forceps, needleOnPassCircle(g, psi) * forcepsGrip, 1.0);
    w.emit();
  }
  const Eigen::Isometry3d free = needleOnPassCircle(g, out);
  for (int k = 1, n = w.steps(1.0); k <= n; ++k) {
    Eigen::Isometry3d pulled = free;
    pulled.translation() += (def.pullMm * k / n) * g.ew;
    w.hand(Hand::Left, Instrument::Forceps, pulled * forcepsGrip, 1.0);
    w.emit();
  }

  // 5. lets go
  Eigen::Isometry3d done = free;
  done.translation() += def.pullMm * g.ew;
  for (int k = 1, n = w.steps(0.1); k <= n; ++k) {
    w.hand(Hand::Left, Instrument::Forceps, done * forcepsGrip, 1.0 - static_cast<double>(k) / n);
    w.emit();
  }
  return rec;
}

}  // namespace microsim::sim
