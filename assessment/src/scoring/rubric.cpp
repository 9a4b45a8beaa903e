#include "microsim/assessment/scoring/rubric.h"

#include "microsim/assessment/scoring/metrics.h"
#include "microsim/sim/scene/json_location.h"
#include "microsim/sim/scene/spring_scene.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <optional>
#include <sstream>

namespace microsim::assessment {

namespace {

using json = nlohmann::json;
using K = RubricErrorKind;

std::string key(const std::string& path, std::string_view name) {
  return path.empty() ? std::string(name) : path + "." + std::string(name);
}
std::string index(const std::string& path, std::size_t i) {
  return path + "[" + std::to_string(i) + "]";
}

// typed reads that keep the first failure with its field path
class RubricReader {
 public:
  bool fail(K kind, const std::string& path) {
    if (!error_) error_ = RubricError{kind, {}, 0, 0, path};
    return false;
  }
  const std::optional<RubricError>& error() const { return error_; }

  bool object(const json& v, const std::string& path,
              std::initializer_list<std::string_view> allowed) {
    if (!v.is_object()) return fail(K::WrongType, path);
    for (auto it = v.begin(); it != v.end(); ++it) {
      bool known = false;
      for (std::string_view a : allowed) known = known || it.key() == a;
      if (!known) return fail(K::UnknownField, key(path, it.key()));
    }
    return true;
  }
  const json* required(const json& obj, const std::string& path, std::string_view name) {
    const auto it = obj.find(name);
    if (it == obj.end()) {
      fail(K::MissingField, key(path, name));
      return nullptr;
    }
    return &*it;
  }
  bool number(const json& v, const std::string& path, double& out) {
    if (!v.is_number()) return fail(K::WrongType, path);
    out = v.get<double>();
    if (!std::isfinite(out)) return fail(K::InvalidValue, path);
    return true;
  }
  bool numberIn(const json& v, const std::string& path, double lo, double hi, double& out) {
    if (!number(v, path, out)) return false;
    return out >= lo && out <= hi ? true : fail(K::InvalidValue, path);
  }
  bool string(const json& v, const std::string& path, std::string& out) {
    if (!v.is_string()) return fail(K::WrongType, path);
    out = v.get<std::string>();
    return out.empty() ? fail(K::InvalidValue, path) : true;
  }
  bool metricKey(const json& v, const std::string& path, std::string& out) {
    if (!string(v, path, out)) return false;
    return findMetric(out) ? true : fail(K::UnknownMetric, path);
  }
  // an optional number ≥ 0 (strictly > 0 when `positive`)
  bool optNonNegative(const json& obj, const std::string& path, std::string_view name,
                      bool positive, double& out) {
    const auto it = obj.find(name);
    if (it == obj.end()) return true;
    const std::string p = key(path, name);
    if (!number(*it, p, out)) return false;
    return (positive ? out > 0.0 : out >= 0.0) ? true : fail(K::InvalidValue, p);
  }

  bool motion(const json& v, const std::string& path, MotionParams& out) {
    return object(v, path, {"movement_speed", "idle_speed", "min_movement_s", "merge_gap_s"}) &&
           optNonNegative(v, path, "movement_speed", true, out.movementSpeed) &&
           optNonNegative(v, path, "idle_speed", false, out.idleSpeed) &&
           optNonNegative(v, path, "min_movement_s", false, out.minMovementS) &&
           optNonNegative(v, path, "merge_gap_s", false, out.mergeGapS);
  }

  bool metric(const json& v, const std::string& path, RubricMetric& out) {
    if (!object(v, path,
                {"key", "weight", "target", "tolerance", "limit", "bad", "feedback",
                 "only_if_task_done"}))
      return false;
    const json* k = required(v, path, "key");
    const json* w = required(v, path, "weight");
    const json* t = required(v, path, "target");
    const json* tol = required(v, path, "tolerance");
    const json* lim = required(v, path, "limit");
    const json* bad = required(v, path, "bad");
    if (!k || !w || !t || !tol || !lim || !bad) return false;
    if (!metricKey(*k, key(path, "key"), out.key) || !number(*w, key(path, "weight"), out.weight) ||
        !number(*t, key(path, "target"), out.target) ||
        !number(*tol, key(path, "tolerance"), out.tolerance) ||
        !number(*lim, key(path, "limit"), out.limit))
      return false;
    if (!(out.weight > 0.0)) return fail(K::InvalidValue, key(path, "weight"));
    if (out.tolerance < 0.0) return fail(K::InvalidValue, key(path, "tolerance"));
    if (!(out.limit > out.tolerance)) return fail(K::InvalidValue, key(path, "limit"));
    std::string side;
    if (!string(*bad, key(path, "bad"), side)) return false;
    if (side == "above")
      out.bad = BadSide::Above;
    else if (side == "below")
      out.bad = BadSide::Below;
    else if (side == "both")
      out.bad = BadSide::Both;
    else
      return fail(K::InvalidValue, key(path, "bad"));
    out.feedbackAbove = out.key + ".too_high";
    out.feedbackBelow = out.key + ".too_low";
    if (const auto f = v.find("feedback"); f != v.end()) {
      const std::string fp = key(path, "feedback");
      if (!object(*f, fp, {"above", "below"})) return false;
      if (const auto a = f->find("above");
          a != f->end() && !string(*a, key(fp, "above"), out.feedbackAbove))
        return false;
      if (const auto b = f->find("below");
          b != f->end() && !string(*b, key(fp, "below"), out.feedbackBelow))
        return false;
    }
    if (const auto d = v.find("only_if_task_done"); d != v.end()) {
      if (!d->is_boolean()) return fail(K::WrongType, key(path, "only_if_task_done"));
      out.onlyIfTaskDone = d->get<bool>();
    }
    return true;
  }

  bool neverEvent(const json& v, const std::string& path, NeverEvent& out) {
    if (!object(v, path, {"metric", "above", "cap", "feedback"})) return false;
    const json* m = required(v, path, "metric");
    const json* a = required(v, path, "above");
    const json* c = required(v, path, "cap");
    const json* f = required(v, path, "feedback");
    return m && a && c && f && metricKey(*m, key(path, "metric"), out.metric) &&
           number(*a, key(path, "above"), out.above) &&
           numberIn(*c, key(path, "cap"), 0.0, 100.0, out.cap) &&
           string(*f, key(path, "feedback"), out.feedback);
  }

  bool rubric(const json& doc, Rubric& out) {
    if (!object(doc, "",
                {"$schema", "id", "version", "pass_mark", "motion", "metrics", "never_events"}))
      return false;
    const json* id = required(doc, "", "id");
    const json* version = required(doc, "", "version");
    const json* pass = required(doc, "", "pass_mark");
    const json* metrics = required(doc, "", "metrics");
    if (!id || !version || !pass || !metrics) return false;
    if (!string(*id, "id", out.id)) return false;
    if (!version->is_number_integer()) return fail(K::WrongType, "version");
    if (version->get<long long>() < 1 || version->get<long long>() > 1000000)
      return fail(K::InvalidValue, "version");
    out.version = static_cast<int>(version->get<long long>());
    if (!numberIn(*pass, "pass_mark", 0.0, 100.0, out.passMark)) return false;
    if (const auto m = doc.find("motion"); m != doc.end() && !motion(*m, "motion", out.motion))
      return false;

    if (!metrics->is_array()) return fail(K::WrongType, "metrics");
    if (metrics->empty()) return fail(K::InvalidValue, "metrics");
    for (std::size_t i = 0; i < metrics->size(); ++i) {
      RubricMetric m;
      if (!metric((*metrics)[i], index("metrics", i), m)) return false;
      out.metrics.push_back(std::move(m));
    }
    if (const auto n = doc.find("never_events"); n != doc.end()) {
      if (!n->is_array()) return fail(K::WrongType, "never_events");
      for (std::size_t i = 0; i < n->size(); ++i) {
        NeverEvent e;
        if (!neverEvent((*n)[i], index("never_events", i), e)) return false;
        out.neverEvents.push_back(std::move(e));
      }
    }
    return true;
  }

 private:
  std::optional<RubricError> error_;
};

// line and column of the value at the error's path (or its nearest enclosing value),
// found the way the scene loader finds its own
RubricError located(RubricError e, std::string_view text) {
  sim::SceneError probe;
  probe.field = e.field;
  sim::locateSceneError(probe, text);
  e.line = probe.line;
  e.column = probe.column;
  return e;
}

RubricError atOffset(K kind, const std::string& file, std::string_view text,
                     std::size_t offset, std::string field = {}) {
  RubricError e{kind, file, 0, 0, std::move(field)};
  std::tie(e.line, e.column) = sim::lineColumnAt(text, offset);
  return e;
}

}  // namespace

std::variant<Rubric, RubricError> parseRubric(std::string_view text, const std::string& file) {
  // syntax first: nlohmann reports the byte where parsing failed
  json doc;
  try {
    doc = json::parse(text.begin(), text.end());
  } catch (const json::parse_error& e) {
    return atOffset(K::MalformedJson, file, text, e.byte > 0 ? e.byte - 1 : 0);
  } catch (const json::out_of_range&) {
    const auto hit = sim::findOverflowingNumber(text);
    return atOffset(K::InvalidValue, file, text, hit ? hit->offset : 0, hit ? hit->path : "");
  } catch (const std::exception&) {
    return atOffset(K::MalformedJson, file, text, 0);
  }

  // then meaning
  Rubric rubric;
  rubric.file = file;
  RubricReader reader;
  bool ok = false;
  try {
    ok = reader.rubric(doc, rubric);
  } catch (const std::exception&) {
    return atOffset(K::InvalidValue, file, text, 0);
  }
  if (ok) return rubric;
  RubricError e = *reader.error();
  e.file = file;
  return located(e, text);
}

std::variant<Rubric, RubricError> loadRubric(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  // a folder opens as a stream and reads as nothing, which would look like bad JSON
  std::error_code ec;
  if (!in || std::filesystem::is_directory(path, ec)) return RubricError{K::FileNotFound, path, 0, 0, {}};
  std::ostringstream text;
  text << in.rdbuf();
  return parseRubric(text.str(), path);
}

}  // namespace microsim::assessment
