#pragma once
// Where a value sits in JSON text, by the field path the scene loader reports
// ("objects[0].links[3]"): nlohmann-json keeps no positions, so on error the loader
// rescans the (already validated) text once to find the offending value.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace microsim::sim::detail {

/// Byte offset of the value at `path` in valid JSON `text`; "" is the root value.
std::optional<std::size_t> locateJsonPath(std::string_view text, std::string_view path);

struct JsonHit {
  std::size_t offset = 0;
  std::string path;
};
/// The first number in `text` too large for a double (nlohmann-json rejects it without a
/// position); `text` must be otherwise valid JSON.
std::optional<JsonHit> findOverflowingNumber(std::string_view text);

}  // namespace microsim::sim::detail
