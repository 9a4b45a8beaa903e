#include "microsim/sim/scene/recorded_scene.h"

#include "microsim/sim/solve/state_hash.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace microsim::sim {
namespace {

namespace fs = std::filesystem;

// a fresh folder per test, removed after it
class RecordedSceneFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() /
            ("microsim-recorded-scene-" + std::to_string(::getpid()) + "-" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(root_);
    fs::create_directories(root_);
  }
  void TearDown() override { fs::remove_all(root_); }

  std::string write(const std::string& relative, const std::string& text) {
    const fs::path p = root_ / relative;
    fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }
  std::string at(const std::string& relative) const { return (root_ / relative).string(); }

  fs::path root_;
};

TEST_F(RecordedSceneFiles, ADigestIsFnv1aOfTheFilesBytes) {
  const std::string text = R"({"objects": []})";
  const std::string path = write("a.json", text);
  EXPECT_EQ(sceneFileDigest(path), fnv1a64(text.data(), text.size()));
  EXPECT_EQ(sceneFileDigest(write("empty.json", "")), fnv1a64(nullptr, 0));
  EXPECT_NE(sceneFileDigest(write("b.json", text + " ")), sceneFileDigest(path));
  EXPECT_EQ(sceneFileDigest(at("none.json")), std::nullopt);
  EXPECT_EQ(sceneFileDigest(root_.string()), std::nullopt);  // a folder
}

TEST_F(RecordedSceneFiles, RecordingASceneNamesItAbsoluteWithItsDigest) {
  const std::string path = write("scenes/a.json", "{}");
  const fs::path before = fs::current_path();
  fs::current_path(root_);
  const RecordedScene relative = recordScene("scenes/../scenes/a.json");
  fs::current_path(before);
  EXPECT_EQ(relative.path, path);
  EXPECT_EQ(relative.digest, fnv1a64("{}", 2));
  EXPECT_TRUE(relative.known());
  EXPECT_EQ(recordScene(path), relative);
  EXPECT_EQ(recordScene(at("none.json")).digest, 0u);
}

TEST_F(RecordedSceneFiles, TheSceneIsFoundWhereItWasBesideTheRecordingOrInAFolder) {
  const std::string text = R"({"name": "a"})";
  const std::string original = write("scenes/a.json", text);
  const RecordedScene recorded = recordScene(original);
  const std::string recording = at("attempts/1.msrec");
  const std::vector<std::string> shipped = {at("shipped")};

  // where it was
  SceneLocation found = locateRecordedScene(recorded, recording, shipped);
  EXPECT_EQ(found.match, SceneMatch::Same);
  EXPECT_EQ(found.path, original);
  EXPECT_EQ(found.looked,
            (std::vector<std::string>{original, at("attempts/a.json"), at("shipped/a.json")}));

  // moved among the shipped scenes
  fs::remove(original);
  const std::string inShipped = write("shipped/a.json", text);
  found = locateRecordedScene(recorded, recording, shipped);
  EXPECT_EQ(found.match, SceneMatch::Same);
  EXPECT_EQ(found.path, inShipped);

  // kept beside the recording: looked at before the folders
  const std::string beside = write("attempts/a.json", text);
  found = locateRecordedScene(recorded, recording, shipped);
  EXPECT_EQ(found.match, SceneMatch::Same);
  EXPECT_EQ(found.path, beside);
}

TEST_F(RecordedSceneFiles, TheSameBytesWinOverAnEditedFileOfTheSameName) {
  const std::string original = write("scenes/a.json", "{}");
  const RecordedScene recorded = recordScene(original);
  const std::string recording = at("attempts/1.msrec");

  // edited in place, a copy of the original in a folder: the copy is the scene
  write("scenes/a.json", R"({"edited": true})");
  const std::string copy = write("shipped/a.json", "{}");
  SceneLocation found = locateRecordedScene(recorded, recording, {at("shipped")});
  EXPECT_EQ(found.match, SceneMatch::Same);
  EXPECT_EQ(found.path, copy);

  // no copy: the edited file, said to be changed
  fs::remove(copy);
  found = locateRecordedScene(recorded, recording, {at("shipped")});
  EXPECT_EQ(found.match, SceneMatch::Changed);
  EXPECT_EQ(found.path, original);

  // a digest that is not known takes the first file there is
  found = locateRecordedScene({original, 0}, recording, {});
  EXPECT_EQ(found.match, SceneMatch::Same);
  EXPECT_EQ(found.path, original);
}

TEST_F(RecordedSceneFiles, ASceneInNoPlaceIsMissingAndSaysWhereItLooked) {
  const RecordedScene recorded{at("scenes/a.json"), 7};
  const SceneLocation found = locateRecordedScene(recorded, at("attempts/1.msrec"), {at("one"), at("two")});
  EXPECT_EQ(found.match, SceneMatch::Missing);
  EXPECT_TRUE(found.path.empty());
  EXPECT_EQ(found.looked, (std::vector<std::string>{at("scenes/a.json"), at("attempts/a.json"), at("one/a.json"),
                                                    at("two/a.json")}));

  // the same place twice is looked at once
  EXPECT_EQ(locateRecordedScene(recorded, at("scenes/1.msrec"), {at("scenes")}).looked,
            std::vector<std::string>{at("scenes/a.json")});

  // a recording that names no scene looks nowhere
  const SceneLocation unnamed = locateRecordedScene({}, at("attempts/1.msrec"), {at("one")});
  EXPECT_EQ(unnamed.match, SceneMatch::Missing);
  EXPECT_TRUE(unnamed.looked.empty());
}

}  // namespace
}  // namespace microsim::sim
