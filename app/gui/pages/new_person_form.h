#pragma once
// The fields that make a person in the history: a name; for a trainee an optional group
// (an existing one or a new one); for an instructor a password typed twice. The sign-in
// page's first-run instructor and the instructors' "Add a person" dialog both use it.
// It checks what was typed (checkNewPerson); the caller stores it through PeopleStore, which
// checks again (a name already taken, a password too short).

#include "microsim/assessment/storage/history_database.h"

#include <QStringList>
#include <QWidget>

class QComboBox;
class QLineEdit;

namespace microsim::gui {

enum class NewPersonProblem {
  None,
  NoName,            ///< the name is empty (spaces only)
  PasswordTooShort,  ///< fewer than PeopleStore::kMinPasswordLength characters
  PasswordsDiffer,   ///< the repeated password is not the same
};

/// What is wrong with a new person of `role` (the passwords matter for instructors only).
NewPersonProblem checkNewPerson(assessment::Role role, const QString& name, const QString& password,
                                const QString& repeat);

class NewPersonForm : public QWidget {
  Q_OBJECT

 public:
  explicit NewPersonForm(assessment::Role role, QWidget* parent = nullptr);

  assessment::Role role() const { return role_; }
  /// The name as typed, without surrounding spaces.
  QString name() const;
  /// The group typed or chosen (trainees; empty: none).
  QString group() const;
  QString password() const;
  /// The problem with what is typed; None when it can be stored.
  NewPersonProblem problem() const;
  /// Groups offered in the group box (trainees).
  void setGroups(const QStringList& groups);
  /// Empties every field.
  void clear();

  /// A sentence for a problem with what was typed.
  static QString describe(NewPersonProblem problem);
  /// A sentence for a store's refusal to add `name`.
  static QString describe(const assessment::HistoryStatus& status, const QString& name);

 Q_SIGNALS:
  /// Return was pressed in the last field.
  void submitted();

 private:
  assessment::Role role_;
  QLineEdit* name_ = nullptr;
  QComboBox* group_ = nullptr;
  QLineEdit* password_ = nullptr;
  QLineEdit* repeat_ = nullptr;
};

}  // namespace microsim::gui
