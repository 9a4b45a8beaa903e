#pragma once
// Typed reads of scene JSON that name the field path on failure: the first failure is kept
// as a SceneError (kind + path); positions are added by the caller from the path.
// The same rules as the spring-scene loader: wrong JSON types, non-finite and negative
// numbers, and unknown keys are errors.

#include "microsim/sim/mesh/spring_model.h"
#include "microsim/sim/scene/spring_scene.h"

#include <nlohmann/json.hpp>

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

namespace microsim::sim::detail {

class JsonReader {
 public:
  using json = nlohmann::json;

  static std::string key(const std::string& path, std::string_view name) {
    return path.empty() ? std::string(name) : path + "." + std::string(name);
  }
  static std::string index(const std::string& path, std::size_t i) {
    return path + "[" + std::to_string(i) + "]";
  }

  bool fail(SceneErrorKind kind, const std::string& path);
  const std::optional<SceneError>& error() const { return error_; }
  std::optional<SceneError>& error() { return error_; }

  bool number(const json& v, const std::string& path, double& out);
  bool nonNegative(const json& v, const std::string& path, double& out);
  bool positive(const json& v, const std::string& path, double& out);
  bool intAtLeast(const json& v, const std::string& path, long long least, int& out);
  bool boolean(const json& v, const std::string& path, bool& out);
  bool string(const json& v, const std::string& path, std::string& out);
  bool vec3(const json& v, const std::string& path, Vec3& out);
  /// A JSON object whose keys are all in `allowed`.
  bool object(const json& v, const std::string& path,
              std::initializer_list<std::string_view> allowed);
  static const json* field(const json& obj, std::string_view name);
  bool required(const json& obj, const std::string& path, std::string_view name,
                const json*& out);

  // optional fields: absent leaves `out` alone
  bool optNumber(const json& obj, const std::string& path, std::string_view name, double& out);
  bool optNonNegative(const json& obj, const std::string& path, std::string_view name,
                      double& out);
  bool optPositive(const json& obj, const std::string& path, std::string_view name, double& out);
  bool optInt(const json& obj, const std::string& path, std::string_view name, long long least,
              int& out);
  bool optBool(const json& obj, const std::string& path, std::string_view name, bool& out);
  bool optVec3(const json& obj, const std::string& path, std::string_view name, Vec3& out);

 private:
  std::optional<SceneError> error_;
};

/// Fills e.offset/line/column from e.field: the value at the path in `text`, or at its
/// nearest enclosing value that can be found.
void locateSceneError(SceneError& e, std::string_view text);

}  // namespace microsim::sim::detail
