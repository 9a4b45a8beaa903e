#include "gui/pages/sign_in_page.h"

#include "gui/pages/new_person_form.h"

#include "microsim/assessment/storage/people_store.h"

#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QStackedWidget>
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

  // instructors: sign in, or, in a history without any, create the first one
  auto* instructorBox = new QGroupBox(tr("Instructor"), this);
  instructorStack_ = new QStackedWidget(instructorBox);
  auto* signInForm = new QWidget(instructorStack_);
  instructorName_ = new QLineEdit(signInForm);
  instructorName_->setObjectName(QStringLiteral("instructorName"));
  password_ = new QLineEdit(signInForm);
  password_->setObjectName(QStringLiteral("instructorPassword"));
  password_->setEchoMode(QLineEdit::Password);
  auto* instructorSignIn = new QPushButton(tr("Sign in as instructor"), signInForm);
  instructorSignIn->setObjectName(QStringLiteral("instructorSignInButton"));
  auto* form = new QFormLayout(signInForm);
  form->setContentsMargins(0, 0, 0, 0);
  form->addRow(tr("Name"), instructorName_);
  form->addRow(tr("Password"), password_);
  form->addRow(instructorSignIn);

  auto* firstRun = new QWidget(instructorStack_);
  firstRun->setObjectName(QStringLiteral("firstInstructorForm"));
  auto* firstRunText = new QLabel(tr("No instructor has been set up in this history yet. Create the first one: "
                                     "they can then add instructors and trainees."),
                                  firstRun);
  firstRunText->setWordWrap(true);
  firstInstructor_ = new NewPersonForm(assessment::Role::Instructor, firstRun);
  auto* createInstructor = new QPushButton(tr("Create instructor and sign in"), firstRun);
  createInstructor->setObjectName(QStringLiteral("createFirstInstructorButton"));
  auto* firstRunLayout = new QVBoxLayout(firstRun);
  firstRunLayout->setContentsMargins(0, 0, 0, 0);
  firstRunLayout->addWidget(firstRunText);
  firstRunLayout->addWidget(firstInstructor_);
  firstRunLayout->addWidget(createInstructor);
  instructorStack_->addWidget(signInForm);
  instructorStack_->addWidget(firstRun);
  auto* instructorLayout = new QVBoxLayout(instructorBox);
  instructorLayout->addWidget(instructorStack_);

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
  connect(createInstructor, &QPushButton::clicked, this, &SignInPage::createFirstInstructor);
  connect(firstInstructor_, &NewPersonForm::submitted, this, &SignInPage::createFirstInstructor);
  refresh();
}

void SignInPage::refresh() {
  trainees_->clear();
  message_->clear();
  password_->clear();
  firstInstructor_->clear();
  instructorStack_->setCurrentIndex(0);
  if (!history_ || !history_->isOpen()) {
    showError(tr("The history is unavailable: you can practise, but nothing will be stored."));
    auto* guest = new QListWidgetItem(tr("Guest"), trainees_);
    guest->setData(Qt::UserRole, 0);
    trainees_->setCurrentRow(0);
    return;
  }
  bool anyInstructor = false;
  for (const assessment::Trainee& t : assessment::PeopleStore(*history_).trainees()) {
    anyInstructor = anyInstructor || t.role == Role::Instructor;
    if (t.role != Role::Trainee) continue;
    const QString text = t.group.isEmpty() ? t.name : tr("%1 (%2)").arg(t.name, t.group);
    auto* item = new QListWidgetItem(text, trainees_);
    item->setData(Qt::UserRole, t.id);
    item->setData(Qt::UserRole + 1, t.name);
  }
  signIn_->setEnabled(trainees_->currentRow() >= 0);
  instructorStack_->setCurrentIndex(anyInstructor ? 0 : 1);
}

bool SignInPage::offersFirstInstructor() const { return instructorStack_->currentIndex() == 1; }

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

void SignInPage::createFirstInstructor() {
  if (!history_ || !history_->isOpen()) return;
  if (const NewPersonProblem problem = firstInstructor_->problem(); problem != NewPersonProblem::None) {
    showError(NewPersonForm::describe(problem));
    return;
  }
  const QString name = firstInstructor_->name();
  assessment::PeopleStore people(*history_);
  const std::optional<qint64> id = people.addFirstInstructor(name, firstInstructor_->password());
  if (!id) {
    const QString reason = NewPersonForm::describe(people.lastError(), name);
    refresh();  // another program may have made one meanwhile: offer the sign-in instead
    showError(reason);
    return;
  }
  refresh();
  Q_EMIT signedIn({*id, Role::Instructor}, name);
}

void SignInPage::showError(const QString& text) { message_->setText(text); }

}  // namespace microsim::gui
