#include "gui/pages/new_person_form.h"

#include "microsim/assessment/storage/people_store.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLineEdit>

namespace microsim::gui {

using assessment::Role;

NewPersonProblem checkNewPerson(Role role, const QString& name, const QString& password, const QString& repeat) {
  if (name.trimmed().isEmpty()) return NewPersonProblem::NoName;
  if (role == Role::Instructor) {
    if (password.size() < assessment::PeopleStore::kMinPasswordLength) return NewPersonProblem::PasswordTooShort;
    if (password != repeat) return NewPersonProblem::PasswordsDiffer;
  }
  return NewPersonProblem::None;
}

NewPersonForm::NewPersonForm(Role role, QWidget* parent) : QWidget(parent), role_(role) {
  name_ = new QLineEdit(this);
  name_->setObjectName(QStringLiteral("newPersonName"));
  auto* form = new QFormLayout(this);
  form->setContentsMargins(0, 0, 0, 0);
  form->addRow(tr("Name"), name_);
  // Return in the form's last field submits it
  if (role_ == Role::Trainee) {
    group_ = new QComboBox(this);
    group_->setObjectName(QStringLiteral("newPersonGroup"));
    group_->setEditable(true);
    group_->setInsertPolicy(QComboBox::NoInsert);
    group_->lineEdit()->setPlaceholderText(tr("none"));
    form->addRow(tr("Group"), group_);
    connect(group_->lineEdit(), &QLineEdit::returnPressed, this, &NewPersonForm::submitted);
  } else {
    password_ = new QLineEdit(this);
    password_->setObjectName(QStringLiteral("newPersonPassword"));
    password_->setEchoMode(QLineEdit::Password);
    password_->setPlaceholderText(tr("at least %n characters", nullptr, assessment::PeopleStore::kMinPasswordLength));
    repeat_ = new QLineEdit(this);
    repeat_->setObjectName(QStringLiteral("newPersonRepeat"));
    repeat_->setEchoMode(QLineEdit::Password);
    form->addRow(tr("Password"), password_);
    form->addRow(tr("Password again"), repeat_);
    connect(repeat_, &QLineEdit::returnPressed, this, &NewPersonForm::submitted);
  }
}

QString NewPersonForm::name() const { return name_->text().trimmed(); }
QString NewPersonForm::group() const { return group_ ? group_->currentText().trimmed() : QString(); }
QString NewPersonForm::password() const { return password_ ? password_->text() : QString(); }

NewPersonProblem NewPersonForm::problem() const {
  return checkNewPerson(role_, name_->text(), password(), repeat_ ? repeat_->text() : QString());
}

void NewPersonForm::setGroups(const QStringList& groups) {
  if (!group_) return;
  group_->clear();
  group_->addItems(groups);
  group_->setCurrentIndex(-1);
  group_->clearEditText();
}

void NewPersonForm::clear() {
  name_->clear();
  if (group_) group_->clearEditText();
  if (password_) password_->clear();
  if (repeat_) repeat_->clear();
}

QString NewPersonForm::describe(NewPersonProblem problem) {
  switch (problem) {
    case NewPersonProblem::None: return {};
    case NewPersonProblem::NoName: return tr("Type a name first.");
    case NewPersonProblem::PasswordTooShort:
      return tr("The password needs at least %n characters.", nullptr, assessment::PeopleStore::kMinPasswordLength);
    case NewPersonProblem::PasswordsDiffer: return tr("The two passwords differ; type them again.");
  }
  return {};
}

QString NewPersonForm::describe(const assessment::HistoryStatus& status, const QString& name) {
  switch (status.error) {
    case assessment::HistoryError::NameTaken: return tr("A person called %1 already exists.").arg(name);
    case assessment::HistoryError::Forbidden: return tr("An instructor has been set up meanwhile; sign in as them.");
    default: return tr("%1 could not be added (%2).").arg(name, status.driverMessage);
  }
}

}  // namespace microsim::gui
