// What the attempt page says of Learn mode, at the real window: "follow the marks" where the
// lesson draws marks (lesson 2's entry targets), that the steps tick off where it draws none
// (the instrument tie, whose stitch is already placed).
#include <QLabel>

#include "app/gui/lesson_at_window.h"

#include <gtest/gtest.h>

namespace microsim::gui {
namespace {

QString learnModeLine(int row) {
  const testing::LessonAtWindow app(row, QStringLiteral("Mode Reader"));
  const auto* line = app.window->findChild<QLabel*>(QStringLiteral("attemptMode"));
  return line ? line->text() : QString();
}

TEST(AttemptPageMode, LearnModeSaysToFollowTheMarksOnlyWhereThereAreMarks) {
  EXPECT_EQ(learnModeLine(1), QStringLiteral("Learn mode: follow the marks."));  // 02 needle entry
  EXPECT_EQ(learnModeLine(2),
            QStringLiteral("Learn mode: each step is ticked off as you do it."));  // 02b
}

}  // namespace
}  // namespace microsim::gui
