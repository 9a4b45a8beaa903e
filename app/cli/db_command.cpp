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
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/history_text.h"
#include "cli/output_file.h"
#include "microsim/assessment/storage/attempts_csv.h"
#include "microsim/assessment/storage/history_database.h"
#include "microsim/assessment/storage/people_store.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cstdio>

namespace microsim::cli {

namespace {

using assessment::DatabaseStatus;
using assessment::HistoryDatabase;
using assessment::Role;

struct DbOptions {
  QCommandLineOption db{QStringLiteral("db"),
                        Cli::tr("The history: an SQLite <file> or a postgresql://user@host:port/db URL."),
                        QStringLiteral("file-or-url")};
  QCommandLineOption group{QStringLiteral("group"), Cli::tr("add-trainee: the trainee's <group>."),
                           QStringLiteral("group")};
  QCommandLineOption instructor{QStringLiteral("instructor"),
                                Cli::tr("export-csv: sign in as instructor <name> (password on stdin)."),
                                QStringLiteral("name")};
  QCommandLineOption passwordStdin{QStringLiteral("password-stdin"),
                                   Cli::tr("add-instructor: read the password from standard input.")};
  QCommandLineOption json{QStringLiteral("json"), Cli::tr("list-trainees: also write JSON to <file>."),
                          QStringLiteral("file")};

  QString usage() const {
    return Cli::tr("Usage: microsim-cli db migrate|backup FILE|restore FILE|export-csv FILE --instructor NAME|"
                   "list-trainees|add-trainee NAME [--group G]|add-instructor NAME --password-stdin "
                   "[--db FILE_OR_URL]");
  }
  void declare(CommandLine& line) const;
};

// the actions in the order the usage lists them; all but two take a file or a name
const QStringList kDbActions = {QStringLiteral("migrate"),       QStringLiteral("backup"),
                              QStringLiteral("restore"),       QStringLiteral("export-csv"),
                              QStringLiteral("list-trainees"), QStringLiteral("add-trainee"),
                              QStringLiteral("add-instructor")};
const QStringList kDbActionsWithoutArgument = {QStringLiteral("migrate"), QStringLiteral("list-trainees")};

void DbOptions::declare(CommandLine& line) const {
  line.addOptions({db, group, instructor, passwordStdin, json});
  line.addWord(QStringLiteral("action"), kDbActions.join(QStringLiteral(", ")));
  line.addWord(QStringLiteral("argument"), Cli::tr("the file or name the action takes"));
}

// what the command line asks for, checked
struct DbRequest {
  QString action;
  QString argument;  ///< the file or name the action takes; empty for migrate and list-trainees
  QString location;  ///< the history: --db, else the desktop app's file
};

std::optional<DbRequest> readDbRequest(const CommandLine& line, const DbOptions& o) {
  const QStringList words = line.words();
  DbRequest r{words.value(0), words.value(1), {}};
  if (r.action.isEmpty()) {
    line.usageError(Cli::tr("name an action: %1").arg(kDbActions.join(QStringLiteral(", "))));
    return std::nullopt;
  }
  if (!kDbActions.contains(r.action)) {
    line.usageError(Cli::tr("unknown action '%1' (known: %2)").arg(r.action, kDbActions.join(QStringLiteral(", "))));
    return std::nullopt;
  }
  const bool takesArgument = !kDbActionsWithoutArgument.contains(r.action);
  if (takesArgument && words.size() < 2) {
    line.usageError(Cli::tr("%1 needs a file or a name after it").arg(r.action));
    return std::nullopt;
  }
  if (!takesArgument && words.size() > 1) {
    line.usageError(Cli::tr("unexpected argument '%1'").arg(r.argument));
    return std::nullopt;
  }
  if (r.action == QLatin1String("add-instructor") && !line.isSet(o.passwordStdin)) {
    line.usageError(Cli::tr("add-instructor reads the password from stdin: give --password-stdin"));
    return std::nullopt;
  }
  if (r.action == QLatin1String("export-csv") && !line.isSet(o.instructor)) {
    line.usageError(Cli::tr("export-csv needs --instructor NAME (password on stdin)"));
    return std::nullopt;
  }
  r.location = line.isSet(o.db) ? line.value(o.db) : HistoryDatabase::defaultPath();
  return r;
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

// why the action failed, after the command's prefix and the action: kExitFailure
int actionFailed(const CommandLine& line, const DbRequest& request, const QString& why) {
  return line.failure(request.action + QStringLiteral(": ") + why);
}

// what the history refused
int refused(const CommandLine& line, const DbRequest& request, const assessment::HistoryStatus& why) {
  return actionFailed(line, request, historyErrorText(why));
}

int backUp(const CommandLine& line, const DbRequest& request, HistoryDatabase& history) {
  // said plainly before any copying starts (a server history refuses backup itself, below)
  if (history.driver() == assessment::Driver::SQLite && QFileInfo::exists(request.argument))
    return actionFailed(line, request,
                        Cli::tr("%1 exists already; it was left untouched. Choose another name for the "
                                "backup, or move that file away first.")
                            .arg(request.argument));
  if (!history.backup(request.argument)) return refused(line, request, history.lastError());
  line.io().out << Cli::tr("backed up %1 to %2").arg(history.path(), request.argument) << '\n';
  return kExitOk;
}

int restoreFrom(const CommandLine& line, const DbRequest& request, HistoryDatabase& history) {
  if (!history.restore(request.argument)) return refused(line, request, history.lastError());
  line.io().out << Cli::tr("restored %1 from %2 (schema version %3)")
                       .arg(history.path(), request.argument)
                       .arg(history.schemaVersion())
                << '\n';
  return kExitOk;
}

int exportCsv(const CommandLine& line, const DbRequest& request, const QString& instructor, HistoryDatabase& history) {
  assessment::PeopleStore people(history);
  const auto id = people.verifyInstructor(instructor, passwordFromStdin());
  if (!id) return refused(line, request, people.lastError());
  QFile out(request.argument);
  if (!out.open(QIODevice::WriteOnly | QIODevice::Truncate))
    return line.failure(Cli::tr("cannot write %1: %2").arg(request.argument, out.errorString()));
  const assessment::HistoryStatus exported = assessment::exportAttemptsCsv(history, {*id, Role::Instructor}, out);
  if (!exported.ok()) return refused(line, request, exported);
  QString why;
  if (!closeOutputFile(out, why)) return line.failure(Cli::tr("cannot write %1: %2").arg(request.argument, why));
  line.io().out << Cli::tr("wrote %1").arg(request.argument) << '\n';
  return kExitOk;
}

int listTrainees(const CommandLine& line, const DbRequest& request, const QString& jsonPath, HistoryDatabase& history) {
  assessment::PeopleStore store(history);
  const QList<assessment::Trainee> people = store.trainees();
  if (!store.lastError().ok()) return refused(line, request, store.lastError());
  QTextStream& out = line.io().out;
  out << Cli::tr("id").leftJustified(8) << Cli::tr("role").leftJustified(12) << Cli::tr("group").leftJustified(16)
      << Cli::tr("name") << '\n';
  QJsonArray rows;
  for (const assessment::Trainee& t : people) {
    out << QString::number(t.id).leftJustified(8) << roleName(t.role).leftJustified(12) << t.group.leftJustified(16)
        << t.name << '\n';
    rows.append(QJsonObject{
        {QStringLiteral("id"), t.id},
        {QStringLiteral("name"), t.name},
        {QStringLiteral("role"), t.role == Role::Instructor ? QStringLiteral("instructor") : QStringLiteral("trainee")},
        {QStringLiteral("group"), t.group}});
  }
  if (jsonPath.isEmpty()) return kExitOk;
  return writeCommandOutput(line, jsonPath, QJsonDocument(rows).toJson());
}

// load → run → report
int manageHistory(const CommandLine& line, const DbOptions& options) {
  const std::optional<DbRequest> request = readDbRequest(line, options);
  if (!request) return kExitUsage;

  // load: the history, migrated
  HistoryDatabase history;
  const DatabaseStatus status = history.open(request->location);
  if (!status.ok()) return line.failure(databaseErrorText(status, request->location));

  // run the action and report
  const QString& action = request->action;
  if (action == QLatin1String("migrate")) {
    line.io().out << Cli::tr("%1: schema version %2").arg(history.path()).arg(status.schemaVersion) << '\n';
    return kExitOk;
  }
  if (action == QLatin1String("backup")) return backUp(line, *request, history);
  if (action == QLatin1String("restore")) return restoreFrom(line, *request, history);
  if (action == QLatin1String("export-csv")) return exportCsv(line, *request, line.value(options.instructor), history);
  if (action == QLatin1String("list-trainees")) return listTrainees(line, *request, line.value(options.json), history);
  assessment::PeopleStore people(history);
  const std::optional<qint64> id = action == QLatin1String("add-trainee")
                                       ? people.addTrainee(request->argument, line.value(options.group))
                                       : people.addInstructor(request->argument, passwordFromStdin());
  if (!id) return refused(line, *request, people.lastError());
  line.io().out << (action == QLatin1String("add-trainee") ? Cli::tr("added trainee %1 (id %2)")
                                                    : Cli::tr("added instructor %1 (id %2)"))
                .arg(request->argument)
                .arg(*id)
         << '\n';
  return kExitOk;
}

}  // namespace

int runDb(const QStringList& args, Streams& io) { return runCommand(QStringLiteral("db"), args, io, &manageHistory); }

}  // namespace microsim::cli
