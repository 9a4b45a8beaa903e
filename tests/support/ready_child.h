#pragma once
// A child process of the running test binary, for tests that kill a program mid-way: it runs
// one disabled test of the same binary (with --gtest_also_run_disabled_tests), which prints
// "ready <number>" on stdout once it has reached the state to interrupt, then blocks. The
// parent reads the number and kills it.
#include <QCoreApplication>
#include <QProcess>
#include <QStringList>

#include <optional>
#include <string>

namespace microsim::testing {

/// Starts `child` on `gtestFilter` with `environment` and waits (up to `timeoutMs` between
/// reads) for its "ready <number>" line; nullopt, with what it printed in `output`, when
/// it never came.
inline std::optional<qint64> startReadyChild(QProcess& child, const QString& gtestFilter,
                                             const QProcessEnvironment& environment, int timeoutMs,
                                             std::string* output) {
  child.setProcessEnvironment(environment);
  child.start(QCoreApplication::applicationFilePath(),
              {QStringLiteral("--gtest_filter=") + gtestFilter, QStringLiteral("--gtest_also_run_disabled_tests")});
  if (!child.waitForStarted()) return std::nullopt;
  QByteArray out;
  const auto readyLine = [&out] { return out.contains("ready ") && out.indexOf('\n', out.indexOf("ready ")) > 0; };
  while (!readyLine() && child.waitForReadyRead(timeoutMs)) out += child.readAllStandardOutput();
  const QByteArray ready = out.mid(out.indexOf("ready "));
  if (!ready.startsWith("ready ")) {
    if (output) *output = (out + child.readAllStandardError()).toStdString();
    return std::nullopt;
  }
  return ready.mid(6).trimmed().toLongLong();
}

}  // namespace microsim::testing
