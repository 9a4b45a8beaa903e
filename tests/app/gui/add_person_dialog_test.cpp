// Instructors add trainees and instructors from the GUI: the People menu is theirs only, and
// its dialog stores what it checked in a real temporary SQLite history.
#include "gui/main_window.h"
#include "gui/pages/add_person_dialog.h"
#include "gui/pages/lesson_list_page.h"
#include "gui/pages/new_person_form.h"
#include "gui/pages/sign_in_page.h"
#include "support/instructor_history.h"

#include "microsim/assessment/storage/people_store.h"

#include <QComboBox>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QTest>

#include "app/gui/core_profile.h"

#include <gtest/gtest.h>

namespace microsim::gui {
namespace {

using assessment::Role;

class AddPeople : public testing::InstructorHistoryTest {
 protected:
  void SetUp() override {
    InstructorHistoryTest::SetUp();
    ASSERT_TRUE(assessment::PeopleStore(history_).addTrainee(QStringLiteral("Ana"), QStringLiteral("Tuesday")));
  }
};

TEST_F(AddPeople, ThePeopleMenuIsForSignedInInstructors) {
  requestCoreProfile();
  MainWindow window(&history_, {}, historyPath());
  auto* addTrainee = window.findChild<QAction*>(QStringLiteral("addTraineeAction"));
  auto* addInstructor = window.findChild<QAction*>(QStringLiteral("addInstructorAction"));
  ASSERT_TRUE(addTrainee && addInstructor);
  EXPECT_FALSE(addTrainee->isEnabled());
  EXPECT_FALSE(addInstructor->isEnabled());

  // a trainee signs in: still closed to them
  auto* list = window.findChild<QListWidget*>(QStringLiteral("traineeList"));
  list->setCurrentRow(0);
  window.findChild<QPushButton*>(QStringLiteral("signInButton"))->click();
  ASSERT_EQ(window.currentPage(), window.lessonListPage());
  EXPECT_FALSE(addTrainee->isEnabled());
  window.findChild<QPushButton*>(QStringLiteral("signOutButton"))->click();

  // an instructor signs in: open; signed out: closed again
  window.findChild<QLineEdit*>(QStringLiteral("instructorName"))->setText(testing::kTestInstructor);
  window.findChild<QLineEdit*>(QStringLiteral("instructorPassword"))->setText(testing::kTestInstructorPassword);
  window.findChild<QPushButton*>(QStringLiteral("instructorSignInButton"))->click();
  ASSERT_NE(window.reviewPage(), nullptr);
  EXPECT_TRUE(addTrainee->isEnabled());
  EXPECT_TRUE(addInstructor->isEnabled());
}

TEST_F(AddPeople, AddsATraineeInAGroup) {
  AddPersonDialog dialog(Role::Trainee, history_);
  dialog.show();
  EXPECT_EQ(dialog.findChild<QLineEdit*>(QStringLiteral("newPersonPassword")), nullptr) << "trainees have no password";
  auto* group = dialog.findChild<QComboBox*>(QStringLiteral("newPersonGroup"));
  ASSERT_NE(group, nullptr);
  EXPECT_EQ(group->findText(QStringLiteral("Tuesday")), 0) << "the existing groups are offered";

  // a taken name is refused and the dialog stays open
  QTest::keyClicks(dialog.findChild<QLineEdit*>(QStringLiteral("newPersonName")), QStringLiteral("Ana"));
  QTest::mouseClick(dialog.addButton(), Qt::LeftButton);
  EXPECT_FALSE(dialog.addedId());
  EXPECT_TRUE(dialog.message().contains(QStringLiteral("already exists"))) << dialog.message().toStdString();
  EXPECT_EQ(dialog.result(), QDialog::Rejected);

  dialog.findChild<QLineEdit*>(QStringLiteral("newPersonName"))->setText(QStringLiteral("Carla"));
  group->setEditText(QStringLiteral("Friday"));
  QTest::mouseClick(dialog.addButton(), Qt::LeftButton);
  ASSERT_TRUE(dialog.addedId());
  EXPECT_EQ(dialog.result(), QDialog::Accepted);
  const std::optional<assessment::Trainee> carla = assessment::PeopleStore(history_).person(*dialog.addedId());
  ASSERT_TRUE(carla);
  EXPECT_EQ(carla->name, QStringLiteral("Carla"));
  EXPECT_EQ(carla->role, Role::Trainee);
  EXPECT_EQ(carla->group, QStringLiteral("Friday"));

  // she can sign in from the list
  SignInPage signIn(&history_);
  auto* list = signIn.findChild<QListWidget*>(QStringLiteral("traineeList"));
  EXPECT_EQ(list->findItems(QStringLiteral("Carla (Friday)"), Qt::MatchExactly).size(), 1);
}

TEST_F(AddPeople, AddsAnInstructorWithAPasswordTypedTwice) {
  AddPersonDialog dialog(Role::Instructor, history_);
  dialog.show();
  auto* name = dialog.findChild<QLineEdit*>(QStringLiteral("newPersonName"));
  auto* password = dialog.findChild<QLineEdit*>(QStringLiteral("newPersonPassword"));
  auto* repeat = dialog.findChild<QLineEdit*>(QStringLiteral("newPersonRepeat"));
  ASSERT_TRUE(name && password && repeat);

  QTest::mouseClick(dialog.addButton(), Qt::LeftButton);
  EXPECT_EQ(dialog.message(), NewPersonForm::describe(NewPersonProblem::NoName));
  name->setText(QStringLiteral("Dr Park"));
  password->setText(QStringLiteral("open sesame"));
  repeat->setText(QStringLiteral("open sesame!"));
  QTest::mouseClick(dialog.addButton(), Qt::LeftButton);
  EXPECT_EQ(dialog.message(), NewPersonForm::describe(NewPersonProblem::PasswordsDiffer));
  EXPECT_FALSE(dialog.addedId());

  repeat->setText(QStringLiteral("open sesame"));
  QTest::mouseClick(dialog.addButton(), Qt::LeftButton);
  ASSERT_TRUE(dialog.addedId());
  EXPECT_EQ(assessment::PeopleStore(history_).verifyInstructor(QStringLiteral("Dr Park"), QStringLiteral("open sesame")),
            dialog.addedId());
}

TEST(NewPersonCheck, NamesAndPasswords) {
  EXPECT_EQ(checkNewPerson(Role::Trainee, QStringLiteral("  "), {}, {}), NewPersonProblem::NoName);
  EXPECT_EQ(checkNewPerson(Role::Trainee, QStringLiteral("Ana"), {}, {}), NewPersonProblem::None);
  EXPECT_EQ(checkNewPerson(Role::Instructor, QStringLiteral("Lee"), QStringLiteral("1234567"), QStringLiteral("1234567")),
            NewPersonProblem::PasswordTooShort);
  EXPECT_EQ(checkNewPerson(Role::Instructor, QStringLiteral("Lee"), QStringLiteral("12345678"), QStringLiteral("12345679")),
            NewPersonProblem::PasswordsDiffer);
  EXPECT_EQ(checkNewPerson(Role::Instructor, QStringLiteral("Lee"), QStringLiteral("12345678"), QStringLiteral("12345678")),
            NewPersonProblem::None);
}

}  // namespace
}  // namespace microsim::gui
