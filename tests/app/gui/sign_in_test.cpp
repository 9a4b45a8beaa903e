#include "gui/main_window.h"
#include "gui/pages/lesson_list_page.h"
#include "gui/pages/sign_in_page.h"

#include "microsim/assessment/storage/people_store.h"

#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

namespace microsim::gui {
namespace {

struct Page {
  QTemporaryDir dir;
  assessment::HistoryDatabase history;
  std::unique_ptr<SignInPage> page;

  Page() {
    EXPECT_TRUE(history.open(dir.filePath(QStringLiteral("h.sqlite"))).ok());
    history.setPasswordIterations(1000);
    EXPECT_TRUE(assessment::PeopleStore(history).addTrainee(QStringLiteral("Existing Trainee")).has_value());
    EXPECT_TRUE(assessment::PeopleStore(history).addInstructor(QStringLiteral("Dr Who"), QStringLiteral("correct horse")).has_value());
    page = std::make_unique<SignInPage>(&history);
    page->show();
  }
  template <typename T>
  T* child(const char* name) const {
    T* w = page->findChild<T*>(QString::fromLatin1(name));
    EXPECT_NE(w, nullptr) << name;
    return w;
  }
};

TEST(SignIn, ListsTraineesButNotInstructors) {
  Page p;
  auto* list = p.child<QListWidget>("traineeList");
  ASSERT_EQ(list->count(), 1);
  EXPECT_EQ(list->item(0)->text(), QStringLiteral("Existing Trainee"));
}

TEST(SignIn, PicksAnExistingTrainee) {
  Page p;
  QSignalSpy signedIn(p.page.get(), &SignInPage::signedIn);
  auto* list = p.child<QListWidget>("traineeList");
  QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, list->visualItemRect(list->item(0)).center());
  QTest::mouseClick(p.child<QPushButton>("signInButton"), Qt::LeftButton);
  ASSERT_EQ(signedIn.count(), 1);
  const auto viewer = signedIn.at(0).at(0).value<assessment::Viewer>();
  EXPECT_EQ(viewer.role, assessment::Role::Trainee);
  EXPECT_EQ(signedIn.at(0).at(1).toString(), QStringLiteral("Existing Trainee"));
}

TEST(SignIn, CreatingATakenNameSaysSoAndSignsNobodyIn) {
  Page p;
  QSignalSpy signedIn(p.page.get(), &SignInPage::signedIn);
  QTest::keyClicks(p.child<QLineEdit>("newTraineeName"), QStringLiteral("Existing Trainee"));
  QTest::mouseClick(p.child<QPushButton>("createTraineeButton"), Qt::LeftButton);
  EXPECT_EQ(signedIn.count(), 0);
  EXPECT_TRUE(p.child<QLabel>("signInMessage")->text().contains(QStringLiteral("already exists")));
  EXPECT_EQ(assessment::PeopleStore(p.history).trainees().size(), 2);
}

TEST(SignIn, InstructorNeedsTheRightPassword) {
  Page p;
  QSignalSpy signedIn(p.page.get(), &SignInPage::signedIn);
  QTest::keyClicks(p.child<QLineEdit>("instructorName"), QStringLiteral("Dr Who"));
  QTest::keyClicks(p.child<QLineEdit>("instructorPassword"), QStringLiteral("wrong password"));
  QTest::mouseClick(p.child<QPushButton>("instructorSignInButton"), Qt::LeftButton);
  EXPECT_EQ(signedIn.count(), 0);
  EXPECT_FALSE(p.child<QLabel>("signInMessage")->text().isEmpty());
  EXPECT_TRUE(p.child<QLineEdit>("instructorPassword")->text().isEmpty()) << "the password is not kept";

  QTest::keyClicks(p.child<QLineEdit>("instructorPassword"), QStringLiteral("correct horse"));
  QTest::keyClick(p.child<QLineEdit>("instructorPassword"), Qt::Key_Return);
  ASSERT_EQ(signedIn.count(), 1);
  EXPECT_EQ(signedIn.at(0).at(0).value<assessment::Viewer>().role, assessment::Role::Instructor);
}

TEST(SignIn, WithoutAHistoryOffersAGuest) {
  assessment::HistoryDatabase closed;
  SignInPage page(&closed);
  auto* list = page.findChild<QListWidget*>(QStringLiteral("traineeList"));
  ASSERT_EQ(list->count(), 1);
  QSignalSpy signedIn(&page, &SignInPage::signedIn);
  QTest::mouseClick(page.findChild<QPushButton*>(QStringLiteral("signInButton")), Qt::LeftButton);
  ASSERT_EQ(signedIn.count(), 1);
  EXPECT_EQ(signedIn.at(0).at(0).value<assessment::Viewer>().userId, 0);
}

}  // namespace
}  // namespace microsim::gui
