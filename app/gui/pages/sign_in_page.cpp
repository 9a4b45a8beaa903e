#include "gui/pages/sign_in_page.h"

#include "microsim/assessment/storage/people_store.h"

#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

namespace microsim::gui {

using assessment::HistoryError;
using assessment::Role;

SignInPage::SignInPage(assessment::HistoryDatabase* history, QWidget* parent)
    : QWidget(parent), history_(history) {
  setObjectName(QStringLiteral("signInPage"));
  auto* heading = new QLabel(tr("<h2>Who is practising?</h2>"), this);

  // trainees
  auto* traineeBox = new QGroupBox(tr("Trainee"), this);
  trainees_ = new QListWidget(traineeBox);
  trainees_->setObjectName(QStringLiteral("traineeList"));
  signIn_ = new QPushButton(tr("Sign in"), traineeBox);
  signIn_->setObjectName(QStringLiteral("signInButton"));
  signIn_->setDefault(true);
  newName_ = new QLineEdit(traineeBox);
  newName_->setObjectName(QStringLiteral("newTraineeName"));
  newName_->setPlaceholderText(tr("Your name"));
  auto* create = new QPushButton(tr("Create and sign in"), traineeBox);
  create->setObjectName(QStringLiteral("createTraineeButton"));
  auto* newRow = new QHBoxLayout;
  newRow->addWidget(newName_, 1);
  newRow->addWidget(create);
  auto* traineeLayout = new QVBoxLayout(traineeBox);
  traineeLayout->addWidget(trainees_, 1);
  traineeLayout->addWidget(signIn_);
  traineeLayout->addWidget(new QLabel(tr("New trainee:"), traineeBox));
  traineeLayout->addLayout(newRow);

  // instructors
  auto* instructorBox = new QGroupBox(tr("Instructor"), this);
  instructorName_ = new QLineEdit(instructorBox);
  instructorName_->setObjectName(QStringLiteral("instructorName"));
  password_ = new QLineEdit(instructorBox);
  password_->setObjectName(QStringLiteral("instructorPassword"));
  password_->setEchoMode(QLineEdit::Password);
  auto* instructorSignIn = new QPushButton(tr("Sign in as instructor"), instructorBox);
  instructorSignIn->setObjectName(QStringLiteral("instructorSignInButton"));
  auto* form = new QFormLayout(instructorBox);
  form->addRow(tr("Name"), instructorName_);
  form->addRow(tr("Password"), password_);
  form->addRow(instructorSignIn);

  message_ = new QLabel(this);
  message_->setObjectName(QStringLiteral("signInMessage"));
  message_->setStyleSheet(QStringLiteral("color: #b00020"));
  message_->setWordWrap(true);

  auto* boxes = new QHBoxLayout;
  boxes->addWidget(traineeBox, 3);
  boxes->addWidget(instructorBox, 2, Qt::AlignTop);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(heading);
  layout->addLayout(boxes, 1);
  layout->addWidget(message_);

  connect(signIn_, &QPushButton::clicked, this, &SignInPage::signInSelected);
  connect(trainees_, &QListWidget::itemDoubleClicked, this, &SignInPage::signInSelected);
  connect(trainees_, &QListWidget::currentRowChanged, this, [this](int row) { signIn_->setEnabled(row >= 0); });
  connect(create, &QPushButton::clicked, this, &SignInPage::createTrainee);
  connect(newName_, &QLineEdit::returnPressed, this, &SignInPage::createTrainee);
  connect(instructorSignIn, &QPushButton::clicked, this, &SignInPage::signInInstructor);
  connect(password_, &QLineEdit::returnPressed, this, &SignInPage::signInInstructor);
  refresh();
}

void SignInPage::refresh() {
  trainees_->clear();
  message_->clear();
  password_->clear();
  if (!history_ || !history_->isOpen()) {
    showError(tr("The history is unavailable: you can practise, but nothing will be stored."));
    auto* guest = new QListWidgetItem(tr("Guest"), trainees_);
    guest->setData(Qt::UserRole, 0);
    trainees_->setCurrentRow(0);
    return;
  }
  for (const assessment::Trainee& t : assessment::PeopleStore(*history_).trainees()) {
    if (t.role != Role::Trainee) continue;
    const QString text = t.group.isEmpty() ? t.name : tr("%1 (%2)").arg(t.name, t.group);
    auto* item = new QListWidgetItem(text, trainees_);
    item->setData(Qt::UserRole, t.id);
    item->setData(Qt::UserRole + 1, t.name);
  }
  signIn_->setEnabled(trainees_->currentRow() >= 0);
}

void SignInPage::signInSelected() {
  const QListWidgetItem* item = trainees_->currentItem();
  if (!item) return;
  const qint64 id = item->data(Qt::UserRole).toLongLong();
  const QString name = id == 0 ? item->text() : item->data(Qt::UserRole + 1).toString();
  Q_EMIT signedIn({id, Role::Trainee}, name);
}

void SignInPage::createTrainee() {
  const QString name = newName_->text().trimmed();
  if (name.isEmpty()) {
    showError(tr("Type a name first."));
    return;
  }
  if (!history_ || !history_->isOpen()) {
    Q_EMIT signedIn({0, Role::Trainee}, name);
    return;
  }
  assessment::PeopleStore people(*history_);
  const std::optional<qint64> id = people.addTrainee(name);
  if (!id) {
    showError(people.lastError().error == HistoryError::NameTaken
                  ? tr("A person called %1 already exists; pick them from the list.").arg(name)
                  : tr("The trainee could not be created (%1).").arg(people.lastError().driverMessage));
    return;
  }
  newName_->clear();
  refresh();
  Q_EMIT signedIn({*id, Role::Trainee}, name);
}

void SignInPage::signInInstructor() {
  if (!history_ || !history_->isOpen()) {
    showError(tr("Instructors need the history to sign in."));
    return;
  }
  const QString name = instructorName_->text().trimmed();
  const std::optional<qint64> id = assessment::PeopleStore(*history_).verifyInstructor(name, password_->text());
  password_->clear();
  if (!id) {
    showError(tr("Unknown instructor or wrong password."));
    return;
  }
  Q_EMIT signedIn({*id, Role::Instructor}, name);
}

void SignInPage::showError(const QString& text) { message_->setText(text); }

}  // namespace microsim::gui
