// What the attempt page says of Learn mode, at the real window: "follow the marks" where the
// lesson draws marks (lesson 2's entry targets), that the steps tick off where it draws none
// (the instrument tie, whose stitch is already placed); and the whole line is shown, not cut
// off at the side panel's edge.
#include <QLabel>

#include "app/gui/lesson_at_window.h"

#include <gtest/gtest.h>

namespace microsim::gui {
namespace {

struct ModeLine {
  QString text;
  bool shownWhole = false;
};

ModeLine learnModeLine(int row) {
  const testing::LessonAtWindow app(row, QStringLiteral("Mode Reader"));
  const auto* line = app.window->findChild<QLabel*>(QStringLiteral("attemptMode"));
  if (!line) return {};
  // wrapped, its lines fit the label's height; on one line, the text fits its width
  const bool whole = line->wordWrap() ? line->heightForWidth(line->width()) <= line->height()
                                      : line->fontMetrics().horizontalAdvance(line->text()) <=
                                            line->contentsRect().width();
  return {line->text(), whole};
}

TEST(AttemptPageMode, LearnModeSaysToFollowTheMarksOnlyWhereThereAreMarks) {
  const ModeLine entry = learnModeLine(1);  // 02 needle entry
  EXPECT_EQ(entry.text, QStringLiteral("Learn mode: follow the marks."));
  EXPECT_TRUE(entry.shownWhole);
  const ModeLine tie = learnModeLine(2);  // 02b
  EXPECT_EQ(tie.text, QStringLiteral("Learn mode: each step is ticked off as you do it."));
  EXPECT_TRUE(tie.shownWhole) << "cut off at the side panel's edge";
}

}  // namespace
}  // namespace microsim::gui
