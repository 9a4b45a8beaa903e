#pragma once
// The settings dialog, built from the tunables table (tunables.h): a combo box per choice,
// a spin box per integer, each labelled and explained from the table. OK stores the values
// in QSettings; the main window then applies them.

#include <QDialog>
#include <QMap>

class QWidget;

namespace microsim::gui::settings {

class SettingsDialog : public QDialog {
  Q_OBJECT

 public:
  explicit SettingsDialog(QWidget* parent = nullptr);

  /// The editor of `key` (a QComboBox or QSpinBox), for tests.
  QWidget* editor(const QString& key) const { return editors_.value(key); }

  /// Writes every editor's value to QSettings.
  void store() const;

 private:
  QMap<QString, QWidget*> editors_;
};

}  // namespace microsim::gui::settings
