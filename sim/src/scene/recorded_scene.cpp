#include "microsim/sim/scene/recorded_scene.h"

#include "microsim/sim/solve/state_hash.h"

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace microsim::sim {

namespace fs = std::filesystem;

std::optional<std::uint64_t> sceneFileDigest(const std::string& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::uint64_t digest = fnv1a64(nullptr, 0);  // the empty file's, continued chunk by chunk
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0)
    digest = fnv1a64(buffer, static_cast<std::size_t>(in.gcount()), digest);
  if (in.bad()) return std::nullopt;
  return digest;
}

RecordedScene recordScene(const std::string& path) {
  std::error_code ec;
  fs::path absolute = fs::absolute(path, ec);
  if (ec) absolute = path;
  return {absolute.lexically_normal().string(), sceneFileDigest(path).value_or(0)};
}

SceneLocation locateRecordedScene(const RecordedScene& scene, const std::string& recordingPath,
                                  const std::vector<std::string>& folders) {
  SceneLocation found;
  if (!scene.known()) return found;

  // the places, in order, each once
  const fs::path name = fs::path(scene.path).filename();
  std::vector<fs::path> places = {fs::path(scene.path), fs::path(recordingPath).parent_path() / name};
  for (const std::string& folder : folders) places.push_back(fs::path(folder) / name);
  for (const fs::path& place : places) {
    const std::string p = place.lexically_normal().string();
    if (std::find(found.looked.begin(), found.looked.end(), p) == found.looked.end()) found.looked.push_back(p);
  }

  // the first with the recorded bytes, else the first that exists
  for (const std::string& p : found.looked) {
    const std::optional<std::uint64_t> digest = sceneFileDigest(p);
    if (!digest) continue;
    if (scene.digest == 0 || *digest == scene.digest) {
      found.match = SceneMatch::Same;
      found.path = p;
      return found;
    }
    if (found.path.empty()) {
      found.match = SceneMatch::Changed;
      found.path = p;
    }
  }
  return found;
}

}  // namespace microsim::sim
