// `microsim-cli db <action> [--db FILE_OR_URL]`: the history database without the GUI.
//   migrate                      bring the schema up to date, print its version
//   backup FILE                  consistent copy of an SQLite history (safe while in use)
//   restore FILE                 replace the history by a backup (checked first)
//   export-csv FILE --instructor NAME   every attempt as CSV; the password comes on stdin
//   list-trainees [--json FILE]  everyone, with role and group
//   add-trainee NAME [--group G]
//   add-instructor NAME --password-stdin   the password never goes on the command line
// --db defaults to the desktop app's file; a postgresql://user@host:port/db URL selects
// a department server. Exit code 0 on success, 1 when the database refused, 2 on usage.
#include "cli/commands.h"
#include "cli/output_file.h"

#include "microsim/assessment/storage/attempts_csv.h"
#include "microsim/assessment/storage/history_database.h"
#include "microsim/assessment/storage/people_store.h"

#include <QCommandLineParser>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cstdio>

namespace microsim::cli {

namespace {

using assessment::DatabaseError;
using assessment::DatabaseStatus;
using assessment::HistoryDatabase;
using assessment::HistoryError;
using assessment::Role;

QString describe(const DatabaseStatus& status, const QString& location) {
  switch (status.error) {
    case DatabaseError::None:
      return {};
    case DatabaseError::CannotCreateFolder:
      return Cli::tr("cannot create the folder for %1").arg(location);
    case DatabaseError::CannotOpen:
      return Cli::tr("cannot open %1").arg(location);
    case DatabaseError::NotADatabase:
      return Cli::tr("%1 is not a microsim database or is damaged; it was left untouched").arg(location);
    case DatabaseError::Locked:
      return Cli::tr("%1 is locked by another program").arg(location);
    case DatabaseError::NewerSchema:
      return Cli::tr("%1 was written by a newer microsim").arg(location);
    case DatabaseError::MigrationFailed:
      return Cli::tr("updating %1 failed; it was left as it was").arg(location);
    case DatabaseError::ReadOnly:
      return Cli::tr("%1 is read-only; it was left untouched").arg(location);
  }
  return {};
}

QString describe(HistoryError error) {
  switch (error) {
    case HistoryError::None:
      return {};
    case HistoryError::NotOpen:
      return Cli::tr("the database is not open");
    case HistoryError::Forbidden:
      return Cli::tr("not allowed for this user");
    case HistoryError::NotFound:
      return Cli::tr("no such person or attempt");
    case HistoryError::NotInProgress:
      return Cli::tr("the attempt is already finished");
    case HistoryError::NameTaken:
      return Cli::tr("that name is taken");
    case HistoryError::InvalidInput:
      return Cli::tr("empty name, or a password shorter than %1 characters")
          .arg(assessment::PeopleStore::kMinPasswordLength);
    case HistoryError::WrongPassword:
      return Cli::tr("unknown instructor or wrong password");
    case HistoryError::Unsupported:
      return Cli::tr("not possible on a PostgreSQL server (use pg_dump and pg_restore there)");
    case HistoryError::NotABackup:
      return Cli::tr("the file is not a microsim history");
    case HistoryError::BackupTooNew:
      return Cli::tr("the backup was written by a newer microsim");
    case HistoryError::FileError:
      return Cli::tr("the file could not be read or written");
    case HistoryError::QueryFailed:
      return Cli::tr("the database reported an error");
  }
  return {};
}

QString roleName(Role r) { return r == Role::Instructor ? Cli::tr("instructor") : Cli::tr("trainee"); }

// the first line of standard input, without its line end
QString passwordFromStdin() {
  QFile in;
  if (!in.open(stdin, QIODevice::ReadOnly)) return {};
  QByteArray line = in.readLine();
  while (line.endsWith('\n') || line.endsWith('\r')) line.chop(1);
  return QString::fromUtf8(line);
}

}  // namespace

int runDb(const QStringList& args, Streams& io) {
  QCommandLineParser parser;
  const QCommandLineOption db(QStringLiteral("db"),
                              Cli::tr("The history: an SQLite <file> or a postgresql://user@host:port/db URL."),
                              QStringLiteral("file-or-url"));
  const QCommandLineOption group(QStringLiteral("group"), Cli::tr("add-trainee: the trainee's <group>."),
                                 QStringLiteral("group"));
  const QCommandLineOption instructor(QStringLiteral("instructor"),
                                      Cli::tr("export-csv: sign in as instructor <name> (password on stdin)."),
                                      QStringLiteral("name"));
  const QCommandLineOption passwordStdin(QStringLiteral("password-stdin"),
                                         Cli::tr("add-instructor: read the password from standard input."));
  const QCommandLineOption json(QStringLiteral("json"), Cli::tr("list-trainees: also write JSON to <file>."),
                                QStringLiteral("file"));
  const QCommandLineOption help(QStringList{QStringLiteral("h"), QStringLiteral("help")}, Cli::tr("Show this help."));
  parser.addOptions({db, group, instructor, passwordStdin, json, help});
  parser.addPositionalArgument(QStringLiteral("action"),
                               Cli::tr("migrate, backup, restore, export-csv, list-trainees, add-trainee or add-instructor"));
  if (!parser.parse(QStringList{QStringLiteral("db")} + args)) {
    io.err << "microsim-cli db: " << parser.errorText() << '\n';
    return kExitUsage;
  }
  const QString usage = Cli::tr(
      "Usage: microsim-cli db migrate|backup FILE|restore FILE|export-csv FILE --instructor NAME|"
      "list-trainees|add-trainee NAME [--group G]|add-instructor NAME --password-stdin [--db FILE_OR_URL]");
  if (parser.isSet(help)) {
    io.out << usage << "\n\n" << parser.helpText().section(QLatin1Char('\n'), 2);
    return kExitOk;
  }

  // every action but migrate and list-trainees takes one argument
  const QStringList words = parser.positionalArguments();
  const QString action = words.value(0);
  const QStringList withArgument = {QStringLiteral("backup"), QStringLiteral("restore"), QStringLiteral("export-csv"),
                                    QStringLiteral("add-trainee"), QStringLiteral("add-instructor")};
  const QStringList without = {QStringLiteral("migrate"), QStringLiteral("list-trainees")};
  const bool known = (withArgument.contains(action) && words.size() == 2) || (without.contains(action) && words.size() == 1);
  if (!known) {
    io.err << usage << '\n';
    return kExitUsage;
  }
  if (action == QLatin1String("add-instructor") && !parser.isSet(passwordStdin)) {
    io.err << Cli::tr("microsim-cli db: add-instructor reads the password from stdin: give --password-stdin") << '\n';
    return kExitUsage;
  }
  if (action == QLatin1String("export-csv") && !parser.isSet(instructor)) {
    io.err << Cli::tr("microsim-cli db: export-csv needs --instructor NAME (password on stdin)") << '\n';
    return kExitUsage;
  }
  const QString argument = words.value(1);

  const QString location = parser.isSet(db) ? parser.value(db) : HistoryDatabase::defaultPath();
  HistoryDatabase history;
  const DatabaseStatus status = history.open(location);
  if (!status.ok()) {
    io.err << Cli::tr("microsim-cli db: %1").arg(describe(status, location));
    if (!status.driverMessage.isEmpty()) io.err << " (" << status.driverMessage << ')';
    io.err << '\n';
    return kExitFailure;
  }
  assessment::PeopleStore people(history);
  const auto failed = [&](const assessment::HistoryStatus& why) {
    io.err << Cli::tr("microsim-cli db %1: %2").arg(action, describe(why.error));
    if (!why.driverMessage.isEmpty()) io.err << " (" << why.driverMessage << ')';
    io.err << '\n';
    return kExitFailure;
  };

  if (action == QLatin1String("migrate")) {
    io.out << Cli::tr("%1: schema version %2").arg(history.path()).arg(status.schemaVersion) << '\n';
  } else if (action == QLatin1String("backup")) {
    // said plainly before any copying starts (a server history refuses backup itself, below)
    if (history.driver() == assessment::Driver::SQLite && QFileInfo::exists(argument)) {
      io.err << Cli::tr("microsim-cli db backup: %1 exists already; it was left untouched. Choose another name for the "
                        "backup, or move that file away first.")
                    .arg(argument)
             << '\n';
      return kExitFailure;
    }
    if (!history.backup(argument)) return failed(history.lastError());
    io.out << Cli::tr("backed up %1 to %2").arg(history.path(), argument) << '\n';
  } else if (action == QLatin1String("restore")) {
    if (!history.restore(argument)) return failed(history.lastError());
    io.out << Cli::tr("restored %1 from %2 (schema version %3)").arg(history.path(), argument).arg(history.schemaVersion())
           << '\n';
  } else if (action == QLatin1String("export-csv")) {
    const auto id = people.verifyInstructor(parser.value(instructor), passwordFromStdin());
    if (!id) return failed(people.lastError());
    QFile out(argument);
    if (!out.open(QIODevice::WriteOnly | QIODevice::Truncate)) {
      io.err << Cli::tr("microsim-cli db: cannot write %1").arg(argument) << '\n';
      return kExitFailure;
    }
    if (const auto exported = assessment::exportAttemptsCsv(history, {*id, Role::Instructor}, out); !exported.ok())
      return failed(exported);
    QString why;
    if (!closeOutputFile(out, why)) {
      io.err << Cli::tr("microsim-cli db: cannot write %1").arg(argument) << " (" << why << ")\n";
      return kExitFailure;
    }
    io.out << Cli::tr("wrote %1").arg(argument) << '\n';
  } else if (action == QLatin1String("list-trainees")) {
    const QList<assessment::Trainee> everyone = people.trainees();
    if (!people.lastError().ok()) return failed(people.lastError());
    io.out << Cli::tr("id").leftJustified(8) << Cli::tr("role").leftJustified(12) << Cli::tr("group").leftJustified(16)
           << Cli::tr("name") << '\n';
    QJsonArray rows;
    for (const assessment::Trainee& t : everyone) {
      io.out << QString::number(t.id).leftJustified(8) << roleName(t.role).leftJustified(12)
             << t.group.leftJustified(16) << t.name << '\n';
      rows.append(QJsonObject{{QStringLiteral("id"), t.id},
                              {QStringLiteral("name"), t.name},
                              {QStringLiteral("role"), t.role == Role::Instructor ? QStringLiteral("instructor")
                                                                                  : QStringLiteral("trainee")},
                              {QStringLiteral("group"), t.group}});
    }
    if (parser.isSet(json)) {
      QString why;
      if (!writeOutputFile(parser.value(json), QJsonDocument(rows).toJson(), why)) {
        io.err << Cli::tr("microsim-cli db: cannot write %1").arg(parser.value(json)) << " (" << why << ")\n";
        return kExitFailure;
      }
    }
  } else if (action == QLatin1String("add-trainee")) {
    const auto id = people.addTrainee(argument, parser.value(group));
    if (!id) return failed(people.lastError());
    io.out << Cli::tr("added trainee %1 (id %2)").arg(argument).arg(*id) << '\n';
  } else {
    const auto id = people.addInstructor(argument, passwordFromStdin());
    if (!id) return failed(people.lastError());
    io.out << Cli::tr("added instructor %1 (id %2)").arg(argument).arg(*id) << '\n';
  }
  return kExitOk;
}

}  // namespace microsim::cli
