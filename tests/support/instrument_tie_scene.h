#pragma once
// The instrument-tie lesson's scene (resources/scenes/instrument_tie.json: a stay stitch
// already placed) with its thread in another number of links or its tail another length, for
// the stay-stitch tests: the loader lays the stitch on the thread as given (stay_stitch.h).
#include "microsim/sim/scene/scene_def.h"

#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <variant>

namespace microsim::testing {

/// The scene read from `sourceRoot`, its thread in `links` links (0: as shipped, 60) and its
/// tail `tailMm` long (0: as shipped, 2 mm); nullopt when it does not load.
inline std::optional<sim::SceneDef> instrumentTieScene(const std::string& sourceRoot, int links = 0,
                                                       double tailMm = 0.0) {
  const std::string folder = sourceRoot + "/resources/scenes/";
  std::ifstream in(folder + "instrument_tie.json");
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::string text = buffer.str();
  const auto replace = [&text](const std::string& shipped, const std::string& with) {
    const std::size_t at = text.find(shipped);
    if (at == std::string::npos) return false;
    text.replace(at, shipped.size(), with);
    return true;
  };
  if (links > 0 && !replace(R"("links": 60)", R"("links": )" + std::to_string(links)))
    return std::nullopt;
  if (tailMm > 0.0 && !replace(R"("tail_mm": 2.0)", R"("tail_mm": )" + std::to_string(tailMm)))
    return std::nullopt;
  sim::SceneDefLoad load = sim::parseSceneDef(text, folder + "instrument_tie.json", folder);
  if (!std::holds_alternative<sim::SceneDef>(load)) return std::nullopt;
  return std::get<sim::SceneDef>(std::move(load));
}

}  // namespace microsim::testing
