#include "cli/recording_text.h"

namespace microsim::cli {

QString recordingErrorText(sim::RecordingError e) {
  using E = sim::RecordingError;
  switch (e) {
    case E::None:
      return {};
    case E::CannotOpen:
      return Cli::tr("cannot open the recording");
    case E::CannotWrite:
      return Cli::tr("cannot write the recording");
    case E::NotARecording:
      return Cli::tr("not a microsim recording");
    case E::UnsupportedVersion:
      return Cli::tr("recording from a newer version");
    case E::Truncated:
      return Cli::tr("unfinished recording (no end record)");
    case E::ChecksumMismatch:
      return Cli::tr("damaged recording (checksum mismatch)");
    case E::Malformed:
      return Cli::tr("damaged recording (malformed frame)");
  }
  return {};
}

}  // namespace microsim::cli
