#include "microsim/sim/scene/render_snapshot.h"

#include "microsim/sim/scene/scene.h"
#include "microsim/sim/tools/forceps.h"
#include "microsim/sim/tools/microscissors.h"

#include <cmath>

namespace microsim::sim {

namespace {

void copyPoints(const Points& x, std::vector<float>& out) {
  out.resize(static_cast<std::size_t>(x.cols()) * 3);
  for (Eigen::Index i = 0; i < x.cols(); ++i) {
    for (int d = 0; d < 3; ++d) {
      out[static_cast<std::size_t>(i) * 3 + d] = static_cast<float>(x(d, i));
    }
  }
}

// what the forceps of `hand` would close on now, and where (ToolSnapshot::between)
void fillJawTarget(const Scene& scene, Hand hand, ToolSnapshot& tool) {
  const tools::Forceps& forceps = *scene.forceps(hand);
  const BetweenJaws found = scene.betweenJaws(hand, forceps.closure());
  tool.between = JawTarget::Nothing;
  tool.betweenPoint = forceps.pose().translation().cast<float>();
  if (found.suture) {
    const Points& x = scene.sutureState()->x;
    const Vec3 at = (1.0 - found.suture->fraction) * x.col(found.suture->link) +
                    found.suture->fraction * x.col(found.suture->link + 1);
    tool.between = found.suture->link < scene.sutureModel()->swage() ? JawTarget::Needle : JawTarget::Thread;
    tool.betweenPoint = at.cast<float>();
    return;
  }
  if (found.faces.empty()) return;
  const auto& triangles = scene.tissue().triangles();
  const Points& x = scene.tissueState().x;
  Vec3 sum = Vec3::Zero();
  double area = 0.0;
  for (const tools::FaceGrasp& g : found.faces) {
    const auto& t = triangles[static_cast<std::size_t>(g.face)];
    const Vec3 p = g.barycentric.x() * x.col(t[0]) + g.barycentric.y() * x.col(t[1]) + g.barycentric.z() * x.col(t[2]);
    sum += g.area * p;
    area += g.area;
  }
  tool.between = JawTarget::Tissue;
  tool.betweenPoint = (sum / area).cast<float>();
}

}  // namespace

void vertexNormals(const std::vector<float>& positions,
                   const std::vector<std::array<int, 3>>& triangles, std::vector<float>& normals) {
  normals.assign(positions.size(), 0.0f);
  const auto vertex = [&](int i) {
    return Eigen::Vector3f(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
  };
  for (const auto& t : triangles) {
    // the cross product's length is twice the area, so summing it weights by area
    const Eigen::Vector3f n = (vertex(t[1]) - vertex(t[0])).cross(vertex(t[2]) - vertex(t[0]));
    for (int c : t) {
      for (int d = 0; d < 3; ++d) normals[3 * c + d] += n[d];
    }
  }
  for (std::size_t i = 0; i + 2 < normals.size(); i += 3) {
    const float len = std::sqrt(normals[i] * normals[i] + normals[i + 1] * normals[i + 1] +
                                normals[i + 2] * normals[i + 2]);
    if (len > 0.0f && std::isfinite(len)) {
      for (int d = 0; d < 3; ++d) normals[i + d] /= len;
    } else {
      for (int d = 0; d < 3; ++d) normals[i + d] = 0.0f;
    }
  }
}

void fillSnapshot(const Scene& scene, RenderSnapshot& out) {
  out.time = scene.time();
  out.steps = scene.steps();
  copyPoints(scene.tissueState().x, out.tissuePositions);
  vertexNormals(out.tissuePositions, scene.tissue().triangles(), out.tissueNormals);

  if (const auto* state = scene.sutureState()) {
    copyPoints(state->x, out.suturePositions);
    out.sutureAlive = state->alive;
    out.needleNodes = scene.sutureModel()->swage() + 1;
    out.sutureRadius = static_cast<float>(scene.sutureModel()->def().contactRadius);
  } else {
    out.suturePositions.clear();
    out.sutureAlive.clear();
    out.needleNodes = 0;
    out.sutureRadius = 0.0f;
  }

  for (int h = 0; h < kHandCount; ++h) {
    ToolSnapshot& tool = out.forceps[static_cast<std::size_t>(h)];
    const tools::Forceps* forceps = scene.forceps(static_cast<Hand>(h));
    tool.present = forceps != nullptr;
    if (!forceps) continue;
    tool.pose = forceps->pose().matrix().cast<float>();
    tool.closure = forceps->closure();
    const auto jaws = tools::jawPoses(forceps->def(), forceps->pose(), forceps->closure());
    for (std::size_t j = 0; j < 2; ++j) tool.jaws[j] = jaws[j].matrix().cast<float>();
    tool.holdsTissue = !forceps->heldNodes().empty();
    tool.holdsSuture = forceps->holdsSuture();
    fillJawTarget(scene, static_cast<Hand>(h), tool);
  }
  for (int h = 0; h < kHandCount; ++h) {
    ScalpelSnapshot& scalpel = out.scalpels[static_cast<std::size_t>(h)];
    const auto& blade = scene.blade(static_cast<Hand>(h));
    scalpel.present = blade.has_value();
    if (blade) scalpel.pose = blade->matrix().cast<float>();
  }
  for (int h = 0; h < kHandCount; ++h) {
    const auto hand = static_cast<Hand>(h);
    ScissorsSnapshot& scissors = out.scissors[static_cast<std::size_t>(h)];
    const auto& held = scene.scissors(hand);
    out.instruments[static_cast<std::size_t>(h)] = scene.instrument(hand);
    scissors.present = held.has_value();
    if (!held) continue;
    scissors.pose = held->pose.matrix().cast<float>();
    scissors.closure = held->closure;
    const auto blades = tools::scissorsBladePoses(*scene.def().scissors, held->pose, held->closure);
    for (std::size_t b = 0; b < 2; ++b) scissors.blades[b] = blades[b].matrix().cast<float>();
  }
  out.pierceCount = static_cast<int>(scene.pierces().size());
}

}  // namespace microsim::sim
