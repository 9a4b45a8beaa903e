#pragma once
// Sign-in: pick a trainee from the history or create one; instructors sign in with their
// password (checked by PeopleStore::verifyInstructor). In a history without any instructor
// the instructor's box offers to create the first one instead (name, password twice;
// PeopleStore::addFirstInstructor refuses once one exists), who is then signed in. Without a
// usable history the page says so and offers a guest session (nothing is stored).

#include "microsim/assessment/storage/history_database.h"

#include <QWidget>

class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;
class QStackedWidget;

namespace microsim::gui {

class NewPersonForm;

class SignInPage : public QWidget {
  Q_OBJECT

 public:
  explicit SignInPage(assessment::HistoryDatabase* history, QWidget* parent = nullptr);

  /// Re-reads the trainees from the history.
  void refresh();
  /// True while the page offers to create the first instructor (the history has none).
  bool offersFirstInstructor() const;

 Q_SIGNALS:
  /// A person signed in; `viewer.userId` is 0 for a guest without history.
  void signedIn(const microsim::assessment::Viewer& viewer, const QString& name);

 private:
  void signInSelected();
  void createTrainee();
  void signInInstructor();
  void createFirstInstructor();
  void showError(const QString& text);

  assessment::HistoryDatabase* history_;
  QListWidget* trainees_ = nullptr;
  QPushButton* signIn_ = nullptr;
  QLineEdit* newName_ = nullptr;
  QLineEdit* instructorName_ = nullptr;
  QLineEdit* password_ = nullptr;
  QStackedWidget* instructorStack_ = nullptr;
  NewPersonForm* firstInstructor_ = nullptr;
  QLabel* message_ = nullptr;
};

}  // namespace microsim::gui
