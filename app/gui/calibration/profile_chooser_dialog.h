#pragma once
// Chooses the setup profile at start (or from the Calibration menu): the stored profiles,
// newest calibration first, with their errors and who calibrated them; import from and
// export to JSON files (an import that fails validation names the field at fault), and
// delete. exec() == Accepted: selectedProfile() holds the chosen one.

#include "microsim/assessment/storage/setup_profiles.h"

#include <QDialog>

#include <optional>

class QListWidget;
class QPushButton;

namespace microsim::gui {

class ProfileChooserDialog : public QDialog {
  Q_OBJECT

 public:
  ProfileChooserDialog(assessment::HistoryDatabase* database, QWidget* parent = nullptr);

  /// Reloads the list; `select` (an id) becomes current when present.
  void reload(qint64 select = 0);
  const std::optional<assessment::SetupProfile>& selectedProfile() const { return selected_; }

  /// Imports a JSON file into the database; on failure returns a user-readable reason.
  std::optional<qint64> importFile(const QString& path, QString* error);
  /// Exports a stored profile to a JSON file.
  bool exportFile(qint64 id, const QString& path, QString* error);

  /// A user-readable sentence for an import error.
  static QString describe(const assessment::ProfileJsonError& error);

 private:
  qint64 currentId() const;
  void choose();

  assessment::HistoryDatabase* database_;
  QListWidget* list_ = nullptr;
  QPushButton* use_ = nullptr;
  std::optional<assessment::SetupProfile> selected_;
};

}  // namespace microsim::gui
