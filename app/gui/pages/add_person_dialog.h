#pragma once
// An instructor adds a trainee (name, group) or another instructor (name, password twice)
// to the history (the People menu). The person is stored when "Add" is pressed and what was
// typed is valid; otherwise the dialog says why and stays open.

#include "gui/pages/new_person_form.h"

#include <QDialog>

#include <optional>

class QLabel;
class QPushButton;

namespace microsim::gui {

class AddPersonDialog : public QDialog {
  Q_OBJECT

 public:
  /// `history` must be open and outlive the dialog.
  AddPersonDialog(assessment::Role role, assessment::HistoryDatabase& history, QWidget* parent = nullptr);

  NewPersonForm* form() const { return form_; }
  QPushButton* addButton() const { return add_; }
  /// The message shown under the form (why the person was not added).
  QString message() const;
  /// The person added, once the dialog was accepted.
  std::optional<qint64> addedId() const { return added_; }
  QString addedName() const { return form_->name(); }

 private:
  void addPerson();

  assessment::HistoryDatabase& history_;
  NewPersonForm* form_ = nullptr;
  QLabel* message_ = nullptr;
  QPushButton* add_ = nullptr;
  std::optional<qint64> added_;
};

}  // namespace microsim::gui
