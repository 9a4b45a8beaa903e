#pragma once
// Output files written whole or reported as failed. QFile buffers: on a full disk (ENOSPC)
// write() still returns the byte count and the error only shows when the buffer is
// flushed, which QFile's destructor does silently. Every command's --json, --record and
// export output goes through here so that a full disk is an error, never a success.
#include "cli/command_line.h"

#include <QByteArray>
#include <QFile>
#include <QString>

namespace microsim::cli {

/// Replaces `path` with `bytes`. False, with `error` set to the system's reason, when the
/// file could not be opened or any byte could not be written.
bool writeOutputFile(const QString& path, const QByteArray& bytes, QString& error);

/// Flushes and closes an output file that was written piecewise. False, with `error`
/// set, when a write already failed or a buffered byte could not be written.
bool closeOutputFile(QFile& file, QString& error);

/// writeOutputFile for a command's --json (or other) output: kExitOk, or kExitFailure after
/// printing "cannot write PATH: reason" through `line`.
int writeCommandOutput(const CommandLine& line, const QString& path, const QByteArray& bytes);

}  // namespace microsim::cli
