#include "gui/screenshots.h"

#include "gui/main_window.h"
#include "gui/pages/lesson_list_page.h"
#include "gui/pages/results_page.h"
#include "gui/pages/sign_in_page.h"
#include "gui/review/review_screenshots.h"
#include "gui/settings/settings_dialog.h"
#include "gui/simulation_runner.h"
#include "gui/viewport.h"

#include "microsim/assessment/storage/people_store.h"
#include "microsim/sim/scene/recording.h"

#include <QApplication>
#include <QDir>
#include <QEventLoop>
#include <QFileInfo>
#include <QListWidget>
#include <QPixmap>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTimer>

#include <tuple>

namespace microsim::gui {

namespace {

// Waits for one firing of `signal` of `sender`, armed before the action that makes it fire: a
// replay runs on its own thread and may finish before a wait begun after it could connect (it
// did, while the viewport built a smooth tissue surface for the new scene).
template <typename Sender, typename Signal>
class SignalWait {
 public:
  SignalWait(Sender* sender, Signal signal) {
    QObject::connect(sender, signal, &loop_, [this] {
      fired_ = true;
      loop_.quit();
    });
  }
  // runs the event loop until the signal has fired, or a generous deadline passes
  bool wait(int timeoutMs = 30000) {
    if (fired_) return true;
    QTimer::singleShot(timeoutMs, &loop_, &QEventLoop::quit);
    loop_.exec();
    return fired_;
  }

 private:
  QEventLoop loop_;
  bool fired_ = false;
};

template <typename Sender, typename Signal>
bool waitFor(Sender* sender, Signal signal, int timeoutMs = 30000) {
  SignalWait<Sender, Signal> fired(sender, signal);
  return fired.wait(timeoutMs);
}

// lets pending layout and paint events run
void settle() {
  for (int i = 0; i < 5; ++i) QApplication::processEvents();
}

bool saveScreenShot(QWidget& widget, const QString& file, QStringList& written, const ScreenInspector& inspect) {
  settle();
  if (inspect) inspect(QFileInfo(file).fileName(), widget);
  if (!widget.grab().save(file)) return false;
  written << file;
  return true;
}

}  // namespace

QStringList writeScreenshots(const QString& directory, QString* error, int width, int height,
                             const ScreenInspector& inspect) {
  auto fail = [error](const QString& why) {
    if (error) *error = why;
    return QStringList();
  };
  if (!QDir().mkpath(directory)) return fail(QApplication::translate("main", "cannot create %1").arg(directory));
  const QDir out(directory);
  QTemporaryDir scratch;
  assessment::HistoryDatabase history;
  const QString path = scratch.filePath(QStringLiteral("history.sqlite"));
  const assessment::DatabaseStatus status = history.open(path);
  if (!status.ok()) return fail(status.driverMessage);
  for (const QString& name : {QStringLiteral("Alex Demo"), QStringLiteral("Maria Beispiel"), QStringLiteral("Sam Ejemplo")})
    assessment::PeopleStore(history).addTrainee(name, QStringLiteral("Residents 2026"));

  MainWindow window(&history, status, path);
  window.resize(width, height);
  window.show();
  QStringList written;

  // sign-in, then the lessons of the first trainee
  if (!saveScreenShot(window, out.filePath(QStringLiteral("sign-in.png")), written, inspect)) return fail(QStringLiteral("sign-in"));
  auto* list = window.signInPage()->findChild<QListWidget*>(QStringLiteral("traineeList"));
  list->setCurrentRow(0);
  window.signInPage()->findChild<QPushButton*>(QStringLiteral("signInButton"))->click();
  window.lessonListPage()->selectRow(1);
  if (!window.lessonListPage()->statusesLoaded()) waitFor(window.lessonListPage(), &LessonListPage::statusesShown);
  if (!saveScreenShot(window, out.filePath(QStringLiteral("lessons.png")), written, inspect)) return fail(QStringLiteral("lessons"));

  // lesson 2 in Learn mode, the shipped stitch replayed up to the first pierce
  sim::Recording stitch;
  const QString recording = QDir(lesson::lessonsDirectory()).filePath(QStringLiteral("../recordings/stitch.msrec"));
  if (!sim::readRecording(recording.toStdString(), stitch).ok()) return fail(recording);
  if (!window.startLesson(1, assessment::AttemptMode::Learn)) return fail(QStringLiteral("lesson 2"));
  AttemptPage* attempt = window.attemptPage();
  std::vector<sim::InputFrame> part(stitch.frames.begin(), stitch.frames.begin() + std::min<std::ptrdiff_t>(130, std::ssize(stitch.frames)));
  SignalWait replayed(attempt->runner(), &SimulationRunner::replayFinished);
  attempt->replay(std::move(part), false);
  if (!replayed.wait()) return fail(QStringLiteral("replay"));
  const int frames = window.viewport()->framesDrawn();
  window.viewport()->update();
  if (window.viewport()->framesDrawn() == frames) waitFor(window.viewport(), &Viewport::frameDrawn, 10000);
  if (!saveScreenShot(window, out.filePath(QStringLiteral("attempt-learn.png")), written, inspect)) return fail(QStringLiteral("attempt"));

  // the microscope's picture alone, with its depth of field (a GPU's default): from straight
  // above, and from the oblique view turned 40° about the table so the cut ends face the eye
  // and the lumen shows
  const bool focus = window.viewport()->depthOfField();
  window.viewport()->setDepthOfField(true);
  for (const auto& [view, yaw, name] : {std::tuple{NamedView::Top, 0.0f, QStringLiteral("microscope-top.png")},
                                        std::tuple{NamedView::Oblique, 40.0f, QStringLiteral("microscope-oblique.png")}}) {
    window.viewport()->showView(view);
    window.viewport()->camera().orbit(yaw, 0.0f);
    window.viewport()->cameraChanged();
    if (!saveScreenShot(*window.viewport(), out.filePath(name), written, inspect)) return fail(name);
  }
  window.viewport()->showView(NamedView::Microscope);
  window.viewport()->setDepthOfField(focus);

  // the whole stitch, scored
  SignalWait scored(attempt, &AttemptPage::finished);
  attempt->replay(stitch.frames, true);
  if (!scored.wait(120000)) return fail(QStringLiteral("results"));
  if (!saveScreenShot(window, out.filePath(QStringLiteral("results.png")), written, inspect)) return fail(QStringLiteral("results"));

  // the settings dialog
  settings::SettingsDialog dialog(&window);
  dialog.show();
  if (!saveScreenShot(dialog, out.filePath(QStringLiteral("settings.png")), written, inspect)) return fail(QStringLiteral("settings"));
  dialog.close();
  window.close();

  // the instructor's review, on demo data of its own
  const QStringList review = writeReviewScreenshots(directory, inspect);
  if (review.isEmpty()) return fail(QStringLiteral("review"));
  written += review;
  return written;
}

}  // namespace microsim::gui
