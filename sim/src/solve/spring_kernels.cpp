#include "microsim/sim/solve/spring_kernels.h"

#include <cmath>

namespace microsim::sim {

std::vector<unsigned char> freeMask(const SpringModel& model, const SpringControls& controls) {
  std::vector<unsigned char> free(static_cast<std::size_t>(model.nodeCount()), 1);
  for (int i = 0; i < model.nodeCount(); ++i)
    if (model.isFixed(i)) free[i] = 0;
  for (int c : controls.nodes)
    if (c >= 0 && c < model.nodeCount()) free[c] = 0;
  return free;
}

void totalForces(const SpringModel& model, const Points& x, Points& forces) {
  const int n = model.nodeCount();
  forces.resize(3, n);
  // weights
  for (int i = 0; i < n; ++i) forces.col(i) = model.mass(i) * model.gravity;
  // springs, each alive link once
  for (const Link& link : model.links()) {
    if (!link.alive) continue;
    const Vec3 f = linkForce(link, x.col(link.a), x.col(link.b));
    forces.col(link.a) += f;
    forces.col(link.b) -= f;
  }
}

void addPointSpringForces(const std::vector<PointSpring>& springs, const Points& x, Points& forces) {
  for (const PointSpring& s : springs) {
    const Vec3 f = pointSpringForce(s, pointSpringOffset(s, x));
    for (int k = 0; k < s.size(); ++k)
      forces.col(s.nodes[static_cast<std::size_t>(k)]) += s.weights[static_cast<std::size_t>(k)] * f;
  }
}

double totalEnergy(const SpringModel& model, const Points& x,
                   const std::vector<unsigned char>& free) {
  double e = 0.0;
  for (const Link& link : model.links())
    if (link.alive) e += linkEnergy(link, x.col(link.a), x.col(link.b));
  for (int i = 0; i < model.nodeCount(); ++i)
    if (free[i]) e -= model.mass(i) * model.gravity.dot(x.col(i));
  return e;
}

double forceScale(const SpringModel& model, const SpringControls& controls) {
  double kMax = 0.0;
  double restSum = 0.0;
  int alive = 0;
  for (const Link& link : model.links()) {
    if (!link.alive) continue;
    kMax = std::max(kMax, link.k);
    restSum += link.rest;
    ++alive;
  }
  double dMax = 0.0;
  for (int c = 0; c < controls.size(); ++c) {
    const int node = controls.nodes[c];
    if (node < 0 || node >= model.nodeCount()) continue;
    dMax = std::max(dMax, (controls.targets.col(c) - model.restPositions().col(node)).norm());
  }
  double weight = 0.0;
  const double g = model.gravity.norm();
  for (int i = 0; i < model.nodeCount(); ++i) weight = std::max(weight, model.mass(i) * g);

  double scale = std::max(kMax * dMax, weight);
  if (!(scale > 0.0) && alive > 0) scale = kMax * restSum / alive;
  if (!(scale > 0.0) || !std::isfinite(scale)) scale = 1.0;
  return scale;
}

double relativeResidual(const SpringModel& model, const Points& x, const SpringControls& controls) {
  Points f;
  totalForces(model, x, f);
  addPointSpringForces(controls.springs, x, f);
  const std::vector<unsigned char> free = freeMask(model, controls);
  double worst = 0.0;
  for (int i = 0; i < model.nodeCount(); ++i)
    if (free[i]) worst = std::max(worst, f.col(i).norm());
  return worst / forceScale(model, controls);
}

}  // namespace microsim::sim
