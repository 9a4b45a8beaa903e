#include "microsim/sim/scene/json_location.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <tuple>

namespace microsim::sim {

namespace {

class Scanner {
 public:
  // with `overflow` set, the scan stops at the first number no double can hold instead of
  // at `target`
  Scanner(std::string_view text, std::string_view target, bool overflow = false)
      : text_(text), target_(target), overflow_(overflow) {}

  std::optional<std::size_t> run() {
    value();
    return found_;
  }
  const std::string& path() const { return path_; }

 private:
  bool more() const { return pos_ < text_.size() && !found_; }
  char peek() const { return pos_ < text_.size() ? text_[pos_] : '\0'; }
  void skipSpace() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t' ||
                                   text_[pos_] == '\n' || text_[pos_] == '\r'))
      ++pos_;
  }

  // a string's raw contents, escapes left as written
  std::string_view string() {
    const std::size_t begin = ++pos_;
    while (pos_ < text_.size() && text_[pos_] != '"') pos_ += text_[pos_] == '\\' ? 2 : 1;
    const std::size_t end = pos_ < text_.size() ? pos_ : text_.size();
    ++pos_;
    return text_.substr(begin, end - begin);
  }

  void value() {
    skipSpace();
    if (!overflow_ && path_ == target_) {
      found_ = pos_;
      return;
    }
    const std::size_t begin = pos_;
    switch (peek()) {
      case '{':
        object();
        break;
      case '[':
        array();
        break;
      case '"':
        string();
        break;
      default:
        while (pos_ < text_.size() && text_[pos_] != ',' && text_[pos_] != ']' &&
               text_[pos_] != '}' && text_[pos_] != ' ' && text_[pos_] != '\n' &&
               text_[pos_] != '\t' && text_[pos_] != '\r')
          ++pos_;
        if (overflow_ && overflows(text_.substr(begin, pos_ - begin))) found_ = begin;
    }
  }

  static bool overflows(std::string_view token) {
    if (token.empty() || !(token[0] == '-' || (token[0] >= '0' && token[0] <= '9'))) return false;
    const std::string s(token);
    return !std::isfinite(std::strtod(s.c_str(), nullptr));
  }

  void object() {
    ++pos_;
    skipSpace();
    while (more() && peek() != '}') {
      const std::string_view key = string();
      skipSpace();
      ++pos_;  // ':'
      const std::size_t length = path_.size();
      if (!path_.empty()) path_ += '.';
      path_ += key;
      value();
      if (found_) return;
      path_.resize(length);
      skipSpace();
      if (peek() == ',') ++pos_;
      skipSpace();
    }
    ++pos_;
  }

  void array() {
    ++pos_;
    skipSpace();
    for (int index = 0; more() && peek() != ']'; ++index) {
      const std::size_t length = path_.size();
      path_ += '[' + std::to_string(index) + ']';
      value();
      if (found_) return;
      path_.resize(length);
      skipSpace();
      if (peek() == ',') ++pos_;
      skipSpace();
    }
    ++pos_;
  }

  std::string_view text_;
  std::string_view target_;
  bool overflow_ = false;
  std::string path_;
  std::size_t pos_ = 0;
  std::optional<std::size_t> found_;
};

}  // namespace

std::optional<std::size_t> locateJsonPath(std::string_view text, std::string_view path) {
  return Scanner(text, path).run();
}

std::optional<JsonHit> findOverflowingNumber(std::string_view text) {
  Scanner scanner(text, {}, true);
  const std::optional<std::size_t> offset = scanner.run();
  if (!offset) return std::nullopt;
  return JsonHit{*offset, scanner.path()};
}

void locateSceneError(SceneError& e, std::string_view text) {
  std::string path = e.field;
  std::optional<std::size_t> offset = locateJsonPath(text, path);
  while (!offset && !path.empty()) {
    const std::size_t cut = path.find_last_of(".[");
    path.resize(cut == std::string::npos ? 0 : cut);
    offset = locateJsonPath(text, path);
  }
  e.offset = std::min(offset.value_or(0), text.size());
  std::tie(e.line, e.column) = lineColumnAt(text, e.offset);
}

}  // namespace microsim::sim
