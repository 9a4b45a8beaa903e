// Every file of the fuzz corpus (seeds and the inputs of past crashes) through its target,
// in the ordinary build and under the sanitizer presets: a crash found once stays fixed.
#include "fuzz/fuzz_targets.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace microsim::fuzz {
namespace {

const std::filesystem::path kCorpus = std::filesystem::path(MICROSIM_SOURCE_DIR) / "tests/fuzz/corpus";

std::vector<std::uint8_t> readBytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(FuzzCorpus, EveryTargetHasSeedsAndEverySeedRunsClean) {
  for (const Target& target : targets()) {
    SCOPED_TRACE(target.name);
    const std::filesystem::path folder = kCorpus / target.name;
    ASSERT_TRUE(std::filesystem::is_directory(folder)) << folder;
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
      if (!entry.is_regular_file()) continue;
      const std::vector<std::uint8_t> bytes = readBytes(entry.path());
      SCOPED_TRACE(entry.path().filename().string());
      EXPECT_EQ(target.run(bytes.data(), bytes.size()), 0);
      ++files;
    }
    EXPECT_GE(files, 3) << "a target needs seeds to start from";
  }
}

TEST(FuzzCorpus, TargetsTakeEmptyAndTinyInputs) {
  const std::uint8_t one = 0xff;
  for (const Target& target : targets()) {
    SCOPED_TRACE(target.name);
    EXPECT_EQ(target.run(nullptr, 0), 0);
    EXPECT_EQ(target.run(&one, 1), 0);
  }
}

}  // namespace
}  // namespace microsim::fuzz
