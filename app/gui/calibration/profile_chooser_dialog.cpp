#include "gui/calibration/profile_chooser_dialog.h"

#include "gui/number_format.h"
#include "gui/save_file.h"

#include <QDialogButtonBox>
#include <QFile>
#include <QFileDialog>
#include <QListWidget>
#include <QMessageBox>
#include <QPushButton>
#include <QVBoxLayout>

namespace microsim::gui {

ProfileChooserDialog::ProfileChooserDialog(assessment::HistoryDatabase* database, QWidget* parent)
    : QDialog(parent), database_(database) {
  setWindowTitle(tr("Setup profile"));
  list_ = new QListWidget(this);
  auto* buttons = new QDialogButtonBox(this);
  use_ = buttons->addButton(tr("Use"), QDialogButtonBox::AcceptRole);
  QPushButton* import = buttons->addButton(tr("Import…"), QDialogButtonBox::ActionRole);
  QPushButton* exportButton = buttons->addButton(tr("Export…"), QDialogButtonBox::ActionRole);
  QPushButton* remove = buttons->addButton(tr("Delete"), QDialogButtonBox::DestructiveRole);
  buttons->addButton(QDialogButtonBox::Cancel);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(list_);
  layout->addWidget(buttons);

  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(use_, &QPushButton::clicked, this, &ProfileChooserDialog::choose);
  connect(list_, &QListWidget::itemDoubleClicked, this, &ProfileChooserDialog::choose);
  connect(list_, &QListWidget::currentRowChanged, this, [this, exportButton, remove](int row) {
    use_->setEnabled(row >= 0);
    exportButton->setEnabled(row >= 0);
    remove->setEnabled(row >= 0);
  });
  connect(import, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getOpenFileName(this, tr("Import setup profile"), {}, tr("JSON (*.json)"));
    if (path.isEmpty()) return;
    QString error;
    if (const std::optional<qint64> id = importFile(path, &error))
      reload(*id);
    else
      QMessageBox::warning(this, tr("Import setup profile"), error);
  });
  connect(exportButton, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getSaveFileName(this, tr("Export setup profile"), {}, tr("JSON (*.json)"));
    QString error;
    if (!path.isEmpty() && !exportFile(currentId(), path, &error))
      QMessageBox::warning(this, tr("Export setup profile"), error);
  });
  connect(remove, &QPushButton::clicked, this, [this] {
    assessment::SetupProfileStore store(*database_);
    if (store.remove(currentId())) reload();
  });
  reload();
}

void ProfileChooserDialog::reload(qint64 select) {
  list_->clear();
  if (database_ == nullptr || !database_->isOpen()) return;
  assessment::SetupProfileStore store(*database_);
  for (const assessment::SetupProfileSummary& s : store.list()) {
    QString text = tr("%1 — %2 by %3").arg(s.name, QLocale().toString(s.calibratedAt.toLocalTime(), QLocale::ShortFormat),
                                            s.calibratedBy.isEmpty() ? tr("unknown") : s.calibratedBy);
    if (s.freMm) text += QStringLiteral(" · ") + tr("FRE %1 mm").arg(NumberFormat::number(*s.freMm, 2));
    if (s.treMm) text += QStringLiteral(" · ") + tr("TRE %1 mm").arg(NumberFormat::number(*s.treMm, 2));
    auto* item = new QListWidgetItem(text, list_);
    item->setData(Qt::UserRole, s.id);
    if (s.id == select) list_->setCurrentItem(item);
  }
  if (list_->currentRow() < 0 && list_->count() > 0) list_->setCurrentRow(0);
  use_->setEnabled(list_->currentRow() >= 0);
}

qint64 ProfileChooserDialog::currentId() const {
  const QListWidgetItem* item = list_->currentItem();
  return item != nullptr ? item->data(Qt::UserRole).toLongLong() : 0;
}

void ProfileChooserDialog::choose() {
  assessment::SetupProfileStore store(*database_);
  selected_ = store.load(currentId());
  if (selected_) accept();
}

std::optional<qint64> ProfileChooserDialog::importFile(const QString& path, QString* error) {
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly)) {
    *error = tr("Cannot read %1.").arg(path);
    return std::nullopt;
  }
  auto parsed = assessment::importProfileJson(f.readAll());
  if (const auto* e = std::get_if<assessment::ProfileJsonError>(&parsed)) {
    *error = describe(*e);
    return std::nullopt;
  }
  assessment::SetupProfileStore store(*database_);
  const std::optional<qint64> id = store.save(std::get<assessment::SetupProfile>(parsed));
  if (!id) *error = tr("The profile could not be stored: %1").arg(store.lastError());
  return id;
}

bool ProfileChooserDialog::exportFile(qint64 id, const QString& path, QString* error) {
  assessment::SetupProfileStore store(*database_);
  const std::optional<assessment::SetupProfile> profile = store.load(id);
  if (!profile) {
    *error = tr("The profile could not be read: %1").arg(store.lastError());
    return false;
  }
  SaveFile f(path);
  QString why;
  bool written = f.open(why);
  if (written) {
    f.device()->write(assessment::exportProfileJson(*profile));
    written = f.commit(why);
  }
  if (!written) *error = tr("Cannot write %1: %2").arg(path, why);
  return written;
}

QString ProfileChooserDialog::describe(const assessment::ProfileJsonError& e) {
  switch (e.problem) {
    case assessment::ProfileJsonProblem::NotJson: return tr("The file is not a JSON document.");
    case assessment::ProfileJsonProblem::WrongFormat: return tr("The file is not a microsim setup profile (%1).").arg(e.field);
    case assessment::ProfileJsonProblem::Missing: return tr("The field \"%1\" is missing.").arg(e.field);
    case assessment::ProfileJsonProblem::WrongType: return tr("The field \"%1\" has the wrong type.").arg(e.field);
    case assessment::ProfileJsonProblem::OutOfRange: return tr("The field \"%1\" has a value that is not allowed.").arg(e.field);
  }
  return {};
}

}  // namespace microsim::gui
