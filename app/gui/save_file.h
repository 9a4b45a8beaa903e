#pragma once
// An export file written whole or not at all, and whose failure shows. A regular or new
// file goes through a QSaveFile (a temporary file renamed over the target when complete).
// A target that exists and is not a regular file (/dev/full, a FIFO, a terminal) is
// written in place and never replaced: QSaveFile would rename its temporary file over it,
// which succeeds as root and puts a regular file where the device was. QFileDevice buffers
// writes and drops a failed final flush on close, so commit() flushes and checks itself.

#include <QFile>
#include <QSaveFile>
#include <QString>

namespace microsim::gui {

class SaveFile {
 public:
  explicit SaveFile(const QString& path);
  /// Opens for writing; on failure `why` is the system's reason.
  bool open(QString& why);
  QIODevice* device() { return &file(); }
  /// Flushes and puts the file in place; on failure discards what was written and sets
  /// `why` to the system's reason ("No space left on device").
  bool commit(QString& why);
  /// Discards what was written (a temporary file is removed).
  void cancel();

 private:
  QFileDevice& file();

  QSaveFile save_;
  QFile inPlace_;
  bool writeInPlace_ = false;
};

}  // namespace microsim::gui
