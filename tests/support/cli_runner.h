#pragma once
// Runs the real microsim-cli binary (MICROSIM_CLI_PATH) as a user would, for tests.
#include <QByteArray>
#include <QProcess>
#include <QProcessEnvironment>
#include <QString>
#include <QStringList>

namespace microsim::testing {

struct CliRun {
  int exitCode = -1;  ///< -1: did not finish in time; -2: crashed
  QString out;
  QString err;
};

/// Runs microsim-cli with `args`; `input`, when given, is written to its stdin (then closed);
/// `environment` adds or replaces variables of the test's own.
inline CliRun runCli(const QStringList& args, int timeoutMs = 120000, const QByteArray& input = {},
                     const QProcessEnvironment& environment = {}) {
  QProcess p;
  // English messages whatever the machine's locale, so tests can match them
  QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
  env.insert(QStringLiteral("LC_ALL"), QStringLiteral("C"));
  env.insert(QStringLiteral("LANG"), QStringLiteral("C"));
  env.insert(environment);
  p.setProcessEnvironment(env);
  p.start(QStringLiteral(MICROSIM_CLI_PATH), args);
  CliRun r;
  if (!input.isEmpty()) {
    if (!p.waitForStarted()) return r;
    p.write(input);
  }
  p.closeWriteChannel();
  if (!p.waitForFinished(timeoutMs)) {
    p.kill();
    p.waitForFinished();
    return r;
  }
  r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2;
  r.out = QString::fromUtf8(p.readAllStandardOutput());
  r.err = QString::fromUtf8(p.readAllStandardError());
  return r;
}

}  // namespace microsim::testing
