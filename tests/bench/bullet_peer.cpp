#include "bullet_peer.h"

#if MICROSIM_HAVE_BULLET
// Bullet's inline array code trips GCC 12's -Wmaybe-uninitialized once inlined here
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <BulletSoftBody/btDefaultSoftBodySolver.h>
#include <BulletSoftBody/btDeformableBodySolver.h>
#include <BulletSoftBody/btDeformableMassSpringForce.h>
#include <BulletSoftBody/btDeformableMultiBodyConstraintSolver.h>
#include <BulletSoftBody/btDeformableMultiBodyDynamicsWorld.h>
#include <BulletSoftBody/btSoftBody.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>
#include <btBulletDynamicsCommon.h>
#pragma GCC diagnostic pop
#endif

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace microsim::bench {

using namespace microsim::sim;

#if MICROSIM_HAVE_BULLET

bool bulletPeerAvailable() { return true; }

namespace {

/// The % error of Bullet's nodes against the case's reference.
double bulletPeerError(const btSoftBody& body, const PullCase& c) {
  double worst = 0.0;
  for (int i = 0; i < body.m_nodes.size(); ++i) {
    const btVector3& x = body.m_nodes[i].m_x;
    const double d = (Vec3(x.x(), x.y(), x.z()) - c.reference.x.col(i)).norm();
    if (!std::isfinite(d)) return std::numeric_limits<double>::infinity();
    worst = std::max(worst, d);
  }
  return 100.0 * worst / c.displacement;
}

}  // namespace

BulletPeerResult bulletTimeToError(const PullCase& c, double percent, double capSeconds,
                                   const BulletPeerSettings& settings) {
  BulletPeerResult result;
  result.settings = settings;

  // a soft-rigid world with no gravity, no air, no rigid bodies
  btSoftBodyRigidBodyCollisionConfiguration config;
  btCollisionDispatcher dispatcher(&config);
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver constraintSolver;
  btDefaultSoftBodySolver softSolver;
  btSoftRigidDynamicsWorld world(&dispatcher, &broadphase, &constraintSolver, &config, &softSolver);
  world.setGravity(btVector3(0, 0, 0));
  btSoftBodyWorldInfo& info = world.getWorldInfo();
  info.m_gravity.setZero();
  info.air_density = 0;
  info.water_density = 0;
  info.m_sparsesdf.Initialize();

  // the model's nodes at the start state, pinned where fixed or controlled
  const SpringModel& model = c.model;
  const int n = model.nodeCount();
  std::vector<btVector3> x(static_cast<std::size_t>(n));
  std::vector<btScalar> m(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    x[static_cast<std::size_t>(i)] = btVector3(btScalar(c.start.x(0, i)), btScalar(c.start.x(1, i)), btScalar(c.start.x(2, i)));
    m[static_cast<std::size_t>(i)] = model.isFixed(i) ? btScalar(0) : btScalar(model.mass(i));
  }
  for (int k = 0; k < c.controls.size(); ++k) {
    const int node = c.controls.nodes[static_cast<std::size_t>(k)];
    const Vec3 t = c.controls.targets.col(k);
    x[static_cast<std::size_t>(node)] = btVector3(btScalar(t.x()), btScalar(t.y()), btScalar(t.z()));
    m[static_cast<std::size_t>(node)] = 0;
  }
  auto body = std::make_unique<btSoftBody>(&info, n, x.data(), m.data());

  // the model's links, kLST = k / k_max, rest lengths as the model's
  double kMax = 0.0;
  for (const Link& l : model.links())
    if (l.alive) kMax = std::max(kMax, l.k);
  std::vector<std::pair<double, btSoftBody::Material*>> materials;
  for (const Link& l : model.links()) {
    // (a link between two pinned nodes never moves, and Bullet would divide by their zero
    // inverse masses)
    if (!l.alive || kMax <= 0.0) continue;
    if (m[static_cast<std::size_t>(l.a)] == 0 && m[static_cast<std::size_t>(l.b)] == 0) continue;
    const double kLst = settings.stiffness * l.k / kMax;
    auto found = std::find_if(materials.begin(), materials.end(), [&](const auto& e) { return e.first == kLst; });
    if (found == materials.end()) {
      btSoftBody::Material* mat = body->appendMaterial();
      mat->m_kLST = btScalar(kLst);
      mat->m_kAST = 0;
      mat->m_kVST = 0;
      materials.emplace_back(kLst, mat);
      found = materials.end() - 1;
    }
    body->appendLink(l.a, l.b, found->second, false);
    btSoftBody::Link& link = body->m_links[body->m_links.size() - 1];
    link.m_rl = btScalar(l.rest);
    link.m_c1 = link.m_rl * link.m_rl;
  }
  // appendLink asks for the run-time constants to be rebuilt at the first step, which would
  // take the rest lengths from the positions then (the control nodes already pulled): build
  // them now from the model's rest lengths and clear the request
  body->updateLinkConstants();
  body->m_bUpdateRtCst = false;
  body->m_cfg.piterations = settings.iterations;
  body->m_cfg.kDP = btScalar(settings.damping);
  body->m_cfg.collisions = 0;
  btSoftBody* raw = body.get();
  world.addSoftBody(raw);

  // step until the error is reached or the cap is spent
  result.errorPercent = bulletPeerError(*raw, c);
  while (result.errorPercent > percent && result.seconds < capSeconds) {
    const double t0 = cpuSeconds();
    world.stepSimulation(btScalar(settings.dt), 0, btScalar(settings.dt));
    result.seconds += cpuSeconds() - t0;
    ++result.steps;
    result.errorPercent = bulletPeerError(*raw, c);
  }
  result.reached = result.errorPercent <= percent;
  world.removeSoftBody(raw);
  return result;
}

BulletPeerResult bulletSpringTimeToError(const PullCase& c, double percent, double capSeconds,
                                         const BulletSpringSettings& settings) {
  BulletPeerResult result;
  result.settings.iterations = 0;
  result.settings.dt = settings.dt;
  result.settings.damping = settings.damping;

  // the model's stiffnesses: at most two values (elastic and "bending" links of the force)
  const SpringModel& model = c.model;
  std::vector<double> ks;
  for (const Link& l : model.links())
    if (l.alive && std::find(ks.begin(), ks.end(), l.k) == ks.end()) ks.push_back(l.k);
  if (ks.empty() || ks.size() > 2) return result;

  // a deformable world with no gravity, explicit (symplectic Euler)
  btSoftBodyRigidBodyCollisionConfiguration config;
  btCollisionDispatcher dispatcher(&config);
  btDbvtBroadphase broadphase;
  btDeformableBodySolver deformableSolver;
  btDeformableMultiBodyConstraintSolver constraintSolver;
  constraintSolver.setDeformableSolver(&deformableSolver);
  btDeformableMultiBodyDynamicsWorld world(&dispatcher, &broadphase, &constraintSolver, &config, &deformableSolver);
  world.setGravity(btVector3(0, 0, 0));
  world.getWorldInfo().m_gravity.setZero();
  world.getWorldInfo().m_sparsesdf.Initialize();
  world.setImplicit(false);

  // the model's nodes at the start state, pinned where fixed or controlled
  const int n = model.nodeCount();
  std::vector<btVector3> x(static_cast<std::size_t>(n));
  std::vector<btScalar> m(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    x[static_cast<std::size_t>(i)] = btVector3(btScalar(c.start.x(0, i)), btScalar(c.start.x(1, i)), btScalar(c.start.x(2, i)));
    m[static_cast<std::size_t>(i)] = model.isFixed(i) ? btScalar(0) : btScalar(model.mass(i));
  }
  for (int k = 0; k < c.controls.size(); ++k)
    m[static_cast<std::size_t>(c.controls.nodes[static_cast<std::size_t>(k)])] = 0;
  auto body = std::make_unique<btSoftBody>(&world.getWorldInfo(), n, x.data(), m.data());

  // the links with the model's rest lengths; the second stiffness as the force's "bending" links
  for (const Link& l : model.links()) {
    if (!l.alive) continue;
    if (m[static_cast<std::size_t>(l.a)] == 0 && m[static_cast<std::size_t>(l.b)] == 0) continue;
    body->appendLink(l.a, l.b, nullptr, false);
    btSoftBody::Link& link = body->m_links[body->m_links.size() - 1];
    link.m_rl = btScalar(l.rest);
    link.m_c1 = link.m_rl * link.m_rl;
    link.m_bbending = ks.size() == 2 && l.k == ks[1] ? 1 : 0;
  }
  body->updateLinkConstants();
  body->m_bUpdateRtCst = false;
  body->m_cfg.collisions = 0;
  body->setActivationState(DISABLE_DEACTIVATION);  // a slow body must not be put to sleep
  btSoftBody* raw = body.get();
  world.addSoftBody(raw);
  btDeformableMassSpringForce force(static_cast<btScalar>(ks[0]), static_cast<btScalar>(settings.damping), true,
                                    static_cast<btScalar>(ks.size() == 2 ? ks[1] : ks[0]));
  world.addForce(raw, &force);

  // the control nodes jump to their targets
  for (int k = 0; k < c.controls.size(); ++k) {
    const Vec3 t = c.controls.targets.col(k);
    btSoftBody::Node& node = raw->m_nodes[c.controls.nodes[static_cast<std::size_t>(k)]];
    node.m_x = node.m_q = btVector3(btScalar(t.x()), btScalar(t.y()), btScalar(t.z()));
  }

  // step until the error is reached or the cap is spent
  result.errorPercent = bulletPeerError(*raw, c);
  while (result.errorPercent > percent && result.seconds < capSeconds) {
    const double t0 = cpuSeconds();
    world.stepSimulation(btScalar(settings.dt), 0, btScalar(settings.dt));
    result.seconds += cpuSeconds() - t0;
    ++result.steps;
    result.errorPercent = bulletPeerError(*raw, c);
  }
  result.reached = result.errorPercent <= percent;
  world.removeForce(raw, &force);
  world.removeSoftBody(raw);
  return result;
}

#else

bool bulletPeerAvailable() { return false; }

BulletPeerResult bulletSpringTimeToError(const PullCase&, double, double, const BulletSpringSettings&) {
  return {};
}

BulletPeerResult bulletTimeToError(const PullCase&, double, double, const BulletPeerSettings& settings) {
  BulletPeerResult result;
  result.settings = settings;
  return result;
}

#endif

BulletPeerResult bulletSpringBestTimeToError(const PullCase& c, double percent, double capSeconds, bool quick) {
  std::vector<BulletSpringSettings> tries;
  if (quick) {
    tries = {{0.2, 10.0}, {0.5, 10.0}};
  } else {
    for (double dt : {0.1, 0.2, 0.5, 1.0})
      for (double damping : {3.0, 10.0, 30.0}) tries.push_back({dt, damping});
  }
  BulletPeerResult best;
  bool any = false;
  for (const BulletSpringSettings& s : tries) {
    const BulletPeerResult r = bulletSpringTimeToError(c, percent, capSeconds, s);
    const bool better = !any || (r.reached && (!best.reached || r.seconds < best.seconds)) ||
                        (!r.reached && !best.reached && r.errorPercent < best.errorPercent);
    if (better) best = r;
    any = true;
  }
  return best;
}

BulletPeerResult bulletBestTimeToError(const PullCase& c, double percent, double capSeconds, bool quick) {
  std::vector<BulletPeerSettings> tries;
  if (quick) {
    tries = {{16, 0.1, 0.01, 1.0}, {16, 0.1, 0.01, 0.01}};
  } else {
    for (double stiffness : {1.0, 0.1, 0.01})
      for (int iterations : {4, 16, 64}) tries.push_back({iterations, 0.1, 0.01, stiffness});
  }
  BulletPeerResult best;
  bool any = false;
  for (const BulletPeerSettings& s : tries) {
    const BulletPeerResult r = bulletTimeToError(c, percent, capSeconds, s);
    const bool better = !any || (r.reached && (!best.reached || r.seconds < best.seconds)) ||
                        (!r.reached && !best.reached && r.errorPercent < best.errorPercent);
    if (better) best = r;
    any = true;
  }
  return best;
}

}  // namespace microsim::bench
