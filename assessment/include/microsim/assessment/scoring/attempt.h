#pragma once
// One attempt as the metrics see it (DESIGN.md §Assessment): what the scene reported
// (events, pierces), what the hands did (tool-tip motion every step), the vessels' geometry
// and the worst tissue stretch. Metrics are pure functions of an Attempt, so an Attempt
// captured live, replayed from a recording or written by hand in a test scores alike.
//
// Motion. One sample per step, taken from the frame the step consumed: a frame the scene
// rejected (sim::validateSequence) repeats the previous accepted one, and a hand that is not
// tracked keeps its last position with `tracked` false, exactly as the tools behave.
//
// Circumference. A pierce's position around a vessel is an angle (degrees, [0, 360)) about
// the vessel pair's shared axis (end 0's direction, clamp → cut); 0° is the direction to
// the microscope (the camera eye projected onto the cross-section), so 0° is the top of the
// front wall and 180° the middle of the back wall; positive is right-handed about the axis.
//
// Units: millimetres, seconds, degrees.

#include "microsim/sim/scene/end_state_check.h"
#include "microsim/sim/scene/input_frame.h"
#include "microsim/sim/scene/leak_test.h"
#include "microsim/sim/scene/recording.h"
#include "microsim/sim/scene/scene.h"
#include "microsim/sim/scene/scene_def.h"
#include "microsim/sim/scene/scene_events.h"

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace microsim::assessment {

/// One hand's tool tip at the end of one step.
struct MotionSample {
  double time = 0.0;                        ///< s, the frame's time
  sim::Vec3 position = sim::Vec3::Zero();   ///< tool tip, scene frame (mm)
  double closure = 0.0;                     ///< 0 open .. 1 closed
  bool tracked = false;                     ///< false: the source lost the hand; position held
  sim::Instrument instrument = sim::Instrument::None;
};

/// A vessel (or one end of a severed vessel) as the pierce metrics need it.
struct VesselGeometry {
  int vessel = -1;                          ///< index into SceneDef::vessels
  int object = -1;                          ///< tissue object; a severed vessel's ends share it
  int end = -1;                             ///< 0 or 1 for a severed vessel's ends, else -1
  sim::Vec3 axis = sim::Vec3::UnitX();      ///< unit, from the clamped end to the cut end
  sim::Vec3 cutCentre = sim::Vec3::Zero();  ///< centre of the cut-end ring at rest (mm)
  double radius = 0.0;                      ///< outer radius (mm)
  double wallThickness = 0.0;               ///< mm
  sim::Vec3 angleAxis = sim::Vec3::UnitX(); ///< unit axis the circumferential angle turns about
  sim::Vec3 angleZero = sim::Vec3::UnitZ(); ///< unit, ⟂ angleAxis: 0° (toward the microscope)
};

/// The lumen's pressure test on the final scene (sim/scene/leak_test.h), as scoring sees it.
struct LeakFinding {
  /// Solved: the numbers below hold; anything else: no verdict (leaks false, the numbers NaN)
  sim::LeakTestStatus status = sim::LeakTestStatus::Solved;
  bool leaks = false;  ///< fluid escapes through the suture line
  double largestGapMm = std::numeric_limits<double>::quiet_NaN();  ///< mm, widest gap
  double angleDeg = std::numeric_limits<double>::quiet_NaN();      ///< where it is, [0, 360)
  double limitMm = std::numeric_limits<double>::quiet_NaN();       ///< mm: wider leaks
  double pressureMmHg = std::numeric_limits<double>::quiet_NaN();  ///< as tested
};

/// The finding of a leak test's result (a verdict only when it was solved).
LeakFinding leakFinding(const sim::LeakResult& result);

struct Attempt {
  std::vector<sim::SceneEvent> events;
  std::vector<sim::PierceEvent> pierces;
  std::array<std::vector<MotionSample>, sim::kHandCount> motion;  ///< per hand, one per step
  std::vector<VesselGeometry> vessels;      ///< parallel to SceneDef::vessels
  double stepDt = 0.01;                     ///< s between motion samples
  double duration = 0.0;                    ///< s, steps × dt
  int steps = 0;
  double maxStretch = 0.0;                  ///< max over steps and live links of (l − r)/r
  /// mm, the curved needle's arc radius; NaN without a needle or with a straight one
  double needleRadius = std::numeric_limits<double>::quiet_NaN();
  bool truncated = false;                   ///< the recording had no end record: partial
  std::string sceneFile;                    ///< as loaded, empty when built in memory
  /// the leak test on the final scene (sim::leakTest at its default 100 mmHg), which
  /// replayAttempt runs; none for an attempt captured or built otherwise
  std::optional<LeakFinding> leak;
  /// the final scene looked at (sim::checkEndState: over-tight stitches, thread in the lumen,
  /// edge overlap), which replayAttempt runs; none for an attempt captured or built otherwise
  std::optional<sim::EndStateResult> endState;
};

/// The geometry of the scene's vessels (the camera gives the circumferential 0°).
std::vector<VesselGeometry> vesselGeometry(const sim::SceneDef& def);

/// The largest strain (l − r)/r over the live links of `scene`'s tissue now; 0 without links.
double tissueStretch(const sim::Scene& scene);

/// Builds an Attempt from a finished run's parts: the frames the scene consumed, in order
/// (one per step), and the maximum stretch seen during the run.
Attempt assembleAttempt(const sim::SceneDef& def, std::vector<sim::SceneEvent> events,
                        std::vector<sim::PierceEvent> pierces,
                        const std::vector<sim::InputFrame>& frames, double maxStretch);

/// An Attempt from a scene that has stepped through exactly `frames`. The scene keeps no
/// history of its stretch, so maxStretch is the final state's; AttemptRecorder (or
/// replayAttempt) samples it every step.
Attempt captureAttempt(const sim::Scene& scene, const std::vector<sim::InputFrame>& frames);

/// Collects an attempt while it runs: call afterStep once after every Scene::step.
class AttemptRecorder {
 public:
  void afterStep(const sim::Scene& scene, const sim::InputFrame& frame);
  /// The attempt so far.
  Attempt attempt(const sim::Scene& scene) const;
  double maxStretch() const { return maxStretch_; }

 private:
  std::vector<sim::InputFrame> frames_;
  double maxStretch_ = 0.0;
};

enum class ReplayErrorKind : std::uint8_t {
  Scene,      ///< the scene file failed to load (sceneError)
  Recording,  ///< the recording could not be read at all (recording)
};

struct ReplayError {
  ReplayErrorKind kind = ReplayErrorKind::Scene;
  std::optional<sim::SceneError> sceneError;
  sim::RecordingStatus recording;
};

/// Steps a Deterministic scene through a recording's frames, then runs the leak test and the
/// end-state check on the final scene (Attempt::leak, Attempt::endState). A Truncated
/// recording replays its complete frames and the Attempt says truncated; any other recording
/// error fails.
std::variant<Attempt, ReplayError> replayAttempt(const std::string& scenePath,
                                                 const std::string& recordingPath);
/// The same on a recording already in memory.
std::variant<Attempt, ReplayError> replayAttempt(const std::string& scenePath,
                                                 const sim::Recording& recording,
                                                 bool truncated);
/// The same on a scene definition already loaded (and perhaps changed in memory, as the
/// app's solver settings change it): the recording replays on exactly that scene.
std::variant<Attempt, ReplayError> replayAttempt(const sim::SceneDef& scene, const sim::Recording& recording,
                                                 bool truncated);

}  // namespace microsim::assessment
