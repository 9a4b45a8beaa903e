// Fuzz targets for the files a user or an instructor hands the app: rubrics, lessons and
// imported setup profiles.
#include "fuzz/fuzz_targets.h"

#include "lesson/lesson.h"
#include "microsim/assessment/scoring/rubric.h"
#include "microsim/assessment/storage/setup_profiles.h"

#include <QByteArray>
#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <string_view>
#include <variant>

namespace microsim::fuzz {

int fuzzRubric(const std::uint8_t* data, std::size_t size) {
  const auto result = assessment::parseRubric({reinterpret_cast<const char*>(data), size}, "fuzz.json");
  if (const auto* error = std::get_if<assessment::RubricError>(&result)) {
    if (error->line < 0 || error->column < 0) propertyBroken("rubric", "negative error position");
  }
  return 0;
}

int fuzzSetupProfile(const std::uint8_t* data, std::size_t size) {
  const QByteArray bytes(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
  const auto imported = assessment::importProfileJson(bytes);
  if (const auto* profile = std::get_if<assessment::SetupProfile>(&imported)) {
    // what imports exports again and imports to the same document
    const QByteArray exported = assessment::exportProfileJson(*profile);
    const auto again = assessment::importProfileJson(exported);
    const auto* second = std::get_if<assessment::SetupProfile>(&again);
    if (second == nullptr) propertyBroken("setup-profile", "an exported profile does not import");
    if (assessment::exportProfileJson(*second) != exported) {
      propertyBroken("setup-profile", "export/import round trip changed the profile");
    }
  }
  return 0;
}

int fuzzLesson(const std::uint8_t* data, std::size_t size) {
  // lessons are read from files (their scene and rubric resolve beside them), so the input
  // goes into a file in a folder of its own
  static const QTemporaryDir folder;
  const QString path = QDir(folder.path()).filePath(QStringLiteral("lesson.json"));
  QFile file(path);
  if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate)) return 0;
  file.write(reinterpret_cast<const char*>(data), static_cast<qint64>(size));
  file.close();
  const auto result = lesson::loadLesson(path);
  if (const auto* error = std::get_if<lesson::LessonError>(&result)) {
    if (error->offset > static_cast<int>(size)) propertyBroken("lesson", "error offset past the end");
  }
  return 0;
}

}  // namespace microsim::fuzz
