#include "gui/save_file.h"

#include <QFileInfo>

namespace microsim::gui {

SaveFile::SaveFile(const QString& path) : save_(path), inPlace_(path) {
  const QFileInfo target(path);  // follows symbolic links, as QSaveFile does
  writeInPlace_ = target.exists() && !target.isFile();
}

QFileDevice& SaveFile::file() { return writeInPlace_ ? static_cast<QFileDevice&>(inPlace_) : save_; }

bool SaveFile::open(QString& why) {
  if (file().open(QIODevice::WriteOnly)) return true;
  why = file().errorString();
  return false;
}

bool SaveFile::commit(QString& why) {
  // a write that failed earlier (its bytes dropped) leaves error() set even when the last
  // flush has nothing left to write
  bool ok = file().flush() && file().error() == QFileDevice::NoError;
  if (ok && writeInPlace_) {
    inPlace_.close();
    ok = inPlace_.error() == QFileDevice::NoError;
  } else if (ok) {
    ok = save_.commit();
  }
  if (!ok) {
    why = file().errorString();
    cancel();
  }
  return ok;
}

void SaveFile::cancel() {
  if (writeInPlace_)
    inPlace_.close();
  else
    save_.cancelWriting();
}

}  // namespace microsim::gui
