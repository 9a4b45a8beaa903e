#include "microsim/sim/suture/suture_model.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

namespace microsim::sim::suture {

bool validSutureDef(const SutureDef& d) {
  const auto finitePositive = [](double v) { return std::isfinite(v) && v > 0.0; };
  const auto finiteNonNegative = [](double v) { return std::isfinite(v) && v >= 0.0; };
  if (!finitePositive(d.length) || d.needleLinks < 0 || d.links < d.needleLinks + 1) return false;
  if (d.needleLinks > 0) {
    if (d.needleShape == NeedleShape::Curved && !finitePositive(d.needleRadius)) return false;
    if (d.needleShape == NeedleShape::Straight && !finitePositive(d.needleLength)) return false;
  }
  return finitePositive(d.breakStretch) && finitePositive(d.knotBreakStretch) &&
         finitePositive(d.pierceReleaseDistance) && finitePositive(d.massPerLink) &&
         finitePositive(d.needleMass) && finiteNonNegative(d.contactRadius) &&
         finiteNonNegative(d.friction) && finiteNonNegative(d.drag);
}

SutureModel::SutureModel(const SutureDef& def) : def_(def) {
  assert(validSutureDef(def));
  const int n = def.needleLinks;
  const int links = def.links;

  // needle rest shape in its frame, tip at the origin
  needle_.resize(3, n + 1);
  Vec3 swageTangent = Vec3::UnitX();
  for (int k = 0; k <= n; ++k) {
    const double f = n > 0 ? static_cast<double>(k) / n : 0.0;
    if (def.needleShape == NeedleShape::Curved) {
      const double theta = f * 0.75 * std::numbers::pi;
      needle_.col(k) = Vec3(def.needleRadius * std::sin(theta),
                            def.needleRadius * (1.0 - std::cos(theta)), 0.0);
    } else {
      needle_.col(k) = Vec3(f * def.needleLength, 0.0, 0.0);
    }
  }
  if (n > 0 && def.needleShape == NeedleShape::Curved) {
    const double theta = 0.75 * std::numbers::pi;
    swageTangent = Vec3(std::cos(theta), std::sin(theta), 0.0);
  }

  // rest lengths: needle chords, then equal thread links
  const double threadLink = def.length / (links - n);
  rest_.resize(links);
  for (int i = 0; i < links; ++i)
    rest_[i] = i < n ? (needle_.col(i + 1) - needle_.col(i)).norm() : threadLink;
  prefix_.assign(links + 1, 0.0);
  for (int i = 0; i < links; ++i) prefix_[i + 1] = prefix_[i] + rest_[i];

  // whole chain at rest: needle, then thread along the swage tangent
  restX_.resize(3, links + 1);
  restX_.leftCols(n + 1) = needle_;
  for (int i = n + 1; i <= links; ++i) restX_.col(i) = restX_.col(i - 1) + threadLink * swageTangent;

  // masses: half of each thread link to its ends, the needle's mass spread over its nodes
  std::vector<double> mass(links + 1, 0.0);
  for (int i = n; i < links; ++i) {
    mass[i] += 0.5 * def.massPerLink;
    mass[i + 1] += 0.5 * def.massPerLink;
  }
  if (n > 0)
    for (int k = 0; k <= n; ++k) mass[k] += def.needleMass / (n + 1);
  invMass_.resize(links + 1);
  for (int i = 0; i <= links; ++i) invMass_[i] = 1.0 / mass[i];
}

double SutureModel::arc(int i, int j) const {
  return std::abs(prefix_[j] - prefix_[i]);
}

SutureState SutureState::laidOut(const SutureModel& model, const Eigen::Isometry3d& pose) {
  SutureState s;
  s.x = pose * model.restPositions();
  s.xPrev = s.x;
  s.alive.assign(model.linkCount(), 1);
  s.heldPastBreak.assign(model.linkCount(), 0.0);
  return s;
}

int SutureState::brokenLinkCount() const {
  return static_cast<int>(std::count(alive.begin(), alive.end(), std::uint8_t{0}));
}

std::vector<Piece> chainPieces(const std::vector<std::uint8_t>& alive) {
  std::vector<Piece> out;
  Piece current;
  const int links = static_cast<int>(alive.size());
  for (int i = 0; i < links; ++i) {
    if (alive[i]) continue;
    current.last = i;
    out.push_back(current);
    current.first = i + 1;
  }
  current.last = links;
  out.push_back(current);
  return out;
}

std::vector<double> linkStretches(const SutureModel& model, const SutureState& state) {
  std::vector<double> out(model.linkCount(), 0.0);
  for (int i = 0; i < model.linkCount(); ++i)
    if (state.alive[i])
      out[i] = ((state.x.col(i + 1) - state.x.col(i)).norm() - model.rest(i)) / model.rest(i);
  return out;
}

double maxAbsStretch(const SutureModel& model, const Points& x,
                     const std::vector<std::uint8_t>& alive) {
  double worst = 0.0;
  for (int i = 0; i < model.linkCount(); ++i)
    if (alive[i])
      worst = std::max(worst,
                       std::abs((x.col(i + 1) - x.col(i)).norm() - model.rest(i)) / model.rest(i));
  return worst;
}

}  // namespace microsim::sim::suture
