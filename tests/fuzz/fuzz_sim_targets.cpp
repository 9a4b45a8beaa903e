// Fuzz targets for the engine's file formats: scene files, spring scenes, recordings.
#include "fuzz/fuzz_targets.h"

#include "microsim/sim/scene/recording.h"
#include "microsim/sim/scene/scene_def.h"
#include "microsim/sim/scene/spring_scene.h"

#include <cstdio>
#include <cstdlib>
#include <string_view>
#include <variant>

namespace microsim::fuzz {

namespace {

std::string_view asText(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// mesh files named by a fuzzed scene resolve here, an empty folder, so an input can name a
// file but never reach the tester's own files through a relative path
constexpr const char* kNoSuchFolder = "/nonexistent/microsim-fuzz";

void checkErrorIsPlaced(const sim::SceneError& error, std::size_t size, const char* target) {
  // an error points into the text it was given (line and column start at 1; 0 = unknown)
  if (error.line < 0 || error.column < 0) propertyBroken(target, "negative error position");
  if (error.offset > size) propertyBroken(target, "error offset past the end of the text");
}

}  // namespace

int fuzzSceneFile(const std::uint8_t* data, std::size_t size) {
  const sim::SceneDefLoad load = sim::parseSceneDef(asText(data, size), "fuzz.json", kNoSuchFolder);
  if (const auto* error = std::get_if<sim::SceneError>(&load)) {
    checkErrorIsPlaced(*error, size, "scene");
  }
  return 0;
}

int fuzzSpringScene(const std::uint8_t* data, std::size_t size) {
  const sim::SceneLoad load = sim::parseSpringScene(asText(data, size), "fuzz.json", kNoSuchFolder);
  if (const auto* error = std::get_if<sim::SceneError>(&load)) {
    checkErrorIsPlaced(*error, size, "spring-scene");
  }
  return 0;
}

int fuzzRecording(const std::uint8_t* data, std::size_t size) {
  sim::Recording recording;
  const sim::RecordingStatus status = sim::decodeRecording({data, size}, recording);
  if (status.offset > size) propertyBroken("recording", "error offset past the end of the input");
  if (!status.ok() && status.error != sim::RecordingError::Truncated) return 0;
  // whatever decodes (complete or salvaged) re-encodes and decodes to the same frames
  const std::vector<std::uint8_t> again = sim::encodeRecording(recording);
  sim::Recording decoded;
  if (!sim::decodeRecording(again, decoded).ok()) propertyBroken("recording", "re-encoding is unreadable");
  if (decoded.frames != recording.frames || decoded.metadata != recording.metadata || decoded.scene != recording.scene) {
    propertyBroken("recording", "round trip changed the frames, the metadata or the scene");
  }
  return 0;
}

void propertyBroken(const char* target, const char* what) {
  std::fprintf(stderr, "fuzz target %s: %s\n", target, what);
  std::abort();
}

}  // namespace microsim::fuzz
