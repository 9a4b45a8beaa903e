#include "lesson/resource_directory.h"

#include "lesson/lesson.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

#include <gtest/gtest.h>

namespace microsim::lesson {
namespace {

TEST(ResourceDirectory, InstalledProgramsReadShareMicrosimBesideTheirFolder) {
  EXPECT_EQ(resourceDirectoryFor({}, QStringLiteral("/usr/bin")), QStringLiteral("/usr/share/microsim"));
  EXPECT_EQ(resourceDirectoryFor({}, QStringLiteral("/tmp/root/opt/microsim/bin/")),
            QStringLiteral("/tmp/root/opt/microsim/share/microsim"));
}

TEST(ResourceDirectory, AnOverrideWinsAsGiven) {
  EXPECT_EQ(resourceDirectoryFor(QStringLiteral("/srv/lab/resources"), QStringLiteral("/usr/bin")),
            QStringLiteral("/srv/lab/resources"));
  EXPECT_EQ(resourceDirectoryFor(QStringLiteral("relative/res"), QStringLiteral("/usr/bin")), QStringLiteral("relative/res"));
}

TEST(ResourceDirectory, TheBuildTreeLeadsToTheSourcesResources) {
  // this test program lives in <build dir>/tests, the programs in <build dir>/app: both reach
  // the source tree's resources/ through <build dir>/share/microsim
  const QString found = resourceDirectoryFor({}, QCoreApplication::applicationDirPath());
  EXPECT_EQ(QFileInfo(found).canonicalFilePath(),
            QFileInfo(QStringLiteral(MICROSIM_SOURCE_DIR "/resources")).canonicalFilePath());
  EXPECT_EQ(loadLessons(QDir(found).filePath(QStringLiteral("lessons"))).size(), 6u);
}

}  // namespace
}  // namespace microsim::lesson
