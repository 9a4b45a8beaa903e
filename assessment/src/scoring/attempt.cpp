#include "microsim/assessment/scoring/attempt.h"

#include "microsim/sim/scene/circumference_frame.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace microsim::assessment {

LeakFinding leakFinding(const sim::LeakResult& result) {
  LeakFinding f;
  f.status = result.status;
  f.pressureMmHg = result.pressureMmHg;
  if (result.status != sim::LeakTestStatus::Solved) return f;
  f.leaks = result.leak;
  f.largestGapMm = result.largestGapMm;
  f.angleDeg = result.angleDeg;
  f.limitMm = result.thresholdMm;
  return f;
}

std::vector<VesselGeometry> vesselGeometry(const sim::SceneDef& def) {
  std::vector<VesselGeometry> out;
  out.reserve(def.vessels.size());
  for (std::size_t v = 0; v < def.vessels.size(); ++v) {
    const sim::SceneVessel& sv = def.vessels[v];
    VesselGeometry g;
    g.vessel = static_cast<int>(v);
    g.object = sv.object;
    g.end = sv.end;
    g.axis = sv.def.direction.normalized();
    g.cutCentre = sv.def.origin + sv.def.length * g.axis;
    g.radius = sv.def.radius;
    g.wallThickness = sv.def.wallThickness;
    out.push_back(g);
  }

  // the angle frame: end 0's axis for both ends of a severed vessel, 0° toward the camera
  for (VesselGeometry& g : out) {
    g.angleAxis = g.axis;
    for (const VesselGeometry& other : out)
      if (g.end == 1 && other.object == g.object && other.end == 0) g.angleAxis = other.axis;
    g.angleZero = sim::circumferenceZero(g.angleAxis, def.camera.eye - g.cutCentre);
  }
  return out;
}

double tissueStretch(const sim::Scene& scene) {
  const sim::SpringModel& model = scene.tissue();
  const sim::Points& x = scene.tissueState().x;
  double worst = 0.0;
  for (const sim::Link& l : model.links()) {
    if (!l.alive || !(l.rest > 0.0)) continue;
    const double length = (x.col(l.b) - x.col(l.a)).norm();
    worst = std::max(worst, (length - l.rest) / l.rest);
  }
  return worst;
}

Attempt assembleAttempt(const sim::SceneDef& def, std::vector<sim::SceneEvent> events,
                        std::vector<sim::PierceEvent> pierces,
                        const std::vector<sim::InputFrame>& frames, double maxStretch) {
  Attempt a;
  a.events = std::move(events);
  a.pierces = std::move(pierces);
  a.vessels = vesselGeometry(def);
  a.stepDt = 1.0 / def.step.rateHz;
  a.steps = static_cast<int>(frames.size());
  a.duration = a.steps * a.stepDt;
  a.maxStretch = maxStretch;
  a.sceneFile = def.file;
  if (def.needle && def.needle->suture.needleShape == sim::suture::NeedleShape::Curved)
    a.needleRadius = def.needle->suture.needleRadius;

  // the frames as the scene used them: a rejected one repeats the last accepted one
  std::optional<sim::InputFrame> last;
  std::array<MotionSample, sim::kHandCount> held{};
  for (auto& m : a.motion) m.reserve(frames.size());
  for (std::size_t i = 0; i < frames.size(); ++i) {
    sim::InputRejection why{};
    const double previous = last ? last->time : -std::numeric_limits<double>::infinity();
    sim::InputFrame frame = frames[i];
    if (!sim::validateSequence(frames[i], previous, why)) {
      frame = last ? *last : sim::InputFrame{};
      for (sim::HandInput& h : frame.hands) h.tracked = h.tracked && last.has_value();
    }
    last = frame;
    const double t = static_cast<double>(i + 1) * a.stepDt;
    for (int h = 0; h < sim::kHandCount; ++h) {
      const sim::HandInput& in = frame.hands[static_cast<std::size_t>(h)];
      MotionSample& s = held[static_cast<std::size_t>(h)];
      s.time = t;
      s.tracked = in.tracked;
      if (in.tracked) {
        s.position = in.position;
        s.closure = in.closure;
        s.instrument = in.instrument;
      }
      a.motion[static_cast<std::size_t>(h)].push_back(s);
    }
  }
  return a;
}

Attempt captureAttempt(const sim::Scene& scene, const std::vector<sim::InputFrame>& frames) {
  return assembleAttempt(scene.def(), scene.events(), scene.pierces(), frames,
                         tissueStretch(scene));
}

void AttemptRecorder::afterStep(const sim::Scene& scene, const sim::InputFrame& frame) {
  frames_.push_back(frame);
  maxStretch_ = std::max(maxStretch_, tissueStretch(scene));
}

Attempt AttemptRecorder::attempt(const sim::Scene& scene) const {
  return assembleAttempt(scene.def(), scene.events(), scene.pierces(), frames_, maxStretch_);
}

std::variant<Attempt, ReplayError> replayAttempt(const std::string& scenePath,
                                                 const sim::Recording& recording, bool truncated) {
  sim::SceneDefLoad loaded = sim::loadSceneDef(scenePath);
  if (auto* e = std::get_if<sim::SceneError>(&loaded)) {
    ReplayError err;
    err.kind = ReplayErrorKind::Scene;
    err.sceneError = *e;
    return err;
  }
  return replayAttempt(std::get<sim::SceneDef>(loaded), recording, truncated);
}

std::variant<Attempt, ReplayError> replayAttempt(const sim::SceneDef& def,
                                                 const sim::Recording& recording, bool truncated) {
  sim::Scene scene(def, sim::StepMode::Deterministic);
  AttemptRecorder recorder;
  for (const sim::InputFrame& f : recording.frames) {
    scene.step(f);
    recorder.afterStep(scene, f);
  }
  Attempt a = recorder.attempt(scene);
  a.truncated = truncated;
  a.leak = leakFinding(sim::leakTest(scene));
  a.endState = sim::checkEndState(scene);
  return a;
}

std::variant<Attempt, ReplayError> replayAttempt(const std::string& scenePath,
                                                 const std::string& recordingPath) {
  sim::Recording recording;
  const sim::RecordingStatus status = sim::readRecording(recordingPath, recording);
  if (!status.ok() && status.error != sim::RecordingError::Truncated) {
    ReplayError err;
    err.kind = ReplayErrorKind::Recording;
    err.recording = status;
    return err;
  }
  return replayAttempt(scenePath, recording, status.error == sim::RecordingError::Truncated);
}

}  // namespace microsim::assessment
