#include "microsim/sim/scene/back_wall_catch_script.h"
#include "scene/pass_recorder.h"

#include <cmath>
#include <numbers>

namespace microsim::sim {

namespace {

/// How far past the hand-over the forceps turns the needle before it draws the thread: the
/// needle (a 3/8 circle, 135°) is then wholly out, its swage clearDeg + 115° − 135° (20° with
/// the default def) past where the tip left the back wall.
constexpr double kNeedleOutPastHandOverDeg = 115.0;

struct Catch {
  StitchGeometry g;
  Vec3 axisPoint = Vec3::Zero();  // P
  Vec3 axis = Vec3::UnitX();      // end 0's axis, toward its cut
  double startDeg = 0.0;          // ψ
  double handOverDeg = 0.0;
};

// ψ of point x on circle g (needleOnPassCircle: tip = C + R (sin ψ e_u − cos ψ e_w))
double psiOf(const StitchGeometry& g, const Vec3& x) {
  const Vec3 rel = x - g.center;
  return std::atan2(rel.dot(g.eu), -rel.dot(g.ew));
}

std::optional<Catch> catchPass(const SceneDef& scene, const BackWallCatchDef& def) {
  const SceneVessel* end0 = nullptr;
  for (const SceneVessel& v : scene.vessels)
    if (v.end == 0) {
      end0 = &v;
      break;
    }
  if (!end0 || !scene.needle || !scene.forceps[0] || !scene.forceps[1] ||
      scene.needle->suture.needleShape != suture::NeedleShape::Curved)
    return std::nullopt;
  const VesselDef& v = end0->def;
  Catch c;
  c.axis = v.direction.normalized();
  const Vec3& axis = c.axis;
  c.axisPoint = v.origin + (v.length - def.biteMm) * axis;

  // the vessel's top (as the stitch reads it) and the side that faces away from the microscope
  Vec3 top = Vec3::UnitZ() - Vec3::UnitZ().dot(axis) * axis;
  if (top.norm() < 1e-9) top = Vec3::UnitX() - Vec3::UnitX().dot(axis) * axis;
  top.normalize();
  Vec3 side = axis.cross(top);
  if ((scene.camera.eye - c.axisPoint).dot(side) > 0.0) side = -side;
  const auto onOuterWall = [&](double thetaDeg) {
    return c.axisPoint + v.radius * (std::cos(thetaDeg * kRadiansPerDegree) * top +
                                     std::sin(thetaDeg * kRadiansPerDegree) * side);
  };
  const Vec3 entry = onOuterWall(def.entryDeg);
  const Vec3 exit = onOuterWall(def.catchDeg);

  const double radius = scene.needle->suture.needleRadius;
  const Vec3 chord = exit - entry;
  const double half = 0.5 * chord.norm();
  if (!(half > 0.0) || half >= radius) return std::nullopt;
  const Vec3 mid = 0.5 * (entry + exit);
  Vec3 away = axis.cross(chord).normalized();
  if (away.dot(mid - c.axisPoint) < 0.0) away = -away;
  c.g.center = mid + std::sqrt(radius * radius - half * half) * away;
  c.g.radius = radius;
  c.g.ew = top;
  c.g.eu = side;
  // the tip runs toward increasing ψ: turn the parametrisation so that it goes from the entry
  // to the exit the short way, through the lumen
  if (std::remainder(psiOf(c.g, exit) - psiOf(c.g, entry), 2.0 * std::numbers::pi) < 0.0)
    c.g.eu = -side;
  const double psiEntry = psiOf(c.g, entry);
  const double psiExit =
      psiEntry + std::abs(std::remainder(psiOf(c.g, exit) - psiEntry, 2.0 * std::numbers::pi));
  c.startDeg = psiEntry / kRadiansPerDegree - def.leadDeg;
  c.handOverDeg = psiExit / kRadiansPerDegree + def.clearDeg;
  return c;
}

}  // namespace

std::optional<StitchGeometry> backWallCatchGeometry(const SceneDef& scene,
                                                    const BackWallCatchDef& def) {
  const std::optional<Catch> c = catchPass(scene, def);
  if (!c) return std::nullopt;
  return c->g;
}

Recording scriptedBackWallCatch(const SceneDef& scene, const BackWallCatchDef& def) {
  const std::optional<Catch> c = catchPass(scene, def);
  if (!c) return {};
  const StitchGeometry& g = c->g;
  PassPlan plan;
  plan.circle = g;
  plan.startDeg = c->startDeg;
  plan.handOverDeg = c->handOverDeg;
  plan.pullOutDeg = c->handOverDeg + kNeedleOutPastHandOverDeg;
  plan.passSeconds = def.passSeconds;
  plan.gripNode = def.gripNode;
  plan.pullGripNode = def.pullGripNode;
  // both tools keep to the needle's side of the vessel and above it: the forceps waits
  // behind end 0, the holder goes off beyond the cut; the thread is drawn out from the
  // vessel through the circle's centre
  const Vec3& axis = c->axis;
  const Vec3 out = (g.center - c->axisPoint).normalized();
  plan.forcepsWaits.translation() = g.center + 4.0 * g.ew + 1.0 * out - 3.0 * axis;
  plan.holderGoes.translation() = g.center + 4.0 * g.ew - 1.0 * out + 3.0 * axis;
  plan.pullDirection = out;
  plan.pullMm = def.pullMm;
  plan.metadata = R"({"script":"back-wall-catch","version":1})";
  return recordPass(scene, plan);
}

}  // namespace microsim::sim
