#pragma once
// The trainees' history, through QtSql: by default one SQLite file in the user's data
// folder (WAL journaling, foreign keys on), or a department's PostgreSQL server given as
// a URL `postgresql://user[:password]@host[:port]/database`. The same numbered migrations
// build the same schema on both (see migrations.h).
//
// Roles are enforced here, not in the GUI: every read of attempts takes a Viewer, whose
// role is checked against the stored person. A trainee sees only their own attempts; an
// instructor (signed in with a salted PBKDF2 password, see password_hash.h) sees all and
// may annotate. A score is written once, by finishAttempt, in the same transaction as
// its metrics, pierce values and recording; there is no update path, finishAttempt
// refuses an attempt that is not in progress, and SQL triggers refuse UPDATEs of stored
// scores on both drivers.
//
// An attempt records the session that began it (SQLite: pid@host; PostgreSQL: the
// server's backend pid). At open, attempts still in progress whose session is gone
// (a crash, SIGKILL) become Interrupted; attempts of live sessions are left alone.
//
// Errors come back as enums plus the driver's text as data; the app decides what to tell
// the user. A database that cannot be opened is never changed.

#include "microsim/assessment/storage/history_types.h"
#include "microsim/assessment/storage/migrations.h"

#include <QIODevice>
#include <QSqlDatabase>
#include <QString>

#include <optional>

namespace microsim::assessment {

struct AttemptScore;  // scoring/score.h

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

/// Why an operation on an open database failed (HistoryDatabase::lastError()).
enum class HistoryError {
  None,
  NotOpen,
  Forbidden,        ///< the viewer's role does not allow it, or the viewer is unknown
  NotFound,         ///< no such person or attempt
  NotInProgress,    ///< finishAttempt on an attempt that is finished or interrupted
  NameTaken,        ///< a person with that name exists
  InvalidInput,     ///< an empty name, a password shorter than kMinPasswordLength, ...
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
  static constexpr int kMinPasswordLength = 8;
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
  /// PostgreSQL URL, applies pending migrations and marks orphaned attempts Interrupted.
  DatabaseStatus open(const QString& location);
  void close();

  bool isOpen() const;
  Driver driver() const { return driver_; }
  /// The file path (SQLite) or the URL without its password (PostgreSQL).
  QString path() const { return path_; }
  int schemaVersion();
  /// The connection, for repositories in this library.
  QSqlDatabase connection() const;
  /// The outcome of the last operation below.
  HistoryStatus lastError() const { return last_; }
  /// Iterations for passwords set from now on (tests lower it; stored with each hash).
  void setPasswordIterations(int iterations) { passwordIterations_ = iterations; }

  // ---- people -------------------------------------------------------------------------
  /// Everyone, trainees and instructors, by name.
  QList<Trainee> trainees();
  std::optional<Trainee> person(qint64 id);
  /// A trainee; `group` is created when new. nullopt: NameTaken, InvalidInput, ...
  std::optional<qint64> addTrainee(const QString& name, const QString& group = {});
  /// An instructor with a salted PBKDF2-HMAC-SHA256 hash of `password`.
  std::optional<qint64> addInstructor(const QString& name, const QString& password);
  /// The instructor's id when the password matches (constant-time compare).
  std::optional<qint64> verifyInstructor(const QString& name, const QString& password);
  QStringList groups();

  // ---- attempts -----------------------------------------------------------------------
  std::optional<qint64> beginAttempt(qint64 traineeId, const QString& lesson, AttemptMode mode);
  /// Stores score, metrics, pierce values and recording in one transaction and marks the
  /// attempt Finished. Refused (NotInProgress) when the attempt is not in progress.
  bool finishAttempt(qint64 attemptId, const AttemptScore& score, const QByteArray& recording);
  /// Oldest first. A trainee gets only their own (asking for another's gives Forbidden
  /// and an empty list); an instructor gets everyone's, or `traineeId`'s.
  QList<AttemptSummary> attempts(const Viewer& viewer, std::optional<qint64> traineeId = {});
  std::optional<AttemptDetail> attempt(const Viewer& viewer, qint64 attemptId);
  /// Instructors only. Returns the annotation's id.
  std::optional<qint64> annotate(const Viewer& viewer, qint64 attemptId, const QString& note);

  // ---- files --------------------------------------------------------------------------
  /// A consistent copy of the open SQLite database (VACUUM INTO), safe while in use.
  /// Written as `toFile`.part and renamed when complete; refused (FileError) when
  /// `toFile` exists.
  bool backup(const QString& toFile);
  /// Replaces the open SQLite database by `fromFile` after checking that it is a microsim
  /// history no newer than this program; then reopens and migrates it.
  bool restore(const QString& fromFile);
  /// Every attempt the viewer may see, one CSV row each (RFC 4180), with a header row.
  bool exportCsv(const Viewer& viewer, QIODevice& out);

 private:
  bool fail(HistoryError error, const QString& driverMessage = {});
  bool succeed();
  std::optional<Role> storedRole(qint64 personId);
  bool mayView(const Viewer& viewer, std::optional<qint64> traineeId);
  void interruptOrphanedAttempts();
  DatabaseStatus openSqlite(const QString& path);
  DatabaseStatus openPostgres(const QString& url);
  DatabaseStatus finishOpen(QSqlDatabase& db);

  QString connectionName_;
  QString path_;
  Driver driver_ = Driver::SQLite;
  QString session_;  ///< tag of this connection's session, stored with begun attempts
  HistoryStatus last_;
  int passwordIterations_ = kDefaultPasswordIterations;
};

}  // namespace microsim::assessment
