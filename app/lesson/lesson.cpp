#include "lesson/lesson.h"

#include "lesson/resource_directory.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>

#include <algorithm>
#include <cmath>
#include <optional>

namespace microsim::lesson {

QString Text::in(const QString& language) const {
  if (language == QLatin1String("de") && !de.isEmpty()) return de;
  if (language == QLatin1String("es") && !es.isEmpty()) return es;
  return en;
}

namespace {

// the conditions that are one count ≥ 1
std::optional<ConditionKind> countedCondition(const QString& key) {
  if (key == QLatin1String("pierces")) return ConditionKind::Pierces;
  if (key == QLatin1String("crossings")) return ConditionKind::Crossings;
  if (key == QLatin1String("stitches")) return ConditionKind::Stitches;
  if (key == QLatin1String("throws")) return ConditionKind::Throws;
  if (key == QLatin1String("knots")) return ConditionKind::Knots;
  if (key == QLatin1String("cuts")) return ConditionKind::Cuts;
  return std::nullopt;
}

// the first failure wins; every reader returns early once `error` is set
class Reader {
 public:
  explicit Reader(QString file) : file_(std::move(file)) {}

  std::optional<LessonError> error;

  bool fail(LessonErrorKind kind, const QString& field, const QString& detail = {}) {
    if (!error) error = LessonError{kind, file_, field, -1, detail};
    return false;
  }

  bool onlyKeys(const QJsonObject& o, const QString& at, const QStringList& allowed) {
    for (auto it = o.begin(); it != o.end(); ++it)
      if (!allowed.contains(it.key())) return fail(LessonErrorKind::UnknownField, join(at, it.key()));
    return true;
  }

  std::optional<QJsonValue> require(const QJsonObject& o, const QString& at, const QString& key) {
    if (!o.contains(key)) {
      fail(LessonErrorKind::Missing, join(at, key));
      return std::nullopt;
    }
    return o.value(key);
  }

  std::optional<QString> string(const QJsonValue& v, const QString& at) {
    if (!v.isString()) {
      fail(LessonErrorKind::WrongType, at, QStringLiteral("string"));
      return std::nullopt;
    }
    return v.toString();
  }

  std::optional<double> number(const QJsonValue& v, const QString& at, double min) {
    if (!v.isDouble()) {
      fail(LessonErrorKind::WrongType, at, QStringLiteral("number"));
      return std::nullopt;
    }
    const double d = v.toDouble();
    if (!std::isfinite(d) || d < min) {
      fail(LessonErrorKind::BadValue, at, QString::number(d));
      return std::nullopt;
    }
    return d;
  }

  std::optional<int> integer(const QJsonValue& v, const QString& at, int min) {
    const std::optional<double> d = number(v, at, min);
    if (!d) return std::nullopt;
    if (*d != std::floor(*d) || *d > 1e6) {
      fail(LessonErrorKind::BadValue, at, QString::number(*d));
      return std::nullopt;
    }
    return static_cast<int>(*d);
  }

  std::optional<Text> text(const QJsonValue& v, const QString& at) {
    if (!v.isObject()) {
      fail(LessonErrorKind::WrongType, at, QStringLiteral("object"));
      return std::nullopt;
    }
    const QJsonObject o = v.toObject();
    if (!onlyKeys(o, at, {QStringLiteral("en"), QStringLiteral("de"), QStringLiteral("es")}))
      return std::nullopt;
    Text t;
    const std::optional<QJsonValue> en = require(o, at, QStringLiteral("en"));
    if (!en) return std::nullopt;
    const std::optional<QString> english = string(*en, join(at, QStringLiteral("en")));
    if (!english) return std::nullopt;
    if (english->trimmed().isEmpty()) {
      fail(LessonErrorKind::BadValue, join(at, QStringLiteral("en")));
      return std::nullopt;
    }
    t.en = *english;
    for (const QString& lang : {QStringLiteral("de"), QStringLiteral("es")}) {
      if (!o.contains(lang)) continue;
      const std::optional<QString> s = string(o.value(lang), join(at, lang));
      if (!s) return std::nullopt;
      (lang == QLatin1String("de") ? t.de : t.es) = *s;
    }
    return t;
  }

  std::optional<Eigen::Vector3d> vec3(const QJsonValue& v, const QString& at) {
    if (!v.isArray() || v.toArray().size() != 3) {
      fail(LessonErrorKind::WrongType, at, QStringLiteral("[x, y, z]"));
      return std::nullopt;
    }
    Eigen::Vector3d out;
    for (int i = 0; i < 3; ++i) {
      const std::optional<double> d =
          number(v.toArray().at(i), QStringLiteral("%1[%2]").arg(at).arg(i), -1e9);
      if (!d) return std::nullopt;
      out[i] = *d;
    }
    return out;
  }

  std::optional<Condition> condition(const QJsonValue& v, const QString& at) {
    if (!v.isObject()) {
      fail(LessonErrorKind::WrongType, at, QStringLiteral("object"));
      return std::nullopt;
    }
    const QJsonObject o = v.toObject();
    if (o.size() != 1) {
      fail(LessonErrorKind::BadValue, at, QStringLiteral("exactly one condition"));
      return std::nullopt;
    }
    const QString key = o.begin().key();
    const QJsonValue value = o.begin().value();
    const QString here = join(at, key);
    Condition c;
    if (key == QLatin1String("grab")) {
      c.kind = ConditionKind::Grab;
      if (!value.isObject()) return failed(LessonErrorKind::WrongType, here, QStringLiteral("object"));
      const QJsonObject g = value.toObject();
      if (!onlyKeys(g, here, {QStringLiteral("min_nodes")})) return std::nullopt;
      const std::optional<QJsonValue> n = require(g, here, QStringLiteral("min_nodes"));
      if (!n) return std::nullopt;
      const std::optional<int> count = integer(*n, join(here, QStringLiteral("min_nodes")), 1);
      if (!count) return std::nullopt;
      c.count = *count;
    } else if (key == QLatin1String("stretch_mm")) {
      c.kind = ConditionKind::Stretch;
      const std::optional<double> mm = number(value, here, 1e-6);
      if (!mm) return std::nullopt;
      c.millimetres = *mm;
    } else if (const std::optional<ConditionKind> counted = countedCondition(key)) {
      c.kind = *counted;
      const std::optional<int> count = integer(value, here, 1);
      if (!count) return std::nullopt;
      c.count = *count;
    } else if (key == QLatin1String("target")) {
      c.kind = ConditionKind::Target;
      if (!value.isObject()) return failed(LessonErrorKind::WrongType, here, QStringLiteral("object"));
      const QJsonObject t = value.toObject();
      if (!onlyKeys(t, here, {QStringLiteral("index"), QStringLiteral("tolerance_mm")})) return std::nullopt;
      const std::optional<QJsonValue> index = require(t, here, QStringLiteral("index"));
      const std::optional<QJsonValue> tol = index ? require(t, here, QStringLiteral("tolerance_mm")) : std::nullopt;
      if (!tol) return std::nullopt;
      const std::optional<int> i = integer(*index, join(here, QStringLiteral("index")), 0);
      const std::optional<double> mm = i ? number(*tol, join(here, QStringLiteral("tolerance_mm")), 1e-6) : std::nullopt;
      if (!mm) return std::nullopt;
      c.count = *i;
      c.millimetres = *mm;
    } else {
      fail(LessonErrorKind::UnknownField, here);
      return std::nullopt;
    }
    return c;
  }

  std::optional<Condition> failed(LessonErrorKind kind, const QString& field, const QString& detail) {
    fail(kind, field, detail);
    return std::nullopt;
  }

  static QString join(const QString& at, const QString& key) {
    return at.isEmpty() ? key : at + QLatin1Char('.') + key;
  }
  static QString index(const QString& at, qsizetype i) { return QStringLiteral("%1[%2]").arg(at).arg(i); }

 private:
  QString file_;
};

std::variant<Lesson, LessonError> parse(const QJsonObject& root, const QString& file) {
  Reader r(file);
  auto failure = [&r]() -> std::variant<Lesson, LessonError> { return *r.error; };
  Lesson lesson;
  lesson.file = file;
  if (!r.onlyKeys(root, {}, {QStringLiteral("id"), QStringLiteral("version"), QStringLiteral("title"),
                             QStringLiteral("goals"), QStringLiteral("scene"), QStringLiteral("rubric"),
                             QStringLiteral("steps"), QStringLiteral("guides"), QStringLiteral("$schema")}))
    return failure();

  // id, version, title, goals
  const std::optional<QJsonValue> id = r.require(root, {}, QStringLiteral("id"));
  const std::optional<QString> idText = id ? r.string(*id, QStringLiteral("id")) : std::nullopt;
  if (!idText) return failure();
  static const QRegularExpression idPattern(QStringLiteral("^[0-9a-z_]+$"));
  if (!idPattern.match(*idText).hasMatch()) {
    r.fail(LessonErrorKind::BadValue, QStringLiteral("id"), *idText);
    return failure();
  }
  lesson.id = *idText;
  const std::optional<QJsonValue> version = r.require(root, {}, QStringLiteral("version"));
  const std::optional<int> v = version ? r.integer(*version, QStringLiteral("version"), 1) : std::nullopt;
  if (!v) return failure();
  lesson.version = *v;
  const std::optional<QJsonValue> title = r.require(root, {}, QStringLiteral("title"));
  const std::optional<Text> t = title ? r.text(*title, QStringLiteral("title")) : std::nullopt;
  if (!t) return failure();
  lesson.title = *t;
  const std::optional<QJsonValue> goals = r.require(root, {}, QStringLiteral("goals"));
  if (!goals) return failure();
  if (!goals->isArray()) {
    r.fail(LessonErrorKind::WrongType, QStringLiteral("goals"), QStringLiteral("array"));
    return failure();
  }
  const QJsonArray goalArray = goals->toArray();
  for (qsizetype i = 0; i < goalArray.size(); ++i) {
    const std::optional<Text> g = r.text(goalArray.at(i), Reader::index(QStringLiteral("goals"), i));
    if (!g) return failure();
    lesson.goals.push_back(*g);
  }

  // scene and rubric, relative to the lesson file
  const QDir base = QFileInfo(file).absoluteDir();
  for (const QString& key : {QStringLiteral("scene"), QStringLiteral("rubric")}) {
    const std::optional<QJsonValue> value = r.require(root, {}, key);
    const std::optional<QString> rel = value ? r.string(*value, key) : std::nullopt;
    if (!rel) return failure();
    const QString path = QDir::cleanPath(base.absoluteFilePath(*rel));
    if (!QFileInfo::exists(path)) {
      r.fail(LessonErrorKind::MissingFile, key, path);
      return failure();
    }
    (key == QLatin1String("scene") ? lesson.scenePath : lesson.rubricPath) = path;
  }

  // steps
  const std::optional<QJsonValue> steps = r.require(root, {}, QStringLiteral("steps"));
  if (!steps) return failure();
  if (!steps->isArray()) {
    r.fail(LessonErrorKind::WrongType, QStringLiteral("steps"), QStringLiteral("array"));
    return failure();
  }
  const QJsonArray stepArray = steps->toArray();
  if (stepArray.isEmpty()) {
    r.fail(LessonErrorKind::BadValue, QStringLiteral("steps"), QStringLiteral("at least one step"));
    return failure();
  }
  for (qsizetype i = 0; i < stepArray.size(); ++i) {
    const QString at = Reader::index(QStringLiteral("steps"), i);
    if (!stepArray.at(i).isObject()) {
      r.fail(LessonErrorKind::WrongType, at, QStringLiteral("object"));
      return failure();
    }
    const QJsonObject s = stepArray.at(i).toObject();
    if (!r.onlyKeys(s, at, {QStringLiteral("instruction"), QStringLiteral("success")})) return failure();
    const std::optional<QJsonValue> instruction = r.require(s, at, QStringLiteral("instruction"));
    const std::optional<Text> text = instruction ? r.text(*instruction, Reader::join(at, QStringLiteral("instruction"))) : std::nullopt;
    const std::optional<QJsonValue> success = text ? r.require(s, at, QStringLiteral("success")) : std::nullopt;
    const std::optional<Condition> c = success ? r.condition(*success, Reader::join(at, QStringLiteral("success"))) : std::nullopt;
    if (!c) return failure();
    lesson.steps.push_back({*text, *c});
  }

  // guides
  if (root.contains(QStringLiteral("guides"))) {
    const QJsonValue guides = root.value(QStringLiteral("guides"));
    if (!guides.isArray()) {
      r.fail(LessonErrorKind::WrongType, QStringLiteral("guides"), QStringLiteral("array"));
      return failure();
    }
    const QJsonArray guideArray = guides.toArray();
    for (qsizetype i = 0; i < guideArray.size(); ++i) {
      const QString at = Reader::index(QStringLiteral("guides"), i);
      if (!guideArray.at(i).isObject()) {
        r.fail(LessonErrorKind::WrongType, at, QStringLiteral("object"));
        return failure();
      }
      const QJsonObject g = guideArray.at(i).toObject();
      if (!r.onlyKeys(g, at, {QStringLiteral("target"), QStringLiteral("direction")})) return failure();
      const std::optional<QJsonValue> target = r.require(g, at, QStringLiteral("target"));
      const std::optional<Eigen::Vector3d> p = target ? r.vec3(*target, Reader::join(at, QStringLiteral("target"))) : std::nullopt;
      const std::optional<QJsonValue> direction = p ? r.require(g, at, QStringLiteral("direction")) : std::nullopt;
      const std::optional<Eigen::Vector3d> d = direction ? r.vec3(*direction, Reader::join(at, QStringLiteral("direction"))) : std::nullopt;
      if (!d) return failure();
      if (d->norm() < 1e-9) {
        r.fail(LessonErrorKind::BadValue, Reader::join(at, QStringLiteral("direction")), QStringLiteral("zero vector"));
        return failure();
      }
      lesson.guides.push_back({*p, d->normalized()});
    }
  }

  // a target condition must name a guide
  for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
    const Condition& c = lesson.steps[i].success;
    if (c.kind == ConditionKind::Target && c.count >= static_cast<int>(lesson.guides.size())) {
      r.fail(LessonErrorKind::BadValue,
             Reader::index(QStringLiteral("steps"), static_cast<qsizetype>(i)) + QStringLiteral(".success.target.index"),
             QString::number(c.count));
      return failure();
    }
  }
  return lesson;
}

}  // namespace

std::variant<Lesson, LessonError> loadLesson(const QString& path) {
  const QString file = QFileInfo(path).absoluteFilePath();
  QFile f(file);
  if (!f.open(QIODevice::ReadOnly))
    return LessonError{LessonErrorKind::CannotOpen, file, {}, -1, f.errorString()};
  QJsonParseError parseError;
  const QByteArray text = f.readAll();
  const QJsonDocument doc = QJsonDocument::fromJson(text, &parseError);
  if (parseError.error != QJsonParseError::NoError) {
    // Qt places some errors at the end of input one past the last byte (e.g. a file cut off
    // inside a string); the error points at the text, so it is clamped to its end
    const int offset = static_cast<int>(std::min<qsizetype>(parseError.offset, text.size()));
    return LessonError{LessonErrorKind::NotJson, file, {}, offset, parseError.errorString()};
  }
  if (!doc.isObject())
    return LessonError{LessonErrorKind::WrongType, file, {}, -1, QStringLiteral("object")};
  return parse(doc.object(), file);
}

std::vector<Lesson> loadLessons(const QString& directory, std::vector<LessonError>* errors) {
  std::vector<Lesson> lessons;
  const QDir dir(directory);
  const QStringList files = dir.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name);
  for (const QString& name : files) {
    std::variant<Lesson, LessonError> result = loadLesson(dir.filePath(name));
    if (auto* lesson = std::get_if<Lesson>(&result))
      lessons.push_back(std::move(*lesson));
    else if (errors)
      errors->push_back(std::get<LessonError>(result));
  }
  return lessons;
}

QString lessonsDirectory() { return QDir(resourceDirectory()).filePath(QStringLiteral("lessons")); }

}  // namespace microsim::lesson
