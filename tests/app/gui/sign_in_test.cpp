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

// a history without instructors: the instructor's box offers to create the first one, checks
// what is typed, signs the new instructor in, and from then on offers the password sign-in
TEST(SignIn, FirstRunCreatesTheFirstInstructorWhoCanThenSignIn) {
  QTemporaryDir dir;
  assessment::HistoryDatabase history;
  ASSERT_TRUE(history.open(dir.filePath(QStringLiteral("first.sqlite"))).ok());
  history.setPasswordIterations(1000);
  ASSERT_TRUE(assessment::PeopleStore(history).addTrainee(QStringLiteral("A Trainee")).has_value());
  SignInPage page(&history);
  page.show();
  ASSERT_TRUE(page.offersFirstInstructor());
  auto* form = page.findChild<QWidget*>(QStringLiteral("firstInstructorForm"));
  ASSERT_NE(form, nullptr);
  EXPECT_TRUE(form->isVisible());
  EXPECT_FALSE(page.findChild<QLineEdit*>(QStringLiteral("instructorPassword"))->isVisible());

  QSignalSpy signedIn(&page, &SignInPage::signedIn);
  auto* name = page.findChild<QLineEdit*>(QStringLiteral("newPersonName"));
  auto* password = page.findChild<QLineEdit*>(QStringLiteral("newPersonPassword"));
  auto* repeat = page.findChild<QLineEdit*>(QStringLiteral("newPersonRepeat"));
  auto* create = page.findChild<QPushButton*>(QStringLiteral("createFirstInstructorButton"));
  auto* message = page.findChild<QLabel*>(QStringLiteral("signInMessage"));
  ASSERT_TRUE(name && password && repeat && create && message);

  // the two passwords must agree, and be long enough
  QTest::keyClicks(name, QStringLiteral("Dr Lee"));
  QTest::keyClicks(password, QStringLiteral("correct horse"));
  QTest::keyClicks(repeat, QStringLiteral("correct horsE"));
  QTest::mouseClick(create, Qt::LeftButton);
  EXPECT_EQ(signedIn.count(), 0);
  EXPECT_TRUE(message->text().contains(QStringLiteral("differ"))) << message->text().toStdString();
  password->setText(QStringLiteral("short"));
  repeat->setText(QStringLiteral("short"));
  QTest::mouseClick(create, Qt::LeftButton);
  EXPECT_EQ(signedIn.count(), 0);
  EXPECT_TRUE(message->text().contains(QStringLiteral("at least 8"))) << message->text().toStdString();
  EXPECT_FALSE(assessment::PeopleStore(history).verifyInstructor(QStringLiteral("Dr Lee"), QStringLiteral("short")));

  password->setText(QStringLiteral("correct horse"));
  repeat->setText(QStringLiteral("correct horse"));
  QTest::keyClick(repeat, Qt::Key_Return);
  ASSERT_EQ(signedIn.count(), 1);
  const auto viewer = signedIn.at(0).at(0).value<assessment::Viewer>();
  EXPECT_EQ(viewer.role, assessment::Role::Instructor);
  EXPECT_EQ(signedIn.at(0).at(1).toString(), QStringLiteral("Dr Lee"));
  EXPECT_FALSE(page.offersFirstInstructor());
  EXPECT_TRUE(password->text().isEmpty()) << "the password is not kept";

  // signed out and back: the password sign-in, with the password just set
  SignInPage again(&history);
  again.show();
  EXPECT_FALSE(again.offersFirstInstructor());
  QSignalSpy signedInAgain(&again, &SignInPage::signedIn);
  QTest::keyClicks(again.findChild<QLineEdit*>(QStringLiteral("instructorName")), QStringLiteral("Dr Lee"));
  QTest::keyClicks(again.findChild<QLineEdit*>(QStringLiteral("instructorPassword")), QStringLiteral("correct horse"));
  QTest::mouseClick(again.findChild<QPushButton*>(QStringLiteral("instructorSignInButton")), Qt::LeftButton);
  ASSERT_EQ(signedInAgain.count(), 1);
  EXPECT_EQ(signedInAgain.at(0).at(0).value<assessment::Viewer>().userId, viewer.userId);
}

TEST(SignIn, AHistoryWithAnInstructorOffersNoFirstRun) {
  Page p;
  EXPECT_FALSE(p.page->offersFirstInstructor());
  EXPECT_TRUE(p.child<QLineEdit>("instructorPassword")->isVisible());
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
