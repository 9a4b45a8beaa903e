#include "lesson/lesson.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cstring>

namespace microsim::lesson {
namespace {

const QString kLessons = QStringLiteral(MICROSIM_SOURCE_DIR "/resources/lessons");

// a valid lesson beside a scene and a rubric file, with `patch` applied to its text
struct LessonFile {
  QTemporaryDir dir;
  QString path;

  explicit LessonFile(const QByteArray& json) {
    QDir(dir.path()).mkpath(QStringLiteral("lessons"));
    for (const char* name : {"scene.json", "rubric.json"}) {
      QFile f(dir.filePath(QString::fromLatin1(name)));
      EXPECT_TRUE(f.open(QIODevice::WriteOnly));
      f.write("{}");
    }
    path = dir.filePath(QStringLiteral("lessons/l.json"));
    QFile f(path);
    EXPECT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(json);
  }
};

const QByteArray kSteps = R"([{"instruction": {"en": "Grab"}, "success": {"grab": {"min_nodes": 2}}}])";

QByteArray valid(const QByteArray& steps = kSteps,
                 const QByteArray& extra = {}) {
  return R"({"id": "t_1", "version": 2, "title": {"en": "T", "de": "T-de"}, "goals": [{"en": "G"}],
             "scene": "../scene.json", "rubric": "../rubric.json", "steps": )" + steps + extra + "}";
}

LessonError errorOf(const QByteArray& json) {
  LessonFile f(json);
  const auto result = loadLesson(f.path);
  EXPECT_TRUE(std::holds_alternative<LessonError>(result)) << json.toStdString();
  if (!std::holds_alternative<LessonError>(result)) return {};
  LessonError e = std::get<LessonError>(result);
  EXPECT_EQ(e.file, f.path);
  return e;
}

TEST(Lesson, LoadsAValidFile) {
  LessonFile f(valid(kSteps, R"(, "guides": [{"target": [1, 2, 3], "direction": [0, 0, 2]}])"));
  const auto result = loadLesson(f.path);
  ASSERT_TRUE(std::holds_alternative<Lesson>(result));
  const Lesson& l = std::get<Lesson>(result);
  EXPECT_EQ(l.id, QStringLiteral("t_1"));
  EXPECT_EQ(l.version, 2);
  EXPECT_EQ(l.title.in(QStringLiteral("de")), QStringLiteral("T-de"));
  EXPECT_EQ(l.title.in(QStringLiteral("es")), QStringLiteral("T"));  // falls back to English
  ASSERT_EQ(l.steps.size(), 1u);
  EXPECT_EQ(l.steps[0].success.kind, ConditionKind::Grab);
  EXPECT_EQ(l.steps[0].success.count, 2);
  ASSERT_EQ(l.guides.size(), 1u);
  EXPECT_DOUBLE_EQ(l.guides[0].direction.z(), 1.0);  // normalised
  EXPECT_EQ(l.scenePath, f.dir.filePath(QStringLiteral("scene.json")));
  EXPECT_EQ(l.rubricPath, f.dir.filePath(QStringLiteral("rubric.json")));
}

TEST(Lesson, EveryShippedLessonLoads) {
  std::vector<LessonError> errors;
  const std::vector<Lesson> lessons = loadLessons(kLessons, &errors);
  for (const LessonError& e : errors)
    ADD_FAILURE() << e.file.toStdString() << ": " << e.field.toStdString() << " " << e.detail.toStdString();
  ASSERT_EQ(lessons.size(), 6u);
  const QStringList ids = {QStringLiteral("01_orientation"), QStringLiteral("02_needle_entry"),
                           QStringLiteral("02b_instrument_tie"), QStringLiteral("03_single_stitch"), QStringLiteral("04_triangulation"),
                           QStringLiteral("05_full_anastomosis")};
  for (std::size_t i = 0; i < lessons.size(); ++i) {
    EXPECT_EQ(lessons[i].id, ids[static_cast<qsizetype>(i)]);
    EXPECT_FALSE(lessons[i].title.de.isEmpty()) << lessons[i].id.toStdString();
    EXPECT_FALSE(lessons[i].title.es.isEmpty()) << lessons[i].id.toStdString();
    for (const Step& s : lessons[i].steps) {
      EXPECT_FALSE(s.instruction.de.isEmpty()) << lessons[i].id.toStdString();
      EXPECT_FALSE(s.instruction.es.isEmpty()) << lessons[i].id.toStdString();
    }
  }
}

TEST(Lesson, ReportsSyntaxErrorsWithAnOffset) {
  const LessonError e = errorOf(R"({"id": "x", )");
  EXPECT_EQ(e.kind, LessonErrorKind::NotJson);
  EXPECT_GT(e.offset, 0);
}

TEST(Lesson, PlacesTheErrorOfAFileCutOffInAStringInsideTheFile) {
  // found by the lesson fuzzer: Qt reports a string left open at the end of the input one
  // byte past the end
  const char* text = "{\"id\": \"cut off";
  const LessonError e = errorOf(text);
  EXPECT_EQ(e.kind, LessonErrorKind::NotJson);
  EXPECT_GT(e.offset, 0);
  EXPECT_LE(e.offset, static_cast<int>(std::strlen(text)));
}

TEST(Lesson, ReportsAMissingFile) {
  const auto result = loadLesson(QStringLiteral("/nonexistent/lesson.json"));
  ASSERT_TRUE(std::holds_alternative<LessonError>(result));
  EXPECT_EQ(std::get<LessonError>(result).kind, LessonErrorKind::CannotOpen);
}

struct BadCase {
  QByteArray json;
  LessonErrorKind kind;
  const char* field;
};

TEST(Lesson, NamesTheFieldOfEveryMalformedValue) {
  const std::vector<BadCase> cases = {
      {"[1, 2]", LessonErrorKind::WrongType, ""},
      {R"({"version": 1})", LessonErrorKind::Missing, "id"},
      {valid(kSteps, R"(, "colour": 1)"), LessonErrorKind::UnknownField, "colour"},
      {valid(R"({"a": 1})"), LessonErrorKind::WrongType, "steps"},
      {valid("[]"), LessonErrorKind::BadValue, "steps"},
      {valid(R"([{"instruction": {"en": "x"}}])"), LessonErrorKind::Missing, "steps[0].success"},
      {valid(R"([{"instruction": {"en": "x"}, "success": {"grab": {"min_nodes": 1}}},
                 {"instruction": {"en": "y"}, "success": {"pierces": -2}}])"),
       LessonErrorKind::BadValue, "steps[1].success.pierces"},
      {valid(R"([{"instruction": {"en": "x"}, "success": {"pierces": 1.5}}])"), LessonErrorKind::BadValue,
       "steps[0].success.pierces"},
      {valid(R"([{"instruction": {"en": "x"}, "success": {"knots": 0}}])"), LessonErrorKind::BadValue,
       "steps[0].success.knots"},
      {valid(R"([{"instruction": {"en": "x"}, "success": {"cuts": "both"}}])"), LessonErrorKind::WrongType,
       "steps[0].success.cuts"},
      {valid(R"([{"instruction": {"en": "x"}, "success": {"jump": 1}}])"), LessonErrorKind::UnknownField,
       "steps[0].success.jump"},
      {valid(R"([{"instruction": {"en": "x"}, "success": {"pierces": 1, "stitches": 1}}])"),
       LessonErrorKind::BadValue, "steps[0].success"},
      {valid(R"([{"instruction": {"fr": "x"}, "success": {"pierces": 1}}])"), LessonErrorKind::UnknownField,
       "steps[0].instruction.fr"},
      {valid(R"([{"instruction": {"de": "x"}, "success": {"pierces": 1}}])"), LessonErrorKind::Missing,
       "steps[0].instruction.en"},
      {valid(R"([{"instruction": {"en": "x"}, "success": {"stretch_mm": "far"}}])"), LessonErrorKind::WrongType,
       "steps[0].success.stretch_mm"},
      {valid(R"([{"instruction": {"en": "x"}, "success": {"target": {"index": 3, "tolerance_mm": 0.1}}}])"),
       LessonErrorKind::BadValue, "steps[0].success.target.index"},
      {valid(kSteps, R"(, "guides": [{"target": [1, 2], "direction": [0, 0, 1]}])"), LessonErrorKind::WrongType,
       "guides[0].target"},
      {valid(kSteps, R"(, "guides": [{"target": [1, 2, 3], "direction": [0, 0, 0]}])"), LessonErrorKind::BadValue,
       "guides[0].direction"},
  };
  for (const BadCase& c : cases) {
    const LessonError e = errorOf(c.json);
    EXPECT_EQ(e.kind, c.kind) << c.json.toStdString();
    EXPECT_EQ(e.field.toStdString(), c.field) << c.json.toStdString();
  }
}

TEST(Lesson, RejectsABadIdAndAMissingScene) {
  QByteArray badId = valid();
  badId.replace("\"t_1\"", "\"Lesson One\"");
  EXPECT_EQ(errorOf(badId).field, QStringLiteral("id"));
  QByteArray noScene = valid();
  noScene.replace("../scene.json", "../nowhere.json");
  const LessonError e = errorOf(noScene);
  EXPECT_EQ(e.kind, LessonErrorKind::MissingFile);
  EXPECT_EQ(e.field, QStringLiteral("scene"));
}

TEST(Lesson, LoadLessonsCollectsErrorsAndKeepsTheGoodOnes) {
  LessonFile f(valid());
  QFile bad(f.dir.filePath(QStringLiteral("lessons/0_bad.json")));
  ASSERT_TRUE(bad.open(QIODevice::WriteOnly));
  bad.write("not json");
  bad.close();
  std::vector<LessonError> errors;
  const std::vector<Lesson> lessons = loadLessons(f.dir.filePath(QStringLiteral("lessons")), &errors);
  ASSERT_EQ(lessons.size(), 1u);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_TRUE(errors[0].file.endsWith(QStringLiteral("0_bad.json")));
}

}  // namespace
}  // namespace microsim::lesson
