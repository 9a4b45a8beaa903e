#include "scene/scene_json_reader.h"

#include "microsim/sim/scene/json_location.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <exception>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <tuple>

namespace microsim::sim::detail {

bool JsonReader::fail(SceneErrorKind kind, const std::string& path) {
  if (!error_) {
    SceneError e;
    e.kind = kind;
    e.field = path;
    error_ = e;
  }
  return false;
}

bool JsonReader::number(const json& v, const std::string& path, double& out) {
  if (!v.is_number()) return fail(SceneErrorKind::WrongType, path);
  out = v.get<double>();
  if (!std::isfinite(out)) return fail(SceneErrorKind::NonFinite, path);
  return true;
}

bool JsonReader::nonNegative(const json& v, const std::string& path, double& out) {
  if (!number(v, path, out)) return false;
  return out >= 0.0 || fail(SceneErrorKind::NegativeValue, path);
}

bool JsonReader::positive(const json& v, const std::string& path, double& out) {
  if (!nonNegative(v, path, out)) return false;
  return out > 0.0 || fail(SceneErrorKind::InvalidValue, path);
}

bool JsonReader::integer(const json& v, const std::string& path, long long& out) {
  if (v.is_number_unsigned()) {
    const auto u = v.get<unsigned long long>();
    if (u > static_cast<unsigned long long>(INT_MAX)) return fail(SceneErrorKind::InvalidValue, path);
    out = static_cast<long long>(u);
    return true;
  }
  if (!v.is_number_integer()) return fail(SceneErrorKind::WrongType, path);
  out = v.get<long long>();
  if (out < INT_MIN || out > INT_MAX) return fail(SceneErrorKind::InvalidValue, path);
  return true;
}

bool JsonReader::intAtLeast(const json& v, const std::string& path, long long least, int& out) {
  long long x = 0;
  if (!integer(v, path, x)) return false;
  if (x < least) return fail(x < 0 ? SceneErrorKind::NegativeValue : SceneErrorKind::InvalidValue, path);
  out = static_cast<int>(x);
  return true;
}

bool JsonReader::nodeIndex(const json& v, const std::string& path, int nodes, int& out) {
  long long x = 0;
  if (!integer(v, path, x)) return false;
  if (x < 0 || x >= nodes) return fail(SceneErrorKind::IndexOutOfRange, path);
  out = static_cast<int>(x);
  return true;
}

bool JsonReader::ints(const json& v, const std::string& path, std::size_t count, long long least,
                      std::vector<int>& out) {
  if (!v.is_array() || v.size() != count) return fail(SceneErrorKind::WrongType, path);
  out.assign(count, 0);
  for (std::size_t c = 0; c < count; ++c)
    if (!intAtLeast(v[c], index(path, c), least, out[c])) return false;
  return true;
}

bool JsonReader::boolean(const json& v, const std::string& path, bool& out) {
  if (!v.is_boolean()) return fail(SceneErrorKind::WrongType, path);
  out = v.get<bool>();
  return true;
}

bool JsonReader::string(const json& v, const std::string& path, std::string& out) {
  if (!v.is_string()) return fail(SceneErrorKind::WrongType, path);
  out = v.get<std::string>();
  return true;
}

bool JsonReader::vec3(const json& v, const std::string& path, Vec3& out) {
  if (!v.is_array() || v.size() != 3) return fail(SceneErrorKind::WrongType, path);
  for (int c = 0; c < 3; ++c)
    if (!number(v[static_cast<std::size_t>(c)], index(path, static_cast<std::size_t>(c)), out[c]))
      return false;
  return true;
}

bool JsonReader::object(const json& v, const std::string& path,
                        std::initializer_list<std::string_view> allowed) {
  if (!v.is_object()) return fail(SceneErrorKind::WrongType, path);
  for (const auto& item : v.items())
    if (std::find(allowed.begin(), allowed.end(), item.key()) == allowed.end())
      return fail(SceneErrorKind::UnknownField, key(path, item.key()));
  return true;
}

const JsonReader::json* JsonReader::field(const json& obj, std::string_view name) {
  const auto it = obj.find(std::string(name));
  return it == obj.end() ? nullptr : &*it;
}

bool JsonReader::required(const json& obj, const std::string& path, std::string_view name,
                          const json*& out) {
  out = field(obj, name);
  return out != nullptr || fail(SceneErrorKind::MissingField, key(path, name));
}

bool JsonReader::optNumber(const json& obj, const std::string& path, std::string_view name,
                           double& out) {
  const json* v = field(obj, name);
  return !v || number(*v, key(path, name), out);
}

bool JsonReader::optNonNegative(const json& obj, const std::string& path, std::string_view name,
                                double& out) {
  const json* v = field(obj, name);
  return !v || nonNegative(*v, key(path, name), out);
}

bool JsonReader::optPositive(const json& obj, const std::string& path, std::string_view name,
                             double& out) {
  const json* v = field(obj, name);
  return !v || positive(*v, key(path, name), out);
}

bool JsonReader::optInt(const json& obj, const std::string& path, std::string_view name,
                        long long least, int& out) {
  const json* v = field(obj, name);
  return !v || intAtLeast(*v, key(path, name), least, out);
}

bool JsonReader::optBool(const json& obj, const std::string& path, std::string_view name,
                         bool& out) {
  const json* v = field(obj, name);
  return !v || boolean(*v, key(path, name), out);
}

bool JsonReader::wallMaterial(const json& obj, const std::string& path, VesselDef& def) {
  const json* v = field(obj, "material");
  if (!v) return true;
  const std::string at = key(path, "material");
  WallMaterial m;
  if (!object(*v, at, {"youngs_modulus", "fung_exponent", "density", "damping_ratio"}) ||
      !optPositive(*v, at, "youngs_modulus", m.youngsModulus) ||
      !optNonNegative(*v, at, "fung_exponent", m.fungExponent) ||
      !optPositive(*v, at, "density", m.density) ||
      !optNonNegative(*v, at, "damping_ratio", m.dampingRatio))
    return false;
  // b·s is evaluated up to strain 5; beyond e^50 the law is linear anyway (spring_kernels.h)
  if (m.fungExponent > 50.0) return fail(SceneErrorKind::InvalidValue, key(at, "fung_exponent"));
  def.material = m;
  def.overrides = {field(obj, "k_layer") != nullptr, field(obj, "k_between") != nullptr,
                   field(obj, "mass") != nullptr, field(obj, "damping") != nullptr};
  return true;
}

bool JsonReader::optVec3(const json& obj, const std::string& path, std::string_view name,
                         Vec3& out) {
  const json* v = field(obj, name);
  return !v || vec3(*v, key(path, name), out);
}

SceneError sceneErrorAt(SceneErrorKind kind, const std::string& file, std::string_view text,
                        std::size_t offset) {
  SceneError e;
  e.kind = kind;
  e.file = file;
  e.offset = std::min(offset, text.size());
  std::tie(e.line, e.column) = lineColumnAt(text, e.offset);
  return e;
}

std::variant<nlohmann::json, SceneError> parseSceneJson(std::string_view text,
                                                        const std::string& file) {
  // nlohmann reports the byte where parsing failed
  try {
    return nlohmann::json::parse(text.begin(), text.end());
  } catch (const nlohmann::json::parse_error& e) {
    return sceneErrorAt(SceneErrorKind::MalformedJson, file, text, e.byte > 0 ? e.byte - 1 : 0);
  } catch (const nlohmann::json::out_of_range&) {
    // a number beyond double range, e.g. 1e999: found again in the text
    const std::optional<JsonHit> hit = findOverflowingNumber(text);
    SceneError err = sceneErrorAt(SceneErrorKind::NonFinite, file, text, hit ? hit->offset : 0);
    if (hit) err.field = hit->path;
    return err;
  } catch (const std::exception&) {
    return sceneErrorAt(SceneErrorKind::MalformedJson, file, text, 0);
  }
}

std::variant<SceneFileText, SceneError> readSceneFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::error_code ec;
  if (!in || std::filesystem::is_directory(path, ec)) {
    SceneError e;
    e.kind = SceneErrorKind::FileNotFound;
    e.file = path;
    return e;
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  SceneFileText file{buffer.str(), std::filesystem::path(path).parent_path().string()};
  if (file.baseDir.empty()) file.baseDir = ".";
  return file;
}

}  // namespace microsim::sim::detail
