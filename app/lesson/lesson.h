#pragma once
// A lesson: what the trainee is asked to do in one scene, step by step, and how it is graded.
// Lessons are data, resources/lessons/NN_name.json (schema resources/schema/lesson.schema.json):
//
//   {"id": "02_needle_entry",                      required, [0-9a-z_]+
//    "version": 1,                                 required, integer ≥ 1
//    "title": TEXT, "goals": [TEXT, ...],          required
//    "scene": "../scenes/anastomosis.json",        required, relative to the lesson file
//    "rubric": "../rubrics/02_needle_entry.json",  required, relative to the lesson file
//    "steps": [{"instruction": TEXT, "success": CONDITION}, ...],   required, at least one
//    "guides": [{"target": [x, y, z], "direction": [x, y, z]}, ...]} optional (Learn mode)
//
// TEXT is {"en": "...", "de": "...", "es": "..."}: English required, the others optional;
// Text::in() falls back to English. CONDITION is exactly one of
//   {"grab": {"min_nodes": N}}           a forceps took hold of at least N tissue nodes
//   {"stretch_mm": D}                     some tissue node moved at least D mm from rest
//   {"pierces": N}                        the needle entered a wall at least N times
//   {"crossings": N}                      the needle crossed the gap N times: entered one end
//                                         from its lumen after leaving the other
//   {"stitches": N}                       N stitches: both ends passed through, in turn
//   {"throws": N}                         N throws formed in the thread (ThrowFormed events)
//   {"knots": N}                          N knots pulled tight (KnotTightened events)
//   {"cuts": N}                           the scissors cut N tails: cuts that leave a cut end
//                                         on a stitch (trimming loose thread does not count)
//   {"target": {"index": I, "tolerance_mm": T}}   a pierce within T mm of guides[I].target
// A guide's target is a point on the vessel (mm, scene frame); its direction the ideal needle
// tangent there (unit after loading; perpendicular to the wall).
//
// Loading never throws: a malformed file gives a LessonError naming the file and the field
// path ("steps[2].success.pierces"), as the scene loader does.

#include <Eigen/Core>

#include <QString>
#include <QStringList>

#include <variant>
#include <vector>

namespace microsim::lesson {

/// One user-facing text in every language the lesson file gives.
struct Text {
  QString en;
  QString de;
  QString es;
  /// The text in `language` ("en", "de", "es"), English when that one is missing.
  QString in(const QString& language) const;
};

enum class ConditionKind {
  Grab,
  Stretch,
  Pierces,
  Crossings,
  Stitches,
  Throws,
  Knots,
  Cuts,
  Target
};

struct Condition {
  ConditionKind kind = ConditionKind::Grab;
  int count = 1;  ///< Grab: min nodes; Pierces ... Cuts: how many; Target: guide index
  double millimetres = 0.0;   ///< Stretch: displacement (mm); Target: tolerance (mm)
};

struct Step {
  Text instruction;
  Condition success;
};

/// A Learn-mode mark: where to pierce and the ideal needle direction there.
struct Guide {
  Eigen::Vector3d target = Eigen::Vector3d::Zero();     ///< mm, scene frame
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  ///< unit, ideal needle tangent
};

struct Lesson {
  QString id;
  int version = 1;
  Text title;
  std::vector<Text> goals;
  std::vector<Step> steps;
  std::vector<Guide> guides;
  QString file;        ///< the lesson file (absolute)
  QString scenePath;   ///< absolute
  QString rubricPath;  ///< absolute
};

enum class LessonErrorKind {
  CannotOpen,    ///< the file could not be read
  NotJson,       ///< a JSON syntax error (offset says where)
  Missing,       ///< a required field is absent
  WrongType,     ///< a field has the wrong JSON type
  BadValue,      ///< a value is out of range or unknown (an id with spaces, a negative count)
  UnknownField,  ///< a field the format does not have (a typo would otherwise go unnoticed)
  MissingFile,   ///< the scene or rubric the lesson names does not exist
};

struct LessonError {
  LessonErrorKind kind = LessonErrorKind::CannotOpen;
  QString file;
  QString field;   ///< JSON path of the offending field; empty for the whole file
  int offset = -1; ///< byte offset of a syntax error, else -1
  QString detail;  ///< the JSON parser's message or the offending value, untranslated data
};

std::variant<Lesson, LessonError> loadLesson(const QString& path);

/// Every *.json lesson in `directory`, sorted by file name; files that fail go to `errors`.
std::vector<Lesson> loadLessons(const QString& directory, std::vector<LessonError>* errors = nullptr);

/// The shipped lessons folder, `lessons` in resourceDirectory() (lesson/resource_directory.h).
QString lessonsDirectory();

}  // namespace microsim::lesson
