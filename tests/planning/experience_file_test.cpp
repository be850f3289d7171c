// The experience file: a save and a load give bit-identical experiences; a bad file is refused
// with its name and line, and nothing half-read comes back; a failed save leaves the old file.
#include <gtest/gtest.h>

#include <fstream>

#include "ringlet/hal/splitmix64.hpp"
#include "ringlet/planning/experience_file.hpp"
#include "temp_dir.hpp"

namespace ringlet::planning {
namespace {

std::vector<Experience> random_experiences(std::size_t n, std::uint64_t seed) {
  hal::SplitMix64 rng(seed);
  auto unit = [&] { return static_cast<double>(rng.next() >> 11) * 0x1p-53; };  // all 53 bits used
  std::vector<Experience> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    Experience& e = out[i];
    for (double& f : e.features) f = unit();
    e.features[kDiagonal] = static_cast<double>(rng.below(2));
    e.features[kFrom] = 3.0 / 64.0;
    e.commanded_speed = 2.0 * unit();
    e.achieved_speed = 1.0 / 3.0 + unit();
    e.duration_s = 0.1 + unit();
    e.frame = rng.next();
    e.time_ns = static_cast<std::int64_t>(rng.next() >> 1) * (i % 2 == 0 ? 1 : -1);
  }
  return out;
}

void write(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

std::string file_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

/// The head of a valid file and one valid line (frame … then 11 features).
const std::string kHead =
    "ringlet-experiences 1\n"
    "frame time_ns duration_s commanded_speed achieved_speed diagonal from to from_left from_right to_left "
    "to_right behind ahead corner_left corner_right\n";
const std::string kLine = "7 700 0.5 2 1.25 0 0 0.25 0 0 0 0 0 0 0 1\n";

std::string load_error(const std::filesystem::path& p) {
  try {
    (void)load_experiences(p);
  } catch (const ExperienceFileError& e) {
    return e.what();
  }
  return "(loaded)";
}

TEST(ExperienceFile, SaveThenLoadGivesTheSameBits) {
  test::TempDir dir("learn_experience");
  const auto experiences = random_experiences(500, 7);
  save_experiences(dir / "e.txt", experiences);
  EXPECT_EQ(load_experiences(dir / "e.txt"), experiences);
  save_experiences(dir / "empty.txt", {});
  EXPECT_TRUE(load_experiences(dir / "empty.txt").empty());
}

TEST(ExperienceFile, AValidHandWrittenFileLoads) {
  test::TempDir dir("learn_experience");
  write(dir / "ok.txt", kHead + kLine + "\n" + kLine);  // a blank line is allowed
  const auto e = load_experiences(dir / "ok.txt");
  ASSERT_EQ(e.size(), 2U);
  EXPECT_EQ(e[0].frame, 7U);
  EXPECT_EQ(e[0].time_ns, 700);
  EXPECT_EQ(e[0].achieved_speed, 1.25);
  EXPECT_EQ(e[0].features[kTo], 0.25);
  EXPECT_EQ(e[0].features[kCornerRight], 1.0);
}

TEST(ExperienceFile, BadFilesAreRefusedNamingFileAndLine) {
  test::TempDir dir("learn_experience");
  const auto p = dir / "bad.txt";
  struct Case {
    std::string text, message;
  };
  const std::vector<Case> cases{
      {"", "bad.txt:1: empty file"},
      {"frame,time\n", "bad.txt:1: not an experience file"},
      {"ringlet-experiences 2\n", "bad.txt:1: format version 2, this program reads version 1"},
      {"ringlet-experiences 1\nframe time_ns\n", "bad.txt:2: the columns are not this version's"},
      {kHead + kLine + "7 700 0.5 2 1.25 0 0\n", "bad.txt:4: expected 16 fields, got 7"},
      {kHead + kLine + kLine.substr(0, kLine.size() - 1) + " 0\n", "bad.txt:4: expected 16 fields, got more"},
      {kHead + "7 700 0.5 2 fast 0 0 0.25 0 0 0 0 0 0 0 1\n", "bad.txt:3: column achieved_speed: expected a number, got \"fast\""},
      {kHead + "7 700 0.5 2 1.25 0 0 1.5 0 0 0 0 0 0 0 1\n", "bad.txt:3: column to: 1.5 is outside [0, 1]"},
      {kHead + "7 700 0.5 2 1.25 0.5 0 0 0 0 0 0 0 0 0 1\n", "bad.txt:3: column diagonal: 0.5 is neither 0 nor 1"},
      {kHead + "7 700 0 2 1.25 0 0 0 0 0 0 0 0 0 0 1\n", "bad.txt:3: column duration_s: 0 is not a positive time"},
      {kHead + "7 700 0.5 nan 1.25 0 0 0 0 0 0 0 0 0 0 1\n", "bad.txt:3: column commanded_speed: nan is not finite"},
      {kHead + "-7 700 0.5 2 1.25 0 0 0 0 0 0 0 0 0 0 1\n", "bad.txt:3: column frame: expected a number"},
  };
  for (const Case& c : cases) {
    write(p, c.text);
    EXPECT_NE(load_error(p).find(c.message), std::string::npos) << "got: " << load_error(p) << "\nfor:\n" << c.text;
  }
  EXPECT_NE(load_error(dir / "missing.txt").find("missing.txt: cannot open the file"), std::string::npos);
}

TEST(ExperienceFile, ARefusedSaveLeavesTheOldFile) {
  test::TempDir dir("learn_experience");
  const auto p = dir / "e.txt";
  save_experiences(p, random_experiences(3, 1));
  const std::string before = file_text(p);
  auto bad = random_experiences(3, 2);
  bad[2].features[kAhead] = 2.0;  // not a fraction
  try {
    save_experiences(p, bad);
    ADD_FAILURE() << "saved an experience the loader would refuse";
  } catch (const ExperienceFileError& e) {
    EXPECT_NE(std::string(e.what()).find("refusing to write experience 2"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("column ahead: 2 is outside [0, 1]"), std::string::npos) << e.what();
  }
  EXPECT_EQ(file_text(p), before);
}

}  // namespace
}  // namespace ringlet::planning
