#pragma once
// The main window: menus, the microscope viewport in the centre, and a status bar that
// says where the trainee history is kept (or why it could not be opened).

#include "microsim/assessment/storage/history_database.h"

#include <QMainWindow>

class QLabel;

namespace microsim::gui {

class Viewport;

class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  explicit MainWindow(const assessment::DatabaseStatus& database, const QString& databasePath,
                      QWidget* parent = nullptr);

  Viewport* viewport() const { return viewport_; }
  /// The status bar's text about the history database.
  QString databaseMessage() const;

  /// A user-readable sentence for a database status.
  static QString describe(const assessment::DatabaseStatus& status, const QString& path);

 protected:
  void closeEvent(QCloseEvent* event) override;

 private:
  void buildMenus();
  void chooseLanguage(const QString& language);
  void showAbout();

  Viewport* viewport_ = nullptr;
  QLabel* databaseLabel_ = nullptr;
};

}  // namespace microsim::gui
