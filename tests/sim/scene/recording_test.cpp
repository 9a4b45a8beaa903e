#include "microsim/sim/scene/recording.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <span>

namespace microsim::sim {
namespace {

InputFrame frameAt(int i) {
  InputFrame f;
  f.time = 0.01 * i;
  for (int h = 0; h < kHandCount; ++h) {
    HandInput& hand = f.hands[h];
    hand.instrument = h == 0 ? Instrument::Forceps : Instrument::NeedleHolder;
    hand.tracked = i % 7 != 3;
    hand.position = Eigen::Vector3d(std::sin(0.1 * i) + h, 0.3 * h, -0.01 * i);
    hand.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.05 * i, Eigen::Vector3d::UnitZ()));
    hand.closure = 0.5 + 0.5 * std::sin(0.2 * i + h);
  }
  return f;
}

Recording sample(int frames) {
  Recording r;
  r.scene = {"/data/scenes/two-ends.json", 0x0123456789abcdefULL};
  r.metadata = R"({"lesson":3})";
  for (int i = 0; i < frames; ++i) r.frames.push_back(frameAt(i));
  return r;
}

std::string tempPath(const char* name) {
  return (std::filesystem::temp_directory_path() / (std::string("microsim-") + name + "-" +
                                                    std::to_string(::getpid()))).string();
}

TEST(Recording, RoundTripIsBitExact) {
  const Recording r = sample(250);
  const std::vector<std::uint8_t> bytes = encodeRecording(r);
  Recording back;
  const RecordingStatus s = decodeRecording(bytes, back);
  ASSERT_TRUE(s.ok()) << static_cast<int>(s.error);
  EXPECT_EQ(back.scene, r.scene);
  EXPECT_EQ(back.metadata, r.metadata);
  ASSERT_EQ(back.frames.size(), r.frames.size());
  for (std::size_t i = 0; i < r.frames.size(); ++i) EXPECT_EQ(back.frames[i], r.frames[i]) << i;
  EXPECT_EQ(encodeRecording(back), bytes);
}

TEST(Recording, WriterStreamsTheSameBytesAsTheEncoder) {
  const Recording r = sample(300);
  const std::string path = tempPath("writer");
  RecordingWriter w;
  ASSERT_TRUE(w.open(path, r.scene, r.metadata).ok());
  for (const InputFrame& f : r.frames) ASSERT_TRUE(w.append(f).ok());
  EXPECT_EQ(w.frameCount(), 300u);
  ASSERT_TRUE(w.finish().ok());

  Recording back;
  ASSERT_TRUE(readRecording(path, back).ok());
  EXPECT_EQ(back.scene, r.scene);
  EXPECT_EQ(back.frames, r.frames);
  std::remove(path.c_str());
}

TEST(Recording, TheHeaderNamesTheSceneBeforeTheMetadata) {
  Recording r = sample(3);
  r.scene = {"/s/a.json", 0x1122334455667788ULL};
  r.metadata = "m";
  const std::vector<std::uint8_t> bytes = encodeRecording(r);
  // magic, version 2, hands, the scene's length and path, its digest, the metadata's length and bytes
  ASSERT_GT(bytes.size(), 40u);
  EXPECT_EQ(bytes[8], 2);
  EXPECT_EQ(bytes[9], 0);
  EXPECT_EQ(bytes[12], 9);  // "/s/a.json"
  EXPECT_EQ(std::string(bytes.begin() + 16, bytes.begin() + 25), "/s/a.json");
  EXPECT_EQ(bytes[25], 0x88);
  EXPECT_EQ(bytes[32], 0x11);
  EXPECT_EQ(bytes[33], 1);  // "m"
  EXPECT_EQ(bytes[37], 'm');
  EXPECT_EQ(bytes[38], 'F');

  // a header cut inside the scene's path or digest is an unfinished file, not a damaged one
  Recording back;
  for (std::size_t cut : {std::size_t{14}, std::size_t{20}, std::size_t{28}})
    EXPECT_EQ(decodeRecording(std::span(bytes).first(cut), back).error, RecordingError::Truncated) << cut;

  // no scene known: an empty path, digest 0
  r.scene = {};
  ASSERT_TRUE(decodeRecording(encodeRecording(r), back).ok());
  EXPECT_FALSE(back.scene.known());
  EXPECT_EQ(back.scene.digest, 0u);
}

// resources/recordings/stitch.msrec was written in version 1 (no scene in its header) and is
// kept byte for byte: golden hashes replay it
TEST(Recording, AVersion1RecordingIsStillReadAndNamesNoScene) {
  const std::string path = std::string(MICROSIM_SOURCE_DIR) + "/resources/recordings/stitch.msrec";
  std::ifstream in(path, std::ios::binary);
  const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(bytes.size(), 1000u);
  ASSERT_EQ(bytes[8], 1) << "the shipped stitch is the version-1 sample";

  Recording old;
  const RecordingStatus s = decodeRecording(bytes, old);
  ASSERT_TRUE(s.ok()) << static_cast<int>(s.error);
  EXPECT_FALSE(old.scene.known());
  EXPECT_EQ(old.metadata, R"({"script":"stitch","version":1})");
  EXPECT_GT(old.frames.size(), 400u);

  // written again it becomes version 2 with the same frames and metadata
  old.scene = {"/anywhere/anastomosis.json", 42};
  const std::vector<std::uint8_t> again = encodeRecording(old);
  EXPECT_EQ(again[8], kRecordingVersion);
  Recording back;
  ASSERT_TRUE(decodeRecording(again, back).ok());
  EXPECT_EQ(back.scene, old.scene);
  EXPECT_EQ(back.metadata, old.metadata);
  EXPECT_EQ(back.frames, old.frames);
  EXPECT_EQ(again.size(), bytes.size() + 4 + old.scene.path.size() + 8);
}

TEST(Recording, AnUnfinishedAttemptKeepsItsCompleteFrames) {
  const Recording r = sample(500);
  const std::string path = tempPath("unfinished");
  Recording back;
  {
    RecordingWriter w;
    ASSERT_TRUE(w.open(path, r.scene, r.metadata).ok());
    for (std::size_t i = 0; i < r.frames.size(); ++i) {
      ASSERT_TRUE(w.append(r.frames[i]).ok());
      // what a process killed now would leave (its stdio buffer lost): every frame older
      // than 0.1 s of attempt time is on disk
      const RecordingStatus now = readRecording(path, back);
      ASSERT_EQ(now.error, RecordingError::Truncated) << i;
      const std::size_t kept = back.frames.size();
      ASSERT_LE(kept, i + 1);
      if (kept <= i) {
        ASSERT_GT(r.frames[kept].time, r.frames[i].time - 0.1) << "frame " << i << ": only " << kept << " on disk";
      }
      for (std::size_t k = 0; k < kept; ++k) ASSERT_EQ(back.frames[k], r.frames[k]) << i;
    }
    // destroyed without finish(): the app crashed mid-attempt
  }
  const RecordingStatus s = readRecording(path, back);
  EXPECT_EQ(s.error, RecordingError::Truncated);
  EXPECT_EQ(back.frames, r.frames);
  std::remove(path.c_str());

  // cut in the middle of a frame: everything before the cut survives
  std::vector<std::uint8_t> bytes = encodeRecording(r);
  bytes.resize(bytes.size() / 2);
  EXPECT_EQ(decodeRecording(bytes, back).error, RecordingError::Truncated);
  EXPECT_GT(back.frames.size(), 200u);
  for (std::size_t i = 0; i < back.frames.size(); ++i) EXPECT_EQ(back.frames[i], r.frames[i]);
}

TEST(Recording, DamageIsDetected) {
  const std::vector<std::uint8_t> good = encodeRecording(sample(50));
  std::vector<std::uint8_t> bad = good;
  bad[bad.size() / 2] ^= 0x01;  // one bit inside a frame's value
  Recording back;
  EXPECT_EQ(decodeRecording(bad, back).error, RecordingError::ChecksumMismatch);

  std::vector<std::uint8_t> foreign(good.begin(), good.end());
  foreign[0] = 'X';
  EXPECT_EQ(decodeRecording(foreign, back).error, RecordingError::NotARecording);

  std::vector<std::uint8_t> newer = good;
  newer[8] = kRecordingVersion + 1;
  EXPECT_EQ(decodeRecording(newer, back).error, RecordingError::UnsupportedVersion);

  EXPECT_EQ(readRecording("/nonexistent/dir/x.msrec", back).error, RecordingError::CannotOpen);
}

TEST(Recording, GarbageNeverCrashesAndIsAlwaysRejected) {
  const std::vector<std::uint8_t> good = encodeRecording(sample(20));
  std::mt19937 rng(7);
  for (int trial = 0; trial < 3000; ++trial) {
    std::vector<std::uint8_t> bytes = good;
    // flip a few bytes and sometimes cut the tail
    const int flips = 1 + static_cast<int>(rng() % 4);
    for (int k = 0; k < flips; ++k) bytes[rng() % bytes.size()] = static_cast<std::uint8_t>(rng());
    if (rng() % 3 == 0) bytes.resize(rng() % bytes.size());
    if (bytes == good) continue;
    Recording back;
    const RecordingStatus s = decodeRecording(bytes, back);
    EXPECT_FALSE(s.ok()) << "trial " << trial;
    EXPECT_LE(s.offset, bytes.size());
    for (const InputFrame& f : back.frames) {
      InputRejection why;
      EXPECT_TRUE(validateFrame(f, why));
    }
  }
}

TEST(Recording, WriterRefusesInvalidFramesAndReportsAFullDisk) {
  const std::string path = tempPath("invalid");
  RecordingWriter w;
  ASSERT_TRUE(w.open(path, {}, "").ok());
  InputFrame f = frameAt(1);
  f.hands[0].position.x() = std::nan("");
  EXPECT_EQ(w.append(f).error, RecordingError::Malformed);
  EXPECT_EQ(w.frameCount(), 0u);
  ASSERT_TRUE(w.finish().ok());
  std::remove(path.c_str());

  if (std::filesystem::exists("/dev/full")) {
    RecordingWriter full;
    const RecordingStatus opened = full.open("/dev/full", {"/s/a.json", 1}, "metadata");
    EXPECT_EQ(opened.error, RecordingError::CannotWrite);
  }
}

TEST(InputFrame, ValidationNamesTheReason) {
  InputRejection why{};
  InputFrame f = frameAt(2);
  EXPECT_TRUE(validateFrame(f, why));

  f.hands[1].closure = 1.5;
  EXPECT_FALSE(validateFrame(f, why));
  EXPECT_EQ(why, InputRejection::ClosureOutOfRange);

  f = frameAt(2);
  f.hands[0].orientation = Eigen::Quaterniond(2, 0, 0, 0);
  EXPECT_FALSE(validateFrame(f, why));
  EXPECT_EQ(why, InputRejection::NotUnitRotation);

  f = frameAt(2);
  f.time = INFINITY;
  EXPECT_FALSE(validateFrame(f, why));
  EXPECT_EQ(why, InputRejection::NonFinite);

  f = frameAt(2);
  EXPECT_FALSE(validateSequence(f, 5.0, why));
  EXPECT_EQ(why, InputRejection::TimeBackwards);
  EXPECT_TRUE(validateSequence(f, f.time, why));
}

TEST(Crc32, MatchesTheStandardCheckValue) {
  const std::string check = "123456789";
  EXPECT_EQ(crc32({reinterpret_cast<const std::uint8_t*>(check.data()), check.size()}), 0xCBF43926u);
}

}  // namespace
}  // namespace microsim::sim
