#pragma once
// A GUI test's history: a real SQLite file in a temporary folder, fast password hashing (the
// tests check behaviour, not the hash's cost) and one instructor, Dr Grey, whom the tests
// sign in as. A fixture derives from it and adds its own people in its own SetUp, after
// calling this one.
#include "microsim/assessment/storage/history_database.h"
#include "microsim/assessment/storage/people_store.h"

#include <QString>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace microsim::testing {

inline const QString kTestInstructor = QStringLiteral("Dr Grey");
inline const QString kTestInstructorPassword = QStringLiteral("correct horse");

class InstructorHistoryTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(dir_.isValid());
    history_.setPasswordIterations(1000);
    ASSERT_TRUE(history_.open(historyPath()).ok());
    instructor_ = assessment::PeopleStore(history_).addInstructor(kTestInstructor, kTestInstructorPassword).value_or(0);
    ASSERT_NE(instructor_, 0);
  }

  QString historyPath() const { return dir_.filePath(QStringLiteral("history.sqlite")); }

  QTemporaryDir dir_;
  assessment::HistoryDatabase history_;
  qint64 instructor_ = 0;
};

}  // namespace microsim::testing
