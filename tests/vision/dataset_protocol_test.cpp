// The honest-evaluation protocol end to end, with the real tools: ringlet-dataset sets drawn for
// tuning and for testing share no frame (compared by the decoded pictures' content), a frame is
// the same whichever run writes it (so a range is an identity), and ringlet-vision-eval refuses a
// tuning set that overlaps the test set — by seed and index, or by a copied picture.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "run_command.hpp"

namespace {

namespace fs = std::filesystem;

using ToolRun = ringlet::test::CommandRun;

ToolRun run(const std::string& command) { return ringlet::test::run_command(command + " 2>&1"); }

/// The decoded picture's bytes (not the file's: the same picture must match however it was
/// encoded), keyed by the file name.
std::map<std::string, std::string> pictures(const fs::path& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name.rfind("frame_", 0) != 0 || e.path().extension() != ".png" || name.find("_labels") != std::string::npos) continue;
    const cv::Mat m = cv::imread(e.path().string(), cv::IMREAD_COLOR);
    EXPECT_FALSE(m.empty()) << e.path();
    out[name] = std::string(reinterpret_cast<const char*>(m.data), m.total() * m.elemSize());
  }
  return out;
}

class DatasetProtocol : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = fs::temp_directory_path() / ("ringlet-protocol-" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_);
    // Tuning: seed 21 frames 0-3. Test: seed 22 frames 0-3. Continuation: seed 21 frames 4-5.
    // Overlap: seed 21 frames 2-4 (shares 2 and 3 with tuning).
    make("tune", "--seed 21 -n 4");
    make("test", "--seed 22 -n 4");
    make("next", "--seed 21 --first 4 -n 2");
    make("overlap", "--seed 21 --first 2 -n 3");
  }
  static void TearDownTestSuite() { fs::remove_all(root_); }

  static void make(const char* name, const std::string& flags) {
    const ToolRun r = run(std::string(RINGLET_DATASET_BIN) + " " + flags + " --no-labels -q -o " + (root_ / name).string());
    ASSERT_EQ(r.rc, 0) << r.out;
  }
  static ToolRun eval(const std::string& args) { return run(std::string(RINGLET_VISION_EVAL_BIN) + " -q " + args); }

  static inline fs::path root_;
};

TEST_F(DatasetProtocol, TuningAndTestSetsShareNoPicture) {
  const auto tune = pictures(root_ / "tune");
  const auto test = pictures(root_ / "test");
  const auto next = pictures(root_ / "next");
  ASSERT_EQ(tune.size(), 4U);
  ASSERT_EQ(test.size(), 4U);
  ASSERT_EQ(next.size(), 2U);
  std::set<std::string> seen;
  for (const auto& [name, pixels] : tune) seen.insert(pixels);
  for (const auto& [name, pixels] : test) EXPECT_EQ(seen.count(pixels), 0U) << "test " << name << " is a tuning picture";
  for (const auto& [name, pixels] : next) EXPECT_EQ(seen.count(pixels), 0U) << "next " << name << " is a tuning picture";
  EXPECT_EQ(seen.size(), 4U) << "the four tuning pictures differ";
}

// Frame i is the same picture whichever run wrote it: the old prefix property, now for any range.
TEST_F(DatasetProtocol, AFrameIsAPureFunctionOfSeedAndIndex) {
  const auto tune = pictures(root_ / "tune");
  const auto overlap = pictures(root_ / "overlap");
  ASSERT_EQ(overlap.size(), 3U);
  EXPECT_EQ(overlap.at("frame_0002.png"), tune.at("frame_0002.png"));
  EXPECT_EQ(overlap.at("frame_0003.png"), tune.at("frame_0003.png"));
  const nlohmann::json manifest = nlohmann::json::parse(std::ifstream(root_ / "overlap" / "manifest.json"));
  EXPECT_EQ(manifest.at("generation").at("seed"), 21);
  EXPECT_EQ(manifest.at("ranges"), nlohmann::json::parse("[[2, 5]]"));
}

TEST_F(DatasetProtocol, EvalAcceptsDisjointSetsAndNamesThem) {
  const ToolRun r = eval((root_ / "test").string() + " --tune-set " + (root_ / "tune").string() + " --disjoint-from " +
                     (root_ / "next").string());
  ASSERT_EQ(r.rc, 0) << r.out;
  EXPECT_NE(r.out.find("test set:   " + (root_ / "test").string() + ": 4 frames, seed 22 (generator v4) frames 0-3"),
            std::string::npos) << r.out;
  EXPECT_NE(r.out.find("tuning set: " + (root_ / "tune").string() + ": 4 frames, seed 21 (generator v4) frames 0-3"),
            std::string::npos) << r.out;
  EXPECT_NE(r.out.find("excluded:   " + (root_ / "next").string() + ": 2 frames, seed 21 (generator v4) frames 4-5"),
            std::string::npos) << r.out;
  EXPECT_NE(r.out.find("reported on the 4 test frames only"), std::string::npos) << r.out;
}

TEST_F(DatasetProtocol, EvalRefusesOverlappingSets) {
  const ToolRun same_draws = eval((root_ / "overlap").string() + " --tune-set " + (root_ / "tune").string());
  EXPECT_EQ(same_draws.rc, 2) << same_draws.out;
  EXPECT_NE(same_draws.out.find("the tuning set and the test set overlap: 2 frames of the test set have the seed and "
                                "index of a tuning set frame, 2 have identical pixels"),
            std::string::npos) << same_draws.out;
  EXPECT_EQ(same_draws.out.find("F1"), std::string::npos) << "nothing may be reported";

  // A tuning picture copied into the test set under a test frame's name and record.
  const fs::path copy = root_ / "copied";
  fs::create_directories(copy);
  fs::copy_file(root_ / "test" / "frame_0000.json", copy / "frame_0000.json", fs::copy_options::overwrite_existing);
  fs::copy_file(root_ / "tune" / "frame_0001.png", copy / "frame_0000.png", fs::copy_options::overwrite_existing);
  const ToolRun copied = eval(copy.string() + " --tune-set " + (root_ / "tune").string());
  EXPECT_EQ(copied.rc, 2) << copied.out;
  EXPECT_NE(copied.out.find("0 frames of the test set have the seed and index of a tuning set frame, 1 have identical "
                            "pixels (e.g. tuning set frame_0001.json and test set frame_0000.json have identical pixels)"),
            std::string::npos) << copied.out;

  // The same through --disjoint-from.
  const ToolRun excluded = eval((root_ / "overlap").string() + " --tune 1 --disjoint-from " + (root_ / "tune").string());
  EXPECT_EQ(excluded.rc, 2) << excluded.out;
  EXPECT_NE(excluded.out.find("the excluded set and the test set overlap"), std::string::npos) << excluded.out;
}

}  // namespace
