#pragma once
// A trainee at the real window, for GUI tests that use the app as a person does: a fresh
// history, a new trainee signed in, a lesson opened in Learn mode; then key presses and left
// drags on the viewport made in small moves with the simulation stepping between them, each
// drag aimed again at where the thing dragged is drawn (look, drag, look again).
#include "gui/main_window.h"
#include "gui/pages/results_page.h"
#include "gui/simulation_runner.h"
#include "gui/viewport.h"

#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

#include "app/gui/core_profile.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

namespace microsim::testing {

struct LessonAtWindow {
  QTemporaryDir dir;
  assessment::HistoryDatabase history;
  std::unique_ptr<gui::MainWindow> window;
  gui::Viewport* view = nullptr;
  gui::AttemptPage* attempt = nullptr;

  /// Lesson `row` of the lesson list, opened in Learn mode by the trainee `trainee`.
  LessonAtWindow(int row, const QString& trainee) {
    QSettings().clear();
    gui::requestCoreProfile();
    const QString path = dir.filePath(QStringLiteral("history.sqlite"));
    const assessment::DatabaseStatus status = history.open(path);
    EXPECT_TRUE(status.ok());
    window = std::make_unique<gui::MainWindow>(&history, status, path);
    window->resize(1100, 760);
    window->show();
    EXPECT_TRUE(QTest::qWaitForWindowExposed(window.get()));
    auto* name = window->findChild<QLineEdit*>(QStringLiteral("newTraineeName"));
    QTest::mouseClick(name, Qt::LeftButton);
    QTest::keyClicks(name, trainee);
    QTest::mouseClick(window->findChild<QPushButton*>(QStringLiteral("createTraineeButton")), Qt::LeftButton);
    auto* lessons = window->findChild<QTableWidget*>(QStringLiteral("lessonTable"));
    QTest::mouseClick(lessons->viewport(), Qt::LeftButton, {}, lessons->visualItemRect(lessons->item(row, 0)).center());
    QTest::mouseClick(window->findChild<QPushButton*>(QStringLiteral("learnButton")), Qt::LeftButton);
    attempt = window->attemptPage();
    view = window->viewport();
    EXPECT_TRUE(attempt->isActive());
    EXPECT_TRUE(QTest::qWaitFor([this] { return attempt->runner()->steps() > 5 && view->drawnStep() > 5; }, 20000));
    view->setFocus();
  }

  /// The simulation takes `steps` steps and the viewport draws the result.
  void waitSteps(int steps = 3) {
    const int target = attempt->runner()->steps() + steps;
    EXPECT_TRUE(QTest::qWaitFor([&] { return view->drawnStep() >= target; }, 20000));
  }

  /// Where a scene point is drawn (pixels of the viewport).
  QPoint drawnAt(const Eigen::Vector3d& p) const {
    const gui::MicroscopeCamera& c = view->camera();
    const QMatrix4x4 m = c.projection(static_cast<float>(view->width()) / static_cast<float>(view->height())) * c.view();
    const QVector4D clip = m * QVector4D(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z()), 1.0f);
    return {qRound((clip.x() / clip.w() + 1.0f) * 0.5f * static_cast<float>(view->width())),
            qRound((1.0f - clip.y() / clip.w()) * 0.5f * static_cast<float>(view->height()))};
  }

  const sim::RenderSnapshot& drawn() const { return *view->drawnSnapshot(); }

  /// `key` pressed `times` times, the picture redrawn after each.
  void press(int key, int times = 1, Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
    for (int k = 0; k < times; ++k) {
      QTest::keyClick(view, static_cast<Qt::Key>(key), modifiers);
      waitSteps(2);
    }
  }

  /// A left drag from `from` by `by` pixels, in moves of at most 8 pixels with steps between.
  void drag(QPoint from, QPoint by) {
    QTest::mousePress(view, Qt::LeftButton, {}, from);
    const int moves = std::max(1, (std::max(std::abs(by.x()), std::abs(by.y())) + 7) / 8);
    for (int k = 1; k <= moves; ++k) {
      QTest::mouseMove(view, from + by * k / moves);
      waitSteps(1);
    }
    QTest::mouseRelease(view, Qt::LeftButton, {}, from + by);
    waitSteps();
  }

  /// Drags what is drawn at `grab()` (it moves with the active tool) until it is drawn within
  /// `near` pixels (Manhattan) of `to()`.
  void dragUntil(const std::function<QPoint()>& grab, const std::function<QPoint()>& to, int near = 1) {
    for (int tries = 0; tries < 8; ++tries) {
      const QPoint at = grab();
      const QPoint by = to() - at;
      if (by.manhattanLength() <= near) return;
      drag(at, by);
    }
    ADD_FAILURE() << "the tool never reached the place";
  }

  /// Finish attempt clicked; the result once scored.
  gui::AttemptResult finish() {
    QSignalSpy finished(attempt, &gui::AttemptPage::finished);
    QTest::mouseClick(window->findChild<QPushButton*>(QStringLiteral("finishButton")), Qt::LeftButton);
    EXPECT_TRUE(finished.count() > 0 || finished.wait(180000));
    return window->resultsPage()->result();
  }
};

}  // namespace microsim::testing
