#pragma once
// A scene whose thread is tied in a knot, and the hands that pull it tight: the shipped scene
// with its needle's suture replaced by a thread (no needle) laid in an analytic knot of the
// recogniser's tests (bench/knot_geometry.h's throws in a row; the surgeon's knot is a left
// double throw, then a right single), scaled to a quarter, 300 equal links, 12 mm above the
// vessel. The forceps take the two ends (upright, closing across the thread's third node from
// each end from the third frame: jaws laid along the thread would lie on the knot, and jaws
// are solid to it) and, from the sixth, pull them apart 0.01 mm a frame each along the line
// between them. Shared by the engine's scene test and the CLI's report test.
#include "bench/knot_geometry.h"

#include "microsim/sim/scene/scene.h"

#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace microsim::testing {

inline constexpr int kKnotSceneLinks = 300;

/// The scene described above with its thread tied in `throws` (each: its wraps and whether it
/// is right-handed, knot_geometry.h's throwsInARow) instead; nullopt when the shipped scene
/// does not load.
inline std::optional<sim::SceneDef> knotSceneDef(const std::string& sourceRoot,
                                                 const std::vector<std::pair<int, bool>>& throws) {
  sim::SceneDefLoad load = sim::loadSceneDef(sourceRoot + "/resources/scenes/anastomosis.json");
  if (!std::holds_alternative<sim::SceneDef>(load)) return std::nullopt;
  sim::SceneDef def = std::get<sim::SceneDef>(std::move(load));
  namespace kt = sim::suture::knot_test;
  sim::Points x = kt::evenlySpaced(kt::throwsInARow(throws).points(), 0.25, kKnotSceneLinks);
  x.colwise() += sim::Vec3(0.0, 0.0, 12.0) - x.col(0);
  sim::NeedleDef& needle = *def.needle;
  needle.suture.needleLinks = 0;
  needle.suture.links = kKnotSceneLinks;
  needle.suture.length = kt::polylineLength(x);
  needle.initialShape = x;
  return def;
}

/// The scene described above (the shipped scene read from `sourceRoot`); nullopt when the
/// shipped scene does not load.
inline std::optional<sim::SceneDef> surgeonsKnotSceneDef(const std::string& sourceRoot) {
  return knotSceneDef(sourceRoot, {{2, false}, {1, true}});
}

/// A forceps whose jaws lie along the thread's end at node `end` (`inward` = +1 when the
/// thread runs on from it to higher nodes, −1 to lower), its tip just beyond the end.
inline sim::HandInput forcepsOnThreadEnd(const sim::Points& x, int end, int inward,
                                         double closure) {
  const sim::Vec3 along = (x.col(end) - x.col(end + inward * 6)).normalized();
  sim::HandInput h;
  h.tracked = true;
  h.instrument = sim::Instrument::Forceps;
  h.position = x.col(end) + 0.05 * along;
  // the tool's x axis (tip → hinge) runs back along the thread
  h.orientation = Eigen::Quaterniond::FromTwoVectors(sim::Vec3::UnitX(), -along);
  h.closure = closure;
  return h;
}

/// A forceps standing upright over node `node` (its tip there, the jaws rising from it and
/// opening across the thread): the jaws, 3 mm long, stay clear of a small knot beside it.
inline sim::HandInput forcepsAcrossThread(const sim::Points& x, int node, double closure) {
  const sim::Vec3 along = (x.col(node + 1) - x.col(node - 1)).normalized();
  const sim::Vec3 up = sim::Vec3::UnitZ();
  const sim::Vec3 across = up.cross(along).normalized();
  Eigen::Matrix3d frame;
  frame.col(0) = up;  // tip → hinge
  frame.col(1) = across;  // the jaws open this way
  frame.col(2) = up.cross(across);
  sim::HandInput h;
  h.tracked = true;
  h.instrument = sim::Instrument::Forceps;
  h.position = x.col(node);
  h.orientation = Eigen::Quaterniond(frame);
  h.closure = closure;
  return h;
}

/// Frame `k` (0-based) of the pull, for a thread whose nodes were `start` at the beginning.
inline sim::InputFrame knotPullFrame(const sim::Points& start, int k) {
  const int last = static_cast<int>(start.cols()) - 1;
  const sim::Vec3 apart = (start.col(last) - start.col(0)).normalized();
  const double pull = k < 5 ? 0.0 : 0.01 * (k - 5);
  const double closure = k < 2 ? 0.0 : 1.0;
  sim::InputFrame f;
  f.time = 0.01 * (k + 1);
  f.hand(sim::Hand::Left) = forcepsAcrossThread(start, 2, closure);
  f.hand(sim::Hand::Left).position -= pull * apart;
  f.hand(sim::Hand::Right) = forcepsAcrossThread(start, last - 2, closure);
  f.hand(sim::Hand::Right).position += pull * apart;
  return f;
}

}  // namespace microsim::testing
