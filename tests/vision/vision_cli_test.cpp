// ringlet-vision, the command-line tool, on pictures the simulator rendered with known ground
// truth: as PNG (lines found, the ball found where it is, overlay written), as JPEG (what a real
// camera's photographs are: lossy, still works), and on a picture that is not a field at all
// (noise: must not crash, few or no lines); a tilted torso given by --body-pitch/--body-roll; bad
// images (truncated, grey) and absurd angles; the time per frame and --repeat's statistics.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <utility>
#include <vector>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "ringlet/sim_hal/camera_renderer.hpp"
#include "run_command.hpp"

namespace ringlet {
namespace {

namespace fs = std::filesystem;

using ToolRun = test::CommandRun;

enum class Capture { kStdout, kBoth, kStderr };

/// Runs ringlet-vision; `out` is what `capture` says (stdout; stdout and stderr; stderr only).
ToolRun run_capturing(const std::string& args, Capture capture) {
  const char* redirect = capture == Capture::kStdout ? " 2>/dev/null" : capture == Capture::kBoth ? " 2>&1" : " 2>&1 >/dev/null";
  const std::string command = std::string(RINGLET_VISION_BIN) + " " + args + redirect;
  return test::run_command(command);
}

/// Runs ringlet-vision; `out` is stdout, or stdout and stderr with `with_stderr`.
ToolRun run(const std::string& args, bool with_stderr = false) {
  return run_capturing(args, with_stderr ? Capture::kBoth : Capture::kStdout);
}

ToolRun run_stderr(const std::string& args) { return run_capturing(args, Capture::kStderr); }

class VisionCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("ringlet-vision-cli-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    sim_hal::CameraRenderer renderer(sim_hal::load_world(RINGLET_SIM_WORLDS_DIR "/spl_field.world"), sim_hal::CameraSpec{}, 3);
    // 1.5 m behind the ball (0.6, −0.3) looking along −x: the ball, the centre circle and the
    // centre line are in view.
    renderer.render({2.1, -0.3, -std::acos(0.0)}, {hal::deg_to_rad(yaw_deg_), hal::deg_to_rad(pitch_deg_)});
    truth_ = renderer.truth();
    ASSERT_TRUE(truth_.ball.visible);
    const cv::Mat bgr(480, 640, CV_8UC3, const_cast<std::uint8_t*>(renderer.bgr().data()));
    ASSERT_TRUE(cv::imwrite((dir_ / "frame.png").string(), bgr));
    ASSERT_TRUE(cv::imwrite((dir_ / "frame.jpg").string(), bgr, {cv::IMWRITE_JPEG_QUALITY, 85}));
  }
  void TearDown() override { fs::remove_all(dir_); }

  // The shipped SPL world draws the SPL's black-and-white ball ("look spl bw"): the tool's default
  // detector, verified by the shipped model, as a new user runs it.
  [[nodiscard]] std::string head_flags() const {
    return "--yaw " + std::to_string(yaw_deg_) + " --pitch " + std::to_string(pitch_deg_);
  }

  void expect_lines_and_ball(const std::string& image) {
    const ToolRun r = run((dir_ / image).string() + " " + head_flags() + " --compact");
    ASSERT_EQ(r.rc, 0) << r.out;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j.at("status"), "ok");
    EXPECT_GE(j.at("lines").size(), 2U) << r.out;
    ASSERT_TRUE(j.at("ball").at("seen").get<bool>()) << r.out;
    const auto& g = j.at("ball").at("ground");
    EXPECT_NEAR(g.at(0).get<double>(), truth_.ball.position.x, 0.15) << r.out;
    EXPECT_NEAR(g.at(1).get<double>(), truth_.ball.position.y, 0.15) << r.out;
  }

  fs::path dir_;
  double yaw_deg_ = 5.0;
  double pitch_deg_ = 22.0;
  sim_hal::FrameTruth truth_;
};

TEST_F(VisionCli, RenderedPngGivesLinesAndTheBallNearTheTruth) { expect_lines_and_ball("frame.png"); }

TEST_F(VisionCli, JpegOfTheSameFrameStillGivesLinesAndTheBall) { expect_lines_and_ball("frame.jpg"); }

TEST_F(VisionCli, OverlayIsWrittenAtTheImageSize) {
  const fs::path overlay = dir_ / "overlay.png";
  const ToolRun r = run((dir_ / "frame.png").string() + " " + head_flags() + " --overlay " + overlay.string());
  ASSERT_EQ(r.rc, 0) << r.out;
  const cv::Mat drawn = cv::imread(overlay.string());
  ASSERT_FALSE(drawn.empty());
  EXPECT_EQ(drawn.cols, 640);
  EXPECT_EQ(drawn.rows, 480);
}

// --candidates lists the scan lines' points in the JSON and draws them (magenta and cyan) over the
// overlay; the JSON also gives the local field luminance per colour cell: what a person needs to
// see why a line was missed.
TEST_F(VisionCli, CandidatesAndCellLuminanceShowWhatTheScanSaw) {
  const auto marked = [](const cv::Mat& m) {
    int n = 0;
    for (int y = 0; y < m.rows; ++y)
      for (int x = 0; x < m.cols; ++x) {
        const cv::Vec3b p = m.at<cv::Vec3b>(y, x);
        n += (p == cv::Vec3b(255, 0, 255) || p == cv::Vec3b(255, 255, 0)) ? 1 : 0;
      }
    return n;
  };
  const fs::path plain = dir_ / "plain.png", points = dir_ / "points.png";
  const ToolRun a = run((dir_ / "frame.png").string() + " " + head_flags() + " --compact --overlay " + plain.string());
  const ToolRun b = run((dir_ / "frame.png").string() + " " + head_flags() + " --compact --candidates --overlay " + points.string());
  ASSERT_EQ(a.rc, 0) << a.out;
  ASSERT_EQ(b.rc, 0) << b.out;
  const nlohmann::json j = nlohmann::json::parse(b.out);
  ASSERT_GT(j.at("candidates").get<int>(), 20);
  ASSERT_EQ(j.at("candidate_points").size(), j.at("candidates").get<std::size_t>());
  for (const auto& p : j.at("candidate_points")) {
    EXPECT_GE(p.at(1).get<double>(), j.at("horizon_row").get<double>()) << "every candidate lies below the horizon";
  }
  EXPECT_FALSE(nlohmann::json::parse(a.out).contains("candidate_points")) << "listed only when asked for";
  EXPECT_GT(marked(cv::imread(points.string())), marked(cv::imread(plain.string())) + j.at("candidates").get<int>());
  const nlohmann::json& cells = j.at("field_colour").at("cell_y");
  ASSERT_EQ(cells.size(), 8U);
  ASSERT_EQ(cells.at(7).size(), 8U);
  EXPECT_TRUE(cells.at(7).at(4).is_number()) << "the carpet fills the bottom row";
}

// Uniform RGB noise is the worst case: green-white-green runs occur by chance everywhere, and a
// few short chance alignments survive RANSAC (3 lines of 5–8 points measured). Known weakness,
// documented in vision/README.md; the test holds it to "a few", and to no crash.
TEST_F(VisionCli, NoiseGivesAtMostAFewLines) {
  cv::Mat noise(480, 640, CV_8UC3);
  cv::randu(noise, 0, 256);
  const fs::path file = dir_ / "noise.jpg";
  ASSERT_TRUE(cv::imwrite(file.string(), noise));
  const ToolRun r = run(file.string() + " --compact");
  ASSERT_EQ(r.rc, 0) << r.out;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_LE(j.at("lines").size(), 4U) << r.out;
}

// A smooth picture with no green carpet (a room-like blue-grey gradient with a white door):
// nothing to find.
TEST_F(VisionCli, NoCarpetNoLines) {
  cv::Mat room(480, 640, CV_8UC3);
  for (int y = 0; y < 480; ++y) {
    for (int x = 0; x < 640; ++x) {
      room.at<cv::Vec3b>(y, x) = cv::Vec3b(static_cast<std::uint8_t>(120 + y / 8), static_cast<std::uint8_t>(110 + y / 8),
                                           static_cast<std::uint8_t>(100 + x / 16));
    }
  }
  cv::rectangle(room, {200, 100}, {300, 470}, {240, 240, 240}, cv::FILLED);
  const fs::path file = dir_ / "room.jpg";
  ASSERT_TRUE(cv::imwrite(file.string(), room));
  const ToolRun r = run(file.string() + " --compact");
  ASSERT_EQ(r.rc, 0) << r.out;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("lines").size(), 0U) << r.out;
  EXPECT_FALSE(j.at("ball").at("seen").get<bool>()) << r.out;
}

// Bad input exits 2 with a message naming the file or flag, never "internal error" (exit 1).

// A valid PNG signature and IHDR declaring 40000 × 40000 pixels: OpenCV would throw (or allocate
// gigabytes); the header is checked before the decoder sees it.
TEST_F(VisionCli, OversizedPngHeaderIsBadInput) {
  std::vector<std::uint8_t> png{0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A, 0, 0, 0, 13, 'I', 'H', 'D', 'R',
                                0, 0, 0x9C, 0x40, 0, 0, 0x9C, 0x40, 8, 2, 0, 0, 0, 0, 0, 0, 0};
  const fs::path file = dir_ / "huge.png";
  std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
  const ToolRun r = run(file.string(), true);
  EXPECT_EQ(r.rc, 2) << r.out;
  EXPECT_NE(r.out.find("huge.png: not a readable image: PNG image is 40000x40000 = 1600000000 pixels, more than the "
                       "limit of 16777216"), std::string::npos) << r.out;
}

// The real frame cut in half: header fine, data missing.
TEST_F(VisionCli, TruncatedPngIsBadInput) {
  const std::string bytes = [&] {
    std::ifstream in(dir_ / "frame.png", std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }();
  const fs::path file = dir_ / "half.png";
  std::ofstream(file, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  const ToolRun r = run(file.string(), true);
  EXPECT_EQ(r.rc, 2) << r.out;
  EXPECT_NE(r.out.find("half.png: not a readable image"), std::string::npos) << r.out;
}

TEST_F(VisionCli, ImagePathThatIsADirectoryIsBadInput) {
  const ToolRun r = run(dir_.string(), true);
  EXPECT_EQ(r.rc, 2) << r.out;
  EXPECT_NE(r.out.find(dir_.string() + ": cannot read image: not a regular file (a directory)"), std::string::npos) << r.out;
}

// NaN passes every "x < lo || x > hi" check; each number must be finite and in its documented
// range, and the message names the flag.
TEST_F(VisionCli, NonFiniteOrOutOfRangeCameraFlagsAreBadInput) {
  const std::string png = (dir_ / "frame.png").string();
  const std::pair<const char*, const char*> cases[] = {
      {"--pitch nan", "--pitch: must be a finite number, got nan"},
      {"--pitch 95", "--pitch: must be within [-38.5, 29.5] deg (the NAO's HeadPitch range), got 95"},
      {"--pitch -40", "--pitch: must be within [-38.5, 29.5]"},
      {"--yaw 120", "--yaw: must be within [-119.5, 119.5]"},
      {"--yaw -inf", "--yaw: must be a finite number, got -inf"},
      {"--fx nan --fy 500", "--fx: must be a finite number, got nan"},
      {"--fx 500 --fy 0", "--fy: must be within [1, 100000] px, got 0"},
      {"--hfov nan", "--hfov: must be a finite number"},
      {"--vfov 180", "--vfov: must be within [1, 179] deg"},
      {"--pivot-height nan", "--pivot-height: must be a finite number"},
      {"--camera-forward nan", "--camera-forward: must be a finite number"},
      {"--camera-up 2", "--camera-up: must be within [-1, 1] m"},
      {"--cx 9000 --fx 500 --fy 500", "--cx: must be within [0, 4096] px"},
      {"--cy 700 --fx 500 --fy 500", "--cx/--cy (320, 700) lies outside the 640x480 image"},
      {"--fy 500", "--fy needs --fx"},
      {"--pitch abc", "--pitch: not a number: abc"},
      {"--body-pitch 45", "--body-pitch: must be within [-30, 30] deg"},
      {"--body-pitch -31", "--body-pitch: must be within [-30, 30] deg"},
      {"--body-roll 25", "--body-roll: must be within [-20, 20] deg"},
      {"--body-roll nan", "--body-roll: must be a finite number, got nan"},
      {"--body-pitch inf", "--body-pitch: must be a finite number, got inf"},
      {"--repeat 0", "--repeat: Value 0 not in range 1 to 100000"},
  };
  for (const auto& [flags, message] : cases) {
    const ToolRun r = run(png + " " + flags, true);
    EXPECT_EQ(r.rc, 2) << flags << "\n" << r.out;
    EXPECT_NE(r.out.find(message), std::string::npos) << flags << "\n" << r.out;
    EXPECT_EQ(r.out.find("\"status\""), std::string::npos) << flags << ": no result may be printed\n" << r.out;
  }
  // The ends of the NAO's range are allowed.
  EXPECT_EQ(run(png + " --pitch 29.5 --yaw -119.5").rc, 0);
  EXPECT_EQ(run(png + " --pitch -38.5").rc, 0);
  EXPECT_EQ(run(png + " --body-pitch 30 --body-roll -20").rc, 0);
}

// A JPEG cut short: libjpeg decodes it with grey rows and a warning only; the tool refuses it.
TEST_F(VisionCli, TruncatedJpegIsBadInput) {
  const std::string bytes = [&] {
    std::ifstream in(dir_ / "frame.jpg", std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }();
  const fs::path file = dir_ / "cut.jpg";
  std::ofstream(file, std::ios::binary) << bytes.substr(0, bytes.size() * 3 / 5);
  const ToolRun r = run(file.string(), true);
  EXPECT_EQ(r.rc, 2) << r.out;
  EXPECT_NE(r.out.find("cut.jpg: not a readable image: truncated JPEG (no end-of-image marker)"), std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("\"status\""), std::string::npos) << r.out;
  // Only the last two bytes (the end-of-image marker) missing: still refused.
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes.substr(0, bytes.size() - 2);
  EXPECT_EQ(run(file.string()).rc, 2);
}

// A grey picture: processed (no colour, so nothing is found), with a warning on stderr and in the
// JSON, for PNG and JPEG alike.
TEST_F(VisionCli, GrayscaleImageIsWarnedAbout) {
  cv::Mat grey;
  cv::cvtColor(cv::imread((dir_ / "frame.png").string()), grey, cv::COLOR_BGR2GRAY);
  for (const char* name : {"grey.png", "grey.jpg"}) {
    const fs::path file = dir_ / name;
    ASSERT_TRUE(cv::imwrite(file.string(), grey));
    const ToolRun both = run_stderr(file.string() + " " + head_flags() + " --compact");
    EXPECT_EQ(both.rc, 0) << both.out;
    EXPECT_NE(both.out.find(std::string("ringlet-vision: warning: ") + file.string() +
                            ": grayscale image: colour classification needs a colour picture"),
              std::string::npos) << both.out;
    const ToolRun r = run(file.string() + " " + head_flags() + " --compact");
    ASSERT_EQ(r.rc, 0) << r.out;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    ASSERT_EQ(j.at("warnings").size(), 1U) << r.out;
    EXPECT_NE(j.at("warnings").at(0).get<std::string>().find("grayscale image"), std::string::npos);
    EXPECT_EQ(j.at("lines").size(), 0U) << r.out;
  }
  // A colour picture has no warnings.
  const ToolRun colour = run((dir_ / "frame.png").string() + " " + head_flags() + " --compact");
  ASSERT_EQ(colour.rc, 0);
  EXPECT_FALSE(nlohmann::json::parse(colour.out).contains("warnings"));
}

// Every run prints the time per stage and in total; --repeat N adds min ≤ median ≤ p99 ≤ max.
TEST_F(VisionCli, TimePerFrameAndRepeatStatistics) {
  const std::string png = (dir_ / "frame.png").string() + " " + head_flags() + " --compact";
  const ToolRun once = run(png);
  ASSERT_EQ(once.rc, 0) << once.out;
  const nlohmann::json t = nlohmann::json::parse(once.out).at("time_ms");
  double stages = 0.0;
  for (const char* stage : {"horizon", "classify", "ball", "scan", "ransac"}) {
    ASSERT_TRUE(t.contains(stage)) << t.dump();
    EXPECT_GE(t.at(stage).get<double>(), 0.0);
    stages += t.at(stage).get<double>();
  }
  EXPECT_GT(t.at("total").get<double>(), 0.0);
  EXPECT_LE(stages, t.at("total").get<double>() + 1e-6);
  EXPECT_GT(t.at("wall").get<double>(), 0.0);
  EXPECT_FALSE(nlohmann::json::parse(once.out).contains("timing"));

  const ToolRun repeated = run(png + " --repeat 7");
  ASSERT_EQ(repeated.rc, 0) << repeated.out;
  const nlohmann::json j = nlohmann::json::parse(repeated.out);
  EXPECT_EQ(j.at("timing").at("repeat"), 7);
  for (const char* which : {"total_ms", "wall_ms"}) {
    const auto& s = j.at("timing").at(which);
    EXPECT_GT(s.at("min").get<double>(), 0.0) << which;
    EXPECT_LE(s.at("min").get<double>(), s.at("median").get<double>()) << which;
    EXPECT_LE(s.at("median").get<double>(), s.at("p99").get<double>()) << which;
    EXPECT_LE(s.at("p99").get<double>(), s.at("max").get<double>()) << which;
  }
  EXPECT_TRUE(j.at("timing").at("stages_ms").contains("ransac"));
  // The detections do not change with repetition.
  const nlohmann::json first = nlohmann::json::parse(once.out);
  EXPECT_EQ(j.at("lines"), first.at("lines"));
  EXPECT_EQ(j.at("ball"), first.at("ball"));
  const ToolRun text = run_stderr(png + " --repeat 3");
  EXPECT_NE(text.out.find("ringlet-vision: 3 runs, thread CPU ms per frame: min "), std::string::npos) << text.out;
  EXPECT_NE(text.out.find(" p99 "), std::string::npos) << text.out;
}

// A torso leaning 6° forward and 4° to the right: with --body-pitch/--body-roll the ball lands
// where it is; taken as upright, it lands far off (the horizon and every ground ray are wrong).
TEST_F(VisionCli, BodyTiltFlagsPutTheBallWhereItIs) {
  sim_hal::CameraRenderer renderer(sim_hal::load_world(RINGLET_SIM_WORLDS_DIR "/spl_field.world"), sim_hal::CameraSpec{}, 3);
  const hal::BodyTilt body{hal::deg_to_rad(6.0), hal::deg_to_rad(4.0)};
  renderer.render({2.1, -0.3, -std::acos(0.0)},
                  hal::CameraPosture{body, {hal::deg_to_rad(yaw_deg_), hal::deg_to_rad(pitch_deg_ - 6.0)}});
  const sim_hal::FrameTruth truth = renderer.truth();
  ASSERT_TRUE(truth.ball.visible);
  const cv::Mat bgr(480, 640, CV_8UC3, const_cast<std::uint8_t*>(renderer.bgr().data()));
  const fs::path file = dir_ / "tilted.png";
  ASSERT_TRUE(cv::imwrite(file.string(), bgr));
  const std::string head = "--yaw " + std::to_string(yaw_deg_) + " --pitch " + std::to_string(pitch_deg_ - 6.0);

  const ToolRun r = run(file.string() + " " + head + " --body-pitch 6 --body-roll 4 --compact");
  ASSERT_EQ(r.rc, 0) << r.out;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.at("ball").at("seen").get<bool>()) << r.out;
  const auto& g = j.at("ball").at("ground");
  const double error = std::hypot(g.at(0).get<double>() - truth.ball.position.x, g.at(1).get<double>() - truth.ball.position.y);
  EXPECT_LT(error, 0.15) << r.out;
  EXPECT_EQ(j.at("posture_deg").at("body_roll"), 4.0);

  const ToolRun upright = run(file.string() + " " + head + " --compact");
  ASSERT_EQ(upright.rc, 0) << upright.out;
  const nlohmann::json u = nlohmann::json::parse(upright.out);
  if (u.at("ball").at("seen").get<bool>() && u.at("ball").contains("ground")) {
    const auto& ug = u.at("ball").at("ground");
    const double upright_error =
        std::hypot(ug.at(0).get<double>() - truth.ball.position.x, ug.at(1).get<double>() - truth.ball.position.y);
    EXPECT_GT(upright_error, 3.0 * error + 0.1) << upright.out;
  }
}

// --auto-pitch: a photo whose head pitch is given 3° off (a camera mounted off, a guessed angle)
// is run at the pitch its field lines agree with. 1.5 m before a penalty area, looking at it: its
// front line and both sides are in view. Told the right pitch, it stays.
TEST_F(VisionCli, AutoPitchCorrectsAPitchGivenWrong) {
  sim_hal::CameraRenderer renderer(sim_hal::load_world(RINGLET_SIM_WORLDS_DIR "/spl_field.world"), sim_hal::CameraSpec{}, 3);
  const double pitch_deg = 24.0, yaw_deg = 10.0;
  renderer.render({1.5, -0.6, std::acos(0.0)}, {hal::deg_to_rad(yaw_deg), hal::deg_to_rad(pitch_deg)});
  const cv::Mat bgr(480, 640, CV_8UC3, const_cast<std::uint8_t*>(renderer.bgr().data()));
  const fs::path file = dir_ / "penalty_area.png";
  ASSERT_TRUE(cv::imwrite(file.string(), bgr));
  const auto corrected = [&](double given_deg) {
    const ToolRun r = run(file.string() + " --auto-pitch --compact --yaw " + std::to_string(yaw_deg) + " --pitch " +
                          std::to_string(given_deg));
    EXPECT_EQ(r.rc, 0) << r.out;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    const nlohmann::json& c = j.at("pitch_check");
    EXPECT_TRUE(c.at("rounds").at(0).at("valid").get<bool>()) << r.out;
    EXPECT_GE(c.at("rounds").at(0).at("pairs").get<int>(), 2) << r.out;
    EXPECT_NEAR(c.at("given_head_pitch_deg").get<double>(), given_deg, 1e-6);
    EXPECT_EQ(j.at("posture_deg").at("head_pitch").get<double>(), c.at("head_pitch_deg").get<double>());
    EXPECT_FALSE(j.contains("warnings")) << r.out;
    return c.at("head_pitch_deg").get<double>();
  };
  EXPECT_NEAR(corrected(pitch_deg + 3.0), pitch_deg, 0.5);
  EXPECT_NEAR(corrected(pitch_deg - 3.0), pitch_deg, 0.5);
  EXPECT_NEAR(corrected(pitch_deg), pitch_deg, 0.5);
  // The camera's own pitch as mounted (--camera-pitch, [camera] pitch_deg) takes up the error:
  // then nothing is left to correct.
  const ToolRun mounted = run(file.string() + " --auto-pitch --compact --yaw " + std::to_string(yaw_deg) + " --pitch " +
                              std::to_string(pitch_deg + 3.0) + " --camera-pitch -3");
  ASSERT_EQ(mounted.rc, 0) << mounted.out;
  EXPECT_NEAR(nlohmann::json::parse(mounted.out).at("pitch_check").at("correction_deg").get<double>(), 0.0, 0.5)
      << mounted.out;
  // Without the flag nothing is checked or changed.
  const ToolRun plain = run(file.string() + " --compact --yaw " + std::to_string(yaw_deg) + " --pitch 27");
  ASSERT_EQ(plain.rc, 0) << plain.out;
  const nlohmann::json p = nlohmann::json::parse(plain.out);
  EXPECT_FALSE(p.contains("pitch_check"));
  EXPECT_EQ(p.at("posture_deg").at("head_pitch").get<double>(), 27.0);
}

}  // namespace
}  // namespace ringlet
