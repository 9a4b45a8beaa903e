#pragma once
// Where a value sits in JSON text, by the field path a loader reports
// ("objects[0].links[3]"): nlohmann-json keeps no positions, so on error a loader rescans
// the (already validated) text once to find the offending value. Public because every JSON
// file the project reads (scenes here, rubrics in assessment) reports its errors this way.

#include "microsim/sim/scene/spring_scene.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace microsim::sim {

/// Byte offset of the value at `path` in valid JSON `text`; "" is the root value.
std::optional<std::size_t> locateJsonPath(std::string_view text, std::string_view path);

struct JsonHit {
  std::size_t offset = 0;
  std::string path;
};
/// The first number in `text` too large for a double (nlohmann-json rejects it without a
/// position); `text` must be otherwise valid JSON.
std::optional<JsonHit> findOverflowingNumber(std::string_view text);

/// Fills e.offset/line/column from e.field: the value at the path in `text`, or at its
/// nearest enclosing value that can be found.
void locateSceneError(SceneError& e, std::string_view text);

}  // namespace microsim::sim
