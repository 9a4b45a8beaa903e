// `microsim --check-start` run as a user would run it: the real program, under the suite's
// display, with its settings and history in a temporary folder.
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QProcessEnvironment>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace microsim::gui {
namespace {

struct StartCheckRun {
  int exitCode = -1;  ///< -1: did not finish in time or crashed
  QString out;
  QString err;
};

// starts the app with --check-start; `resources` (when given) is $MICROSIM_RESOURCES
StartCheckRun runStartCheck(const QTemporaryDir& home, const QString& database, const QString& resources = {}) {
  QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
  env.insert(QStringLiteral("LC_ALL"), QStringLiteral("C"));
  env.insert(QStringLiteral("LANG"), QStringLiteral("C"));
  env.insert(QStringLiteral("HOME"), home.path());
  env.insert(QStringLiteral("XDG_CONFIG_HOME"), home.filePath(QStringLiteral("config")));
  env.insert(QStringLiteral("XDG_DATA_HOME"), home.filePath(QStringLiteral("data")));
  // a runtime folder of its own, or Qt warns on stderr where it had none (CI under xvfb-run)
  const QString runtime = home.filePath(QStringLiteral("runtime"));
  QDir().mkpath(runtime);
  QFile::setPermissions(runtime, QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
  env.insert(QStringLiteral("XDG_RUNTIME_DIR"), runtime);
  env.remove(QStringLiteral("MICROSIM_RESOURCES"));
  if (!resources.isEmpty()) env.insert(QStringLiteral("MICROSIM_RESOURCES"), resources);
  QProcess app;
  app.setProcessEnvironment(env);
  app.start(QStringLiteral(MICROSIM_GUI_PATH), {QStringLiteral("--check-start"), QStringLiteral("--database"), database});
  StartCheckRun run;
  if (!app.waitForFinished(120000) || app.exitStatus() != QProcess::NormalExit) {
    app.kill();
    app.waitForFinished();
    return run;
  }
  run.exitCode = app.exitCode();
  run.out = QString::fromUtf8(app.readAllStandardOutput());
  run.err = QString::fromUtf8(app.readAllStandardError());
  return run;
}

// a resources folder whose scenes, rubrics and meshes are the shipped ones, with a copy of
// the shipped lessons that the test may spoil
QString startCheckResourcesCopy(const QTemporaryDir& dir) {
  const QDir shipped(QStringLiteral(MICROSIM_SOURCE_DIR "/resources"));
  const QDir copy(dir.filePath(QStringLiteral("resources")));
  copy.mkpath(QStringLiteral("lessons"));
  for (const QString& folder : {QStringLiteral("scenes"), QStringLiteral("rubrics"), QStringLiteral("meshes")})
    QFile::link(shipped.filePath(folder), copy.filePath(folder));
  for (const QString& lesson : QDir(shipped.filePath(QStringLiteral("lessons"))).entryList({QStringLiteral("*.json")}))
    QFile::copy(shipped.filePath(QStringLiteral("lessons/") + lesson), copy.filePath(QStringLiteral("lessons/") + lesson));
  return copy.path();
}

TEST(StartCheck, StartsWithTheShippedLessonsFoundThroughTheBuildTree) {
  QTemporaryDir home;
  const QString database = home.filePath(QStringLiteral("history.sqlite"));
  const StartCheckRun run = runStartCheck(home, database);
  ASSERT_EQ(run.exitCode, 0) << run.err.toStdString();
  EXPECT_TRUE(run.err.isEmpty()) << run.err.toStdString();
  // the six lessons, from <build dir>/share/microsim, which is the source tree's resources/
  const QString lessons = QFileInfo(QStringLiteral(MICROSIM_GUI_PATH)).dir().filePath(QStringLiteral("../share/microsim/lessons"));
  EXPECT_EQ(run.out.trimmed(), QStringLiteral("microsim started: 6 lesson(s) from %1, history %2")
                                   .arg(QDir::cleanPath(lessons), database));
  EXPECT_EQ(QFileInfo(lessons).canonicalFilePath(),
            QFileInfo(QStringLiteral(MICROSIM_SOURCE_DIR "/resources/lessons")).canonicalFilePath());
  // the history it was given was created, with every migration
  EXPECT_TRUE(QFileInfo(database).isFile());
}

TEST(StartCheck, FailsWithoutLessonsNamingTheFolder) {
  QTemporaryDir home;
  const QString empty = home.filePath(QStringLiteral("empty"));
  QDir().mkpath(empty);
  const StartCheckRun run = runStartCheck(home, home.filePath(QStringLiteral("history.sqlite")), empty);
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_EQ(run.err.trimmed(), QStringLiteral("microsim --check-start: no lesson files in %1/lessons").arg(empty));
  EXPECT_TRUE(run.out.isEmpty());
}

TEST(StartCheck, FailsWhenALessonCannotBeRead) {
  QTemporaryDir home;
  const QString resources = startCheckResourcesCopy(home);
  QFile broken(resources + QStringLiteral("/lessons/03_single_stitch.json"));
  ASSERT_TRUE(broken.open(QIODevice::WriteOnly | QIODevice::Truncate));
  broken.write("{\"id\": ");
  broken.close();

  const StartCheckRun run = runStartCheck(home, home.filePath(QStringLiteral("history.sqlite")), resources);
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_EQ(run.err.trimmed(),
            QStringLiteral("microsim --check-start: 5 of 6 lesson file(s) in %1/lessons could be read").arg(resources));
}

TEST(StartCheck, StartsFromACopiedResourcesFolder) {
  QTemporaryDir home;
  const QString resources = startCheckResourcesCopy(home);
  const StartCheckRun run = runStartCheck(home, home.filePath(QStringLiteral("history.sqlite")), resources);
  ASSERT_EQ(run.exitCode, 0) << run.err.toStdString();
  EXPECT_TRUE(run.out.startsWith(QStringLiteral("microsim started: 6 lesson(s) from %1/lessons,").arg(resources)))
      << run.out.toStdString();
}

TEST(StartCheck, FailsWhenTheHistoryCannotBeOpened) {
  QTemporaryDir home;
  // a file where the history's folder should be
  const QString blocker = home.filePath(QStringLiteral("blocker"));
  QFile file(blocker);
  ASSERT_TRUE(file.open(QIODevice::WriteOnly));
  file.close();
  const StartCheckRun run = runStartCheck(home, blocker + QStringLiteral("/history.sqlite"));
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_TRUE(run.err.contains(QStringLiteral("microsim --check-start: History unavailable: cannot create the folder for %1/history.sqlite").arg(blocker)))
      << run.err.toStdString();
}

}  // namespace
}  // namespace microsim::gui
