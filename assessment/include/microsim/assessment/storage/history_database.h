#pragma once
// The trainees' history, through QtSql: by default one SQLite file in the user's data
// folder (WAL journaling, foreign keys on), or a department's PostgreSQL server given as
// a URL `postgresql://user[:password]@host[:port]/database`. The same numbered migrations
// build the same schema on both (see migrations.h).
//
// This class is the connection: it opens (migrating and sweeping up ended sessions'
// attempts), closes, backs up and restores. The tables are read and written by one store
// each, over an open HistoryDatabase (fooyin's per-table repositories):
//   PeopleStore       trainees, instructors and their password hashes, groups (people_store.h)
//   AttemptStore      attempts: begun, abandoned, listed (attempt_store.h)
//   ScoreStore        a finished attempt's score, metrics, pierce values, recording (score_store.h)
//   AnnotationStore   instructors' notes on attempts (annotation_store.h)
//   SetupProfileStore calibration profiles (setup_profiles.h)
// and readAttemptDetail (attempt_detail.h) and exportAttemptsCsv (attempts_csv.h) read
// through several of them.
//
// Roles are enforced in the stores, not in the GUI: every read of attempts takes a Viewer,
// whose role is checked against the stored person. A trainee sees only their own attempts;
// an instructor (signed in with a salted PBKDF2 password, see password_hash.h) sees all and
// may annotate. A score is written once, by ScoreStore::finish, in the same transaction as
// its metrics, pierce values and recording; there is no update path, and SQL triggers
// refuse UPDATEs of stored scores on both drivers.
//
// Sessions. An attempt records the session (connection) that began it: on SQLite
// pid@host#n, n this process's connection counter; on PostgreSQL the server's backend pid.
// At open, attempts still in progress whose session has ended (its process gone — a crash,
// SIGKILL —, or in this very process its connection closed; on PostgreSQL its backend gone)
// become Interrupted; attempts of live sessions are left alone.
//
// Threads. A QtSql connection belongs to the thread that opened it: open, use and close a
// HistoryDatabase (and its stores) on one thread. The app's attempts do theirs on a worker
// thread with a connection of its own (app/gui/session). setAccessObserver lets a test see
// the thread of every access.
//
// Errors come back as enums plus the driver's text as data; the app decides what to tell
// the user. A database that cannot be opened is never changed.

#include "microsim/assessment/storage/history_types.h"
#include "microsim/assessment/storage/migrations.h"

#include <QSqlDatabase>
#include <QString>

#include <functional>

namespace microsim::assessment {

enum class DatabaseError {
  None,
  CannotCreateFolder,  ///< the folder for the file could not be made
  CannotOpen,          ///< the driver refused the file or server (permissions, missing driver)
  NotADatabase,        ///< the file exists but is not SQLite, or is corrupt
  Locked,              ///< another process holds a lock longer than the busy timeout
  NewerSchema,         ///< written by a newer microsim; opened read-only would be unsafe
  MigrationFailed,     ///< a migration failed and was rolled back
  ReadOnly,            ///< the file (or its folder) is marked read-only; left untouched
};

struct DatabaseStatus {
  DatabaseError error = DatabaseError::None;
  int schemaVersion = 0;
  QString driverMessage;
  bool ok() const { return error == DatabaseError::None; }
};

/// Why an operation on an open database failed (lastError() of the database or a store).
enum class HistoryError {
  None,
  NotOpen,
  Forbidden,        ///< the viewer's role does not allow it, or the viewer is unknown
  NotFound,         ///< no such person or attempt
  NotInProgress,    ///< finishing or abandoning an attempt that is no longer in progress
  NameTaken,        ///< a person with that name exists
  InvalidInput,     ///< an empty name, a password shorter than PeopleStore::kMinPasswordLength, ...
  WrongPassword,    ///< verifyInstructor: unknown name or wrong password (not told apart)
  Unsupported,      ///< backup/restore on PostgreSQL (use pg_dump there)
  NotABackup,       ///< restore: the file is not a microsim history database
  BackupTooNew,     ///< restore: the file's schema is newer than this program's
  FileError,        ///< a file could not be written, copied or replaced
  QueryFailed,      ///< the driver reported an error (see driverMessage)
};

struct HistoryStatus {
  HistoryError error = HistoryError::None;
  QString driverMessage;
  bool ok() const { return error == HistoryError::None; }
};

class HistoryDatabase {
 public:
  /// PBKDF2-HMAC-SHA256 iterations for new instructor passwords (OWASP 2023).
  static constexpr int kDefaultPasswordIterations = 600000;

  HistoryDatabase();
  ~HistoryDatabase();
  HistoryDatabase(const HistoryDatabase&) = delete;
  HistoryDatabase& operator=(const HistoryDatabase&) = delete;

  /// <AppDataLocation>/history.sqlite
  static QString defaultPath();
  /// True for `postgresql://...` or `postgres://...`.
  static bool isUrl(const QString& location);

  /// Opens (creating if needed) the SQLite file at `location`, or connects to the
  /// PostgreSQL URL, applies pending migrations and marks the attempts of ended sessions
  /// Interrupted.
  DatabaseStatus open(const QString& location);
  void close();

  bool isOpen() const;
  Driver driver() const { return driver_; }
  /// The file path (SQLite) or the URL without its password (PostgreSQL).
  QString path() const { return path_; }
  /// What open() was given (a URL keeps its password): another connection to the same
  /// history, e.g. on another thread, opens this.
  QString location() const { return location_; }
  int schemaVersion();
  /// The connection, for the stores of this library.
  QSqlDatabase connection() const;
  /// This connection's session tag, stored with the attempts it begins.
  QString session() const { return session_; }
  /// True when the attempts of `session` can no longer be finished: its process or
  /// server backend is gone, or it was a connection of this process that is closed now.
  bool sessionEnded(const QString& session);
  /// The outcome of the last backup() or restore().
  HistoryStatus lastError() const { return last_; }
  /// Iterations for passwords set from now on (tests lower it; stored with each hash).
  void setPasswordIterations(int iterations) { passwordIterations_ = iterations; }
  int passwordIterations() const { return passwordIterations_; }

  /// A consistent copy of the open SQLite database (VACUUM INTO), safe while in use.
  /// Written as `toFile`.part and renamed when complete; refused (FileError) when
  /// `toFile` exists.
  bool backup(const QString& toFile);
  /// Replaces the open SQLite database by `fromFile` after checking that it is a microsim
  /// history no newer than this program; then reopens and migrates it.
  bool restore(const QString& fromFile);

  /// Called on the calling thread each time a store reaches the driver (connection(),
  /// isOpen()); tests assert with it which threads touch the history. Empty: none.
  /// Process-wide; set it while no history is in use on another thread.
  using AccessObserver = std::function<void(const HistoryDatabase&)>;
  static void setAccessObserver(AccessObserver observer);

 private:
  bool fail(HistoryError error, const QString& driverMessage = {});
  bool succeed();
  DatabaseStatus openSqlite(const QString& path);
  DatabaseStatus openPostgres(const QString& url);
  DatabaseStatus finishOpen(QSqlDatabase& db);
  void notifyAccess() const;

  QString connectionName_;
  QString path_;
  QString location_;
  Driver driver_ = Driver::SQLite;
  QString session_;  ///< tag of this connection's session, stored with begun attempts
  HistoryStatus last_;
  int passwordIterations_ = kDefaultPasswordIterations;
};

}  // namespace microsim::assessment
