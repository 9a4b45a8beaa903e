// Rubric files: a valid one loads with its defaults; malformed ones fail with the file,
// line:column and field path; every shipped rubric loads.
#include "microsim/assessment/scoring/rubric.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace {

using namespace microsim::assessment;

const std::string kValid = R"({
  "id": "demo",
  "version": 3,
  "pass_mark": 65,
  "motion": {"movement_speed": 2},
  "metrics": [
    {"key": "entry_angle", "weight": 2, "target": 0, "tolerance": 15, "limit": 45, "bad": "above",
     "feedback": {"above": "entry_angle.too_oblique"}},
    {"key": "bite", "weight": 1, "target": 0.25, "tolerance": 0.05, "limit": 0.2, "bad": "both",
     "only_if_task_done": true}
  ],
  "never_events": [{"metric": "back_wall_catches", "above": 0, "cap": 0, "feedback": "never.back_wall_catch"}]
})";

RubricError errorOf(const std::string& text) {
  auto r = parseRubric(text, "r.json");
  EXPECT_TRUE(std::holds_alternative<RubricError>(r));
  return std::holds_alternative<RubricError>(r) ? std::get<RubricError>(r) : RubricError{};
}

// kValid with one substring replaced
std::string with(const std::string& from, const std::string& to) {
  std::string s = kValid;
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return s.replace(at, from.size(), to);
}

TEST(Rubric, AValidRubricLoadsWithDefaults) {
  auto r = parseRubric(kValid, "r.json");
  ASSERT_TRUE(std::holds_alternative<Rubric>(r));
  const Rubric& rubric = std::get<Rubric>(r);
  EXPECT_EQ(rubric.id, "demo");
  EXPECT_EQ(rubric.version, 3);
  EXPECT_DOUBLE_EQ(rubric.passMark, 65.0);
  EXPECT_DOUBLE_EQ(rubric.motion.movementSpeed, 2.0);
  EXPECT_DOUBLE_EQ(rubric.motion.idleSpeed, MotionParams{}.idleSpeed);
  ASSERT_EQ(rubric.metrics.size(), 2u);
  EXPECT_EQ(rubric.metrics[0].bad, BadSide::Above);
  EXPECT_EQ(rubric.metrics[0].feedbackAbove, "entry_angle.too_oblique");
  EXPECT_EQ(rubric.metrics[0].feedbackBelow, "entry_angle.too_low");
  EXPECT_EQ(rubric.metrics[1].feedbackAbove, "bite.too_high");
  EXPECT_FALSE(rubric.metrics[0].onlyIfTaskDone) << "by default a metric is part of the task";
  EXPECT_TRUE(rubric.metrics[1].onlyIfTaskDone);
  ASSERT_EQ(rubric.neverEvents.size(), 1u);
  EXPECT_EQ(rubric.neverEvents[0].feedback, "never.back_wall_catch");
}

TEST(Rubric, BrokenJsonNamesTheLineAndColumn) {
  const RubricError e = errorOf("{\n  \"id\": \"x\",\n  \"version\": 1,,\n}");
  EXPECT_EQ(e.kind, RubricErrorKind::MalformedJson);
  EXPECT_EQ(e.file, "r.json");
  EXPECT_EQ(e.line, 3);
  EXPECT_EQ(e.column, 16);
}

TEST(Rubric, AWrongTypeNamesTheFieldAndWhereItIs) {
  const RubricError e = errorOf(with("\"tolerance\": 15", "\"tolerance\": \"15\""));
  EXPECT_EQ(e.kind, RubricErrorKind::WrongType);
  EXPECT_EQ(e.field, "metrics[0].tolerance");
  EXPECT_EQ(e.line, 7);
  EXPECT_GT(e.column, 1);
}

TEST(Rubric, UnknownMetricsFieldsAndMissingFieldsAreErrors) {
  EXPECT_EQ(errorOf(with("\"key\": \"bite\"", "\"key\": \"bight\"")).kind, RubricErrorKind::UnknownMetric);
  EXPECT_EQ(errorOf(with("\"key\": \"bite\"", "\"key\": \"bight\"")).field, "metrics[1].key");
  const RubricError unknown = errorOf(with("\"weight\": 1,", "\"weigth\": 1,"));
  EXPECT_EQ(unknown.kind, RubricErrorKind::UnknownField);
  EXPECT_EQ(unknown.field, "metrics[1].weigth");
  const RubricError missing = errorOf(with("\"pass_mark\": 65,", ""));
  EXPECT_EQ(missing.kind, RubricErrorKind::MissingField);
  EXPECT_EQ(missing.field, "pass_mark");
  EXPECT_EQ(errorOf(with("\"metric\": \"back_wall_catches\"", "\"metric\": \"oops\"")).field,
            "never_events[0].metric");
}

TEST(Rubric, OutOfRangeValuesAreInvalid) {
  EXPECT_EQ(errorOf(with("\"limit\": 45", "\"limit\": 10")).field, "metrics[0].limit");
  EXPECT_EQ(errorOf(with("\"weight\": 2", "\"weight\": 0")).field, "metrics[0].weight");
  EXPECT_EQ(errorOf(with("\"pass_mark\": 65", "\"pass_mark\": 101")).field, "pass_mark");
  EXPECT_EQ(errorOf(with("\"version\": 3", "\"version\": 0")).field, "version");
  EXPECT_EQ(errorOf(with("\"version\": 3", "\"version\": 1.5")).kind, RubricErrorKind::WrongType);
  const RubricError flag = errorOf(with("\"only_if_task_done\": true", "\"only_if_task_done\": 1"));
  EXPECT_EQ(flag.kind, RubricErrorKind::WrongType);
  EXPECT_EQ(flag.field, "metrics[1].only_if_task_done");
  EXPECT_EQ(errorOf(with("\"bad\": \"both\"", "\"bad\": \"sideways\"")).field, "metrics[1].bad");
  EXPECT_EQ(errorOf(with("\"cap\": 0", "\"cap\": 1e999")).kind, RubricErrorKind::InvalidValue);
  const RubricError empty = errorOf(R"({"id": "x", "version": 1, "pass_mark": 50, "metrics": []})");
  EXPECT_EQ(empty.kind, RubricErrorKind::InvalidValue);
  EXPECT_EQ(empty.field, "metrics");
}

TEST(Rubric, AMissingFileSaysSo) {
  auto r = loadRubric("/nonexistent/rubric.json");
  ASSERT_TRUE(std::holds_alternative<RubricError>(r));
  EXPECT_EQ(std::get<RubricError>(r).kind, RubricErrorKind::FileNotFound);
  EXPECT_EQ(std::get<RubricError>(r).file, "/nonexistent/rubric.json");
}

TEST(Rubric, EveryShippedRubricLoadsAndIsNamedAfterItsFile) {
  const std::filesystem::path dir = std::filesystem::path(MICROSIM_SOURCE_DIR) / "resources" / "rubrics";
  int count = 0;
  for (const char* lesson : {"01_orientation", "02_needle_entry", "03_single_stitch", "04_triangulation",
                             "05_full_anastomosis"}) {
    auto r = loadRubric((dir / (std::string(lesson) + ".json")).string());
    ASSERT_TRUE(std::holds_alternative<Rubric>(r)) << lesson << " field " << std::get<RubricError>(r).field;
    EXPECT_EQ(std::get<Rubric>(r).id, lesson);
    ++count;
  }
  EXPECT_EQ(count, 5);
}

}  // namespace
