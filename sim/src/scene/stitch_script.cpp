#include "microsim/sim/scene/stitch_script.h"
#include "scene/pass_recorder.h"

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

namespace microsim::sim {

namespace {

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
    e.angleDeg = std::acos(std::min(1.0, std::abs(std::sin(psi)))) / kRadiansPerDegree;
    e.entry = k == 0 || k == 2;
    e.end = k < 2 ? 0 : 1;
    out.push_back(e);
  }
  return out;
}

Recording scriptedStitch(const SceneDef& scene, const StitchScriptDef& def) {
  const std::optional<Pass> p = pass(scene, def);
  if (!p) return {};
  PassPlan plan;
  plan.circle = p->g;
  plan.startDeg = def.startDeg;
  plan.handOverDeg = def.endDeg;
  plan.pullOutDeg = def.pullOutDeg;
  plan.passSeconds = def.passSeconds;
  plan.gripNode = def.gripNode;
  plan.pullGripNode = def.pullGripNode;
  // the forceps waits above end 0, the holder goes above end 1; the thread is drawn straight up
  plan.forcepsWaits.translation() = p->g.center + 4.0 * p->g.ew - 3.0 * p->g.eu;
  plan.holderGoes.translation() = p->g.center + 4.0 * p->g.ew + 3.0 * p->g.eu;
  plan.pullDirection = p->g.ew;
  plan.pullMm = def.pullMm;
  plan.metadata = R"({"script":"stitch","version":1})";
  return recordPass(scene, plan);
}

}  // namespace microsim::sim
