#pragma once
// The golden state hash of resources/recordings/stitch.msrec replayed on
// resources/scenes/anastomosis.json, and the scores that replay earns on two shipped rubrics,
// in one place for every suite that checks them (the engine, the scoring library,
// `microsim-cli run` and `score`, the GUI's simulation thread and lesson flow). They change, on
// purpose, when a solver's or a metric's arithmetic changes: update them here, with the reason
// in the commit message. They must never change between runs, build types or compilers.
#include <cstdint>

namespace microsim::testing {

inline constexpr std::uint64_t kGoldenStitchHash = 0x9e1ac70b2dcaabf5ULL;
inline constexpr const char* kGoldenStitchHashText = "9e1ac70b2dcaabf5";

/// The stitch's score on resources/rubrics/02_needle_entry.json (lesson 2) and on
/// 03_single_stitch.json (lesson 3). The GUI's lesson flow and `microsim-cli score` are each
/// held to these, so they agree with each other.
inline constexpr double kGoldenStitchScoreNeedleEntry = 95.12411211302032;
inline constexpr double kGoldenStitchScoreSingleStitch = 48.46959211870074;

/// The state hash of resources/recordings/back_wall_catch.msrec replayed on the same scene,
/// and its score on 03_single_stitch.json: 0, the back-wall catch being a never-event.
inline constexpr std::uint64_t kGoldenBackWallCatchHash = 0x54489014e9fc1f94ULL;

}  // namespace microsim::testing
