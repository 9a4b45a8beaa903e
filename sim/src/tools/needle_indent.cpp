#include "microsim/sim/tools/needle_indent.h"

namespace microsim::sim::tools {

namespace {
/// mm the face's point may lie past the tip before the tip counts as no longer pressing on it:
/// far above the spring's own give (wall force / stiffness, below 0.1 µm), far below a dent
constexpr double kFacePastTip = 1e-3;
}  // namespace

Indentation beginIndentation(const FaceCrossing& entry, double throughDepth) {
  Indentation in;
  in.touch = entry;
  in.throughDepth = throughDepth;
  // an entry comes from the face's front: the normal already points at the tip's side
  in.side = entry.entry ? entry.normal : Vec3(-entry.normal);
  return in;
}

Vec3 indentedPoint(const SpringModel& tissue, const Points& x, const Indentation& in) {
  const auto& t = tissue.triangles()[static_cast<std::size_t>(in.touch.face)];
  const Vec3& b = in.touch.barycentric;
  return b.x() * x.col(t[0]) + b.y() * x.col(t[1]) + b.z() * x.col(t[2]);
}

PointSpring indentationSpring(const SpringModel& tissue, const Indentation& in, const Vec3& tip, double k) {
  const auto& t = tissue.triangles()[static_cast<std::size_t>(in.touch.face)];
  PointSpring s;
  s.nodes = {t[0], t[1], t[2], -1};
  s.weights = {in.touch.barycentric.x(), in.touch.barycentric.y(), in.touch.barycentric.z(), 0.0};
  s.anchor = tip;
  s.k = k;
  return s;
}

double indentationForce(const SpringModel& tissue, const Points& x, const Indentation& in, const Vec3& tip,
                        const Vec3& travel, double k) {
  return k * (tip - indentedPoint(tissue, x, in)).dot(travel);
}

double indentationDepth(const Indentation& in, const Vec3& tip) { return (in.touch.point - tip).dot(in.side); }

bool punctured(const SpringModel& tissue, const Points& x, const Indentation& in, const Vec3& tip,
               const Vec3& travel, double k, double punctureForce) {
  if (indentationForce(tissue, x, in, tip, travel, k) >= punctureForce) return true;
  return in.throughDepth > 0.0 && indentationDepth(in, tip) >= in.throughDepth;
}

bool tipWithdrawn(const SpringModel& tissue, const Points& x, const Indentation& in, const Vec3& tip) {
  // The spring holds the face's point on the tip to within the wall's force over its
  // stiffness (a fraction of a micrometre), on the far side while the tip presses and on the
  // near side while it draws the caught face back: too little to tell the two apart after a
  // solve stopped at its tolerance. So the tip counts as drawn back once it is back on its
  // own side of where it first touched the face, or once the face is clearly past it (moved
  // by something stronger than the spring).
  if (indentationDepth(in, tip) < 0.0) return true;
  return (tip - indentedPoint(tissue, x, in)).dot(in.side) > kFacePastTip;
}

std::vector<int> facesAround(const SpringModel& tissue, int face) {
  const auto& corners = tissue.triangles()[static_cast<std::size_t>(face)];
  std::vector<int> out;
  for (std::size_t f = 0; f < tissue.triangles().size(); ++f)
    for (int c : tissue.triangles()[f])
      if (c == corners[0] || c == corners[1] || c == corners[2]) {
        out.push_back(static_cast<int>(f));
        break;
      }
  return out;
}

}  // namespace microsim::sim::tools
