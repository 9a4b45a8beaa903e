#pragma once
// Typed reads of scene JSON that name the field path on failure: the first failure is kept
// as a SceneError (kind + path); positions are added by the caller from the path. Shared by
// both scene loaders (spring_scene.cpp, scene_def.cpp), so that they keep one set of rules:
// wrong JSON types, non-finite and negative numbers, and unknown keys are errors.

#include "microsim/sim/mesh/spring_model.h"
#include "microsim/sim/mesh/vessel.h"
#include "microsim/sim/scene/json_location.h"
#include "microsim/sim/scene/spring_scene.h"

#include <nlohmann/json.hpp>

#include <exception>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

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
  /// An integer in int range.
  bool integer(const json& v, const std::string& path, long long& out);
  bool intAtLeast(const json& v, const std::string& path, long long least, int& out);
  /// An index into `nodes` nodes.
  bool nodeIndex(const json& v, const std::string& path, int nodes, int& out);
  /// An array of exactly `count` integers, each at least `least`.
  bool ints(const json& v, const std::string& path, std::size_t count, long long least,
            std::vector<int>& out);
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

  /// A vessel object's optional "material": {"youngs_modulus" (g/(mm·s²) = Pa),
  /// "fung_exponent", "density" (g/mm³), "damping_ratio"}, each defaulting to WallMaterial's.
  /// With a material, the object's explicit "k_layer", "k_between", "mass" and "damping"
  /// are recorded in def.overrides (an explicit value wins over the derived one).
  bool wallMaterial(const json& obj, const std::string& path, VesselDef& def);

 private:
  std::optional<SceneError> error_;
};

/// A SceneError of `kind` in `file` at byte `offset` of `text` (line and column filled).
SceneError sceneErrorAt(SceneErrorKind kind, const std::string& file, std::string_view text,
                        std::size_t offset);

/// The JSON document in `text`, or the syntax error (MalformedJson at the byte where parsing
/// failed; NonFinite at a number beyond double range).
std::variant<nlohmann::json, SceneError> parseSceneJson(std::string_view text,
                                                        const std::string& file);

/// Parses `text` and reads the document into `result` with `reader.scene(doc, result)`;
/// a failure is the reader's first error, located in the text.
template <class Result, class Reader>
std::variant<Result, SceneError> parseSceneText(std::string_view text, const std::string& file,
                                               Reader& reader, Result result) {
  std::variant<nlohmann::json, SceneError> doc = parseSceneJson(text, file);
  if (auto* e = std::get_if<SceneError>(&doc)) return *e;
  bool ok = false;
  try {
    ok = reader.scene(std::get<nlohmann::json>(doc), result);
  } catch (const std::exception&) {
    return sceneErrorAt(SceneErrorKind::InvalidValue, file, text, 0);
  }
  if (ok) return result;
  SceneError err = *reader.error();
  err.file = file;
  locateSceneError(err, text);
  return err;
}

/// A scene file's text and the directory its relative paths resolve against.
struct SceneFileText {
  std::string text;
  std::string baseDir;
};
/// Reads the file at `path`; FileNotFound when it cannot be read or is a directory.
std::variant<SceneFileText, SceneError> readSceneFile(const std::string& path);

}  // namespace microsim::sim::detail
