#include "gui/pages/add_person_dialog.h"

#include "microsim/assessment/storage/people_store.h"

#include <QDialogButtonBox>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace microsim::gui {

using assessment::Role;

AddPersonDialog::AddPersonDialog(Role role, assessment::HistoryDatabase& history, QWidget* parent)
    : QDialog(parent), history_(history) {
  setWindowTitle(role == Role::Trainee ? tr("Add a trainee") : tr("Add an instructor"));
  form_ = new NewPersonForm(role, this);
  if (role == Role::Trainee) form_->setGroups(assessment::PeopleStore(history_).groups());
  message_ = new QLabel(this);
  message_->setObjectName(QStringLiteral("addPersonMessage"));
  message_->setStyleSheet(QStringLiteral("color: #b00020"));
  message_->setWordWrap(true);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
  add_ = buttons->addButton(tr("Add"), QDialogButtonBox::AcceptRole);
  add_->setObjectName(QStringLiteral("addPersonButton"));
  add_->setDefault(true);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(form_);
  layout->addWidget(message_);
  layout->addWidget(buttons);

  // "Add" stores first; the dialog closes only once the person is in the history
  connect(add_, &QPushButton::clicked, this, &AddPersonDialog::addPerson);
  connect(form_, &NewPersonForm::submitted, this, &AddPersonDialog::addPerson);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
}

QString AddPersonDialog::message() const { return message_->text(); }

void AddPersonDialog::addPerson() {
  if (const NewPersonProblem problem = form_->problem(); problem != NewPersonProblem::None) {
    message_->setText(NewPersonForm::describe(problem));
    return;
  }
  assessment::PeopleStore people(history_);
  added_ = form_->role() == Role::Trainee ? people.addTrainee(form_->name(), form_->group())
                                          : people.addInstructor(form_->name(), form_->password());
  if (!added_) {
    message_->setText(NewPersonForm::describe(people.lastError(), form_->name()));
    return;
  }
  accept();
}

}  // namespace microsim::gui
