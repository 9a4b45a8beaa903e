#pragma once
// The golden state hash of resources/recordings/stitch.msrec replayed on
// resources/scenes/anastomosis.json, in one place for every suite that checks it (the engine,
// `microsim-cli run`, the GUI's simulation thread). It changes, on purpose, when a solver's
// arithmetic changes: update it here, with the reason in the commit message. It must never
// change between runs or build types.
#include <cstdint>

namespace microsim::testing {

inline constexpr std::uint64_t kGoldenStitchHash = 0x3b9962f2cdf9ab3aULL;
inline constexpr const char* kGoldenStitchHashText = "3b9962f2cdf9ab3a";

}  // namespace microsim::testing
