#include "cli/output_file.h"

namespace microsim::cli {

bool closeOutputFile(QFile& file, QString& error) {
  // an error from an earlier write() stays in error() until unsetError()
  const bool flushed = file.flush() && file.error() == QFileDevice::NoError;
  if (!flushed) error = file.errorString();
  file.close();
  if (flushed && file.error() != QFileDevice::NoError) {
    error = file.errorString();
    return false;
  }
  return flushed;
}

bool writeOutputFile(const QString& path, const QByteArray& bytes, QString& error) {
  QFile file(path);
  if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate)) {
    error = file.errorString();
    return false;
  }
  if (file.write(bytes) != bytes.size()) {
    error = file.errorString();
    file.close();
    return false;
  }
  return closeOutputFile(file, error);
}

int writeCommandOutput(const CommandLine& line, const QString& path, const QByteArray& bytes) {
  QString why;
  if (!writeOutputFile(path, bytes, why)) return line.failure(Cli::tr("cannot write %1: %2").arg(path, why));
  return kExitOk;
}

}  // namespace microsim::cli
