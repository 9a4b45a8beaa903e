#pragma once
// Every parser of outside input, as a fuzz target: a function that takes arbitrary bytes,
// must never crash, hang or leak, and aborts when a property the parser promises is broken
// (a decoded recording re-encodes to the same frames; the tracker decoder gives the same
// messages however the bytes are split into reads).
//
// The same functions serve two builds: libFuzzer executables (tests/fuzz/fuzz_entry.cpp,
// preset `fuzz`, clang) explore new inputs, and the ordinary test suite replays every file
// of tests/fuzz/corpus/<target>/ (seeds and the inputs of past crashes) through them, so a
// fixed crash stays fixed in every build.

#include <cstddef>
#include <cstdint>
#include <span>

namespace microsim::fuzz {

using TargetFunction = int (*)(const std::uint8_t* data, std::size_t size);

struct Target {
  const char* name;  ///< also the corpus folder tests/fuzz/corpus/<name>/
  TargetFunction run;
};

/// Every target, in a fixed order.
std::span<const Target> targets();

// the targets, one per parser
int fuzzSceneFile(const std::uint8_t* data, std::size_t size);
int fuzzSpringScene(const std::uint8_t* data, std::size_t size);
int fuzzRecording(const std::uint8_t* data, std::size_t size);
int fuzzIgtlStream(const std::uint8_t* data, std::size_t size);
int fuzzRubric(const std::uint8_t* data, std::size_t size);
int fuzzSetupProfile(const std::uint8_t* data, std::size_t size);
int fuzzLesson(const std::uint8_t* data, std::size_t size);

/// Stops the process with a message when a promised property does not hold (a finding).
[[noreturn]] void propertyBroken(const char* target, const char* what);

}  // namespace microsim::fuzz
