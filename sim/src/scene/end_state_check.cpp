#include "microsim/sim/scene/end_state_check.h"

#include "microsim/sim/collide/end_gap.h"
#include "microsim/sim/collide/point_triangle.h"
#include "microsim/sim/scene/circumference_frame.h"
#include "microsim/sim/scene/scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

namespace microsim::sim {

namespace {

/// What the check knows of the severed vessel: its two ends and the angle frame.
struct EndStateView {
  const SceneDef& def;
  const SpringModel& model;
  const Points& x;
  std::array<const SceneVessel*, 2> ends;
  CircumferenceFrame frame;
  Vec3 origin = Vec3::Zero();  ///< a point of end 0's axis line (mm)

  double angleOf(const Vec3& p) const { return frame.angleDeg(p - origin); }
  /// Which end (0, 1) face `face` is on, and its surface; end −1 off the severed vessel.
  std::pair<int, VesselSurface> holeOf(int face) const {
    const auto on = vesselSurfaceOf(def.vessels, face);
    if (!on) return {-1, VesselSurface::NotAVessel};
    const SceneVessel& v = def.vessels[static_cast<std::size_t>(on->first)];
    const bool severed = (v.end == 0 || v.end == 1) && ends[static_cast<std::size_t>(v.end)] == &v;
    return {severed ? v.end : -1, on->second};
  }
};

Vec3 facePoint(const SpringModel& model, const Points& x, int face, const Vec3& barycentric) {
  const auto& t = model.triangles()[static_cast<std::size_t>(face)];
  return barycentric[0] * x.col(t[0]) + barycentric[1] * x.col(t[1]) + barycentric[2] * x.col(t[2]);
}

/// The unit direction of p away from the line through `origin` along unit `axis`; zero on it.
Vec3 radialOf(const Vec3& p, const Vec3& origin, const Vec3& axis) {
  Vec3 r = p - origin;
  r -= r.dot(axis) * axis;
  const double n = r.norm();
  return n > 0.0 ? Vec3(r / n) : Vec3(Vec3::Zero());
}

/// No broken link between thread nodes a and b.
bool threadWhole(const suture::SutureState& thread, int a, int b) {
  for (int l = std::min(a, b); l < std::max(a, b); ++l)
    if (thread.alive[static_cast<std::size_t>(l)] == 0) return false;
  return true;
}

/// The circular mean of angles (degrees), [0, 360); NaN for none.
double meanAngleDeg(const CircumferenceFrame& frame, const std::vector<double>& degs) {
  Vec3 sum = Vec3::Zero();
  for (double d : degs) sum += frame.direction(d);
  return sum.norm() > 1e-12 ? frame.angleDeg(sum) : std::numeric_limits<double>::quiet_NaN();
}

// --- over-tight stitches -------------------------------------------------------------------

/// One hole's bite to its end's cut lip, at rest and now (mm); none through the cut face.
struct HoleBite {
  double rest = 0.0;
  double now = 0.0;
  double angleDeg = 0.0;
};

std::optional<HoleBite> holeBite(const EndStateView& v, const suture::Pierce& hole) {
  const auto [end, surface] = v.holeOf(hole.face);
  if (end < 0 || (surface != VesselSurface::Outer && surface != VesselSurface::Inner))
    return std::nullopt;
  const SceneVessel& vessel = *v.ends[static_cast<std::size_t>(end)];
  const VesselHull hull = surface == VesselSurface::Outer ? VesselHull::Outer : VesselHull::Inner;
  const Points& rest = v.model.restPositions();
  const Vec3 atRest = facePoint(v.model, rest, hole.face, hole.barycentric);
  const Vec3 now = facePoint(v.model, v.x, hole.face, hole.barycentric);
  // the lip at the hole's own angle in the material: its rest direction
  const Vec3 d = radialOf(atRest, vessel.def.origin, vessel.def.direction.normalized());
  HoleBite b;
  b.rest = (collide::cutRingLip(v.model, rest, vessel, d, hull) - atRest).norm();
  b.now = (collide::cutRingLip(v.model, v.x, vessel, d, hull) - now).norm();
  b.angleDeg = v.angleOf(atRest);
  return b;
}

void addStitchCompressions(const EndStateView& v, const suture::SutureState& thread,
                           const EndStateParams& params, EndStateResult& r) {
  const auto& pierces = thread.pierces;
  const auto endOf = [&](std::size_t i) { return v.holeOf(pierces[i].face).first; };
  const auto joined = [&](std::size_t i, std::size_t j) {
    return threadWhole(thread, pierces[i].node, pierces[j].node);
  };
  for (std::size_t i = 0; i + 1 < pierces.size(); ++i) {
    // a crossing from one end to the other, with each end's other hole of its passage
    const int a = endOf(i), b = endOf(i + 1);
    if (a < 0 || b < 0 || a == b || !joined(i, i + 1)) continue;
    std::vector<std::size_t> holes{i, i + 1};
    if (i > 0 && endOf(i - 1) == a && joined(i - 1, i)) holes.push_back(i - 1);
    if (i + 2 < pierces.size() && endOf(i + 2) == b && joined(i + 1, i + 2)) holes.push_back(i + 2);

    StitchCompression s;
    s.crossing = static_cast<int>(i);
    std::vector<double> angles;
    for (std::size_t h : holes) {
      const std::optional<HoleBite> bite = holeBite(v, pierces[h]);
      if (!bite) continue;
      ++s.holes;
      s.restMm += bite->rest;
      s.nowMm += bite->now;
      angles.push_back(bite->angleDeg);
    }
    if (!(s.restMm > 0.0)) continue;
    s.angleDeg = meanAngleDeg(v.frame, angles);
    s.compression = 1.0 - s.nowMm / s.restMm;
    r.stitches.push_back(s);
    if (s.compression > params.overTightCompression)
      r.findings.push_back(
          {EndStateKind::OverTightStitch, s.angleDeg, s.compression, params.overTightCompression});
  }
}

// --- thread in the lumen ------------------------------------------------------------------

/// How deep p lies inside `end`'s lumen (mm, < 0 in or beyond the wall); NaN when p is not
/// between its clamped and its cut ring along its axis.
double lumenDepth(const EndStateView& v, const SceneVessel& end, const Vec3& p) {
  const Vec3 axis = end.def.direction.normalized();
  const int perRing = end.def.nodesPerRing;
  const int cutInner = end.firstNode + (end.def.rings - 1) * 2 * perRing;  // mesh/vessel.h order
  Vec3 cutCentre = Vec3::Zero();
  for (int j = 0; j < perRing; ++j) cutCentre += v.x.col(cutInner + j);
  cutCentre /= perRing;
  if ((p - cutCentre).dot(axis) >= 0.0 || (p - end.def.origin).dot(axis) <= 0.0)
    return std::numeric_limits<double>::quiet_NaN();

  // the nearest inner face, and which side of it p is on
  double nearest = std::numeric_limits<double>::infinity();
  double depth = std::numeric_limits<double>::quiet_NaN();
  for (int f = end.innerSurface.begin; f < end.innerSurface.end; ++f) {
    const auto& t = v.model.triangles()[static_cast<std::size_t>(f)];
    const Vec3 a = v.x.col(t[0]), b = v.x.col(t[1]), c = v.x.col(t[2]);
    const collide::PointTriangleClosest q = collide::closestPointTriangle(p, a, b, c);
    if (q.distance >= nearest) continue;
    const Vec3 n = (b - a).cross(c - a);
    if (n.norm() < 1e-300) continue;
    nearest = q.distance;
    depth = n.normalized().dot(p - q.point);
  }
  return depth;
}

void addThreadInLumen(const EndStateView& v, const suture::SutureState& thread,
                      const EndStateParams& params, EndStateResult& r) {
  const int first = v.def.needle ? v.def.needle->suture.needleLinks : 0;
  const int last = static_cast<int>(thread.x.cols()) - 1;

  // where thread belongs: a stitch's crossing between its inner holes, a passage's track
  std::vector<bool> crossing(static_cast<std::size_t>(last + 1), false);
  for (std::size_t i = 0; i + 1 < thread.pierces.size(); ++i) {
    const auto [a, sa] = v.holeOf(thread.pierces[i].face);
    const auto [b, sb] = v.holeOf(thread.pierces[i + 1].face);
    const bool acrossTheLine = a != b && sa != VesselSurface::Outer && sb != VesselSurface::Outer;
    const bool throughTheWall =
        a == b && !(sa == VesselSurface::Inner && sb == VesselSurface::Inner);
    if (a < 0 || b < 0 || !(acrossTheLine || throughTheWall)) continue;
    const int lo = std::min(thread.pierces[i].node, thread.pierces[i + 1].node);
    const int hi = std::max(thread.pierces[i].node, thread.pierces[i + 1].node);
    for (int k = lo + 1; k < hi; ++k) crossing[static_cast<std::size_t>(k)] = true;
  }

  // each run of neighbouring nodes beyond the margin: one finding at its deepest node
  const double margin = params.lumenMarginWalls * v.ends[0]->def.wallThickness;
  std::optional<EndStateFinding> run;
  const auto closeRun = [&] {
    if (run) r.findings.push_back(*run);
    run.reset();
  };
  for (int i = first; i <= last; ++i) {
    if (i > first && thread.alive[static_cast<std::size_t>(i - 1)] == 0) closeRun();
    if (crossing[static_cast<std::size_t>(i)]) {
      closeRun();
      continue;
    }
    double depth = std::numeric_limits<double>::quiet_NaN();
    for (const SceneVessel* end : v.ends) {
      const double d = lumenDepth(v, *end, thread.x.col(i));
      if (std::isfinite(d) && !(d <= depth)) depth = d;
    }
    if (std::isfinite(depth) && !(depth <= r.deepestThreadMm)) r.deepestThreadMm = depth;
    if (!(depth > margin)) {
      closeRun();
      continue;
    }
    if (!run || depth > run->measured)
      run = EndStateFinding{EndStateKind::ThreadInLumen, v.angleOf(thread.x.col(i)), depth, margin};
  }
  closeRun();
}

// --- large edge overlap -------------------------------------------------------------------

void addEdgeOverlaps(const EndStateView& v, const EndStateParams& params, EndStateResult& r) {
  const double limit = params.overlapOffsetWalls * v.ends[0]->def.wallThickness;
  const int samples = std::max(1, static_cast<int>(std::lround(360.0 / params.sampleDeg)));

  // at each angle: past each other (s < 0), and by how much the mid-walls are offset
  std::vector<double> offset(static_cast<std::size_t>(samples), 0.0);
  std::vector<bool> over(static_cast<std::size_t>(samples), false);
  for (int k = 0; k < samples; ++k) {
    const Vec3 d = v.frame.direction(360.0 * k / samples);
    std::array<Vec3, 2> mid;
    for (std::size_t e = 0; e < 2; ++e)
      mid[e] = 0.5 * (collide::cutRingLip(v.model, v.x, *v.ends[e], d, VesselHull::Outer) +
                      collide::cutRingLip(v.model, v.x, *v.ends[e], d, VesselHull::Inner));
    const double apart = (mid[1] - mid[0]).dot(v.frame.axis);
    const auto rho = [&](const Vec3& p) {
      const Vec3 rel = p - v.origin;
      return (rel - rel.dot(v.frame.axis) * v.frame.axis).norm();
    };
    if (!(apart < 0.0)) continue;
    const auto i = static_cast<std::size_t>(k);
    offset[i] = std::abs(rho(mid[1]) - rho(mid[0]));
    over[i] = offset[i] > limit;
    r.largestOverlapOffsetMm = std::max(r.largestOverlapOffsetMm, offset[i]);
  }

  // runs of overlapping samples round the circle, each reported at its largest offset
  const auto start = std::find(over.begin(), over.end(), false);
  const int from = start == over.end() ? 0 : static_cast<int>(start - over.begin());
  int best = -1;  // the run's sample of largest offset, -1 outside a run
  const auto closeRun = [&] {
    if (best >= 0)
      r.findings.push_back({EndStateKind::LargeEdgeOverlap, 360.0 * best / samples,
                            offset[static_cast<std::size_t>(best)], limit});
    best = -1;
  };
  for (int n = 0; n < samples; ++n) {
    const int k = (from + n) % samples;
    if (!over[static_cast<std::size_t>(k)]) {
      closeRun();
      continue;
    }
    if (best < 0 || offset[static_cast<std::size_t>(k)] > offset[static_cast<std::size_t>(best)])
      best = k;
  }
  closeRun();
}

}  // namespace

EndStateResult checkEndState(const SceneDef& def, const Points& x,
                             const suture::SutureState* thread, const EndStateParams& params) {
  EndStateResult r;
  const auto ends = collide::severedEnds(def.vessels);
  if (ends[0] == nullptr || ends[1] == nullptr) {
    r.status = EndStateStatus::NoSeveredVessel;
    return r;
  }
  const Vec3 axis = ends[0]->def.direction.normalized();
  const Vec3 cutCentre = ends[0]->def.origin + ends[0]->def.length * axis;
  const EndStateView v{
      def,
      def.tissue.model,
      x,
      ends,
      circumferenceFrame(axis,
                         params.angleZero ? *params.angleZero : Vec3(def.camera.eye - cutCentre)),
      ends[0]->def.origin};
  r.lumenMarginMm = params.lumenMarginWalls * ends[0]->def.wallThickness;
  r.overlapOffsetLimitMm = params.overlapOffsetWalls * ends[0]->def.wallThickness;
  if (thread != nullptr) {
    addStitchCompressions(v, *thread, params, r);
    addThreadInLumen(v, *thread, params, r);
  }
  if (params.sampleDeg > 0.0) addEdgeOverlaps(v, params, r);
  return r;
}

EndStateResult checkEndState(const Scene& scene, const EndStateParams& params) {
  return checkEndState(scene.def(), scene.tissueState().x, scene.sutureState(), params);
}

}  // namespace microsim::sim
