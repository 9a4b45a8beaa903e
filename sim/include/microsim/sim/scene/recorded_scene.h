#pragma once
// The scene a recording was made on, named when recording and found again when replaying.
//
// A recording names its scene file by the absolute path it had and by a digest of its bytes
// (recording.h). Files move: a recording is mailed, a build tree is deleted, a package
// installs the scenes elsewhere. So a replay looks in order at
//   1. the recorded path itself,
//   2. a file of the same name beside the recording (a recording kept with its scene),
//   3. a file of the same name in each of the given folders (the shipped resources/scenes),
// and takes the first whose bytes have the recorded digest: the same scene, wherever it is.
// When none has it, the first that exists is taken and reported Changed (the scene was
// edited since, and the replay may differ from the attempt); when none exists, Missing.
// A recording whose digest is not known (0) takes the first that exists as Same. The digest
// covers the scene file's own bytes, not the meshes it names.

#include "microsim/sim/scene/recording.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace microsim::sim {

/// FNV-1a 64 of the file's bytes; nullopt when it cannot be read.
std::optional<std::uint64_t> sceneFileDigest(const std::string& path);

/// What a recording stores of the scene file at `path`: the path made absolute (against the
/// working folder) and the digest of its bytes now (0 when it cannot be read).
RecordedScene recordScene(const std::string& path);

enum class SceneMatch : std::uint8_t {
  Same,     ///< a file with the recorded bytes (or any file, when the digest is not known)
  Changed,  ///< a file of the recorded name whose bytes differ: edited since
  Missing,  ///< no file of the recorded name in any place looked at
};

struct SceneLocation {
  SceneMatch match = SceneMatch::Missing;
  std::string path;                 ///< the file found; empty when Missing
  std::vector<std::string> looked;  ///< every place looked at, in order
};

/// Where the recorded `scene` is now (see the top of this file); `recordingPath` is the
/// recording's own file, `folders` more places to look, in order.
SceneLocation locateRecordedScene(const RecordedScene& scene, const std::string& recordingPath,
                                  const std::vector<std::string>& folders);

}  // namespace microsim::sim
