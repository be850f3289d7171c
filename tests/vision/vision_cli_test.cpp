// ringlet-vision, the command-line tool, on pictures the simulator rendered with known ground
// truth: as PNG (lines found, the ball found where it is, overlay written), as JPEG (what a real
// camera's photographs are: lossy, still works), and on a picture that is not a field at all
// (noise: must not crash, few or no lines).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "ringlet/sim/camera_renderer.hpp"

namespace ringlet {
namespace {

namespace fs = std::filesystem;

struct ToolRun {
  int rc = -1;
  std::string out;
};

ToolRun run(const std::string& args) {
  ToolRun r;
  const std::string command = std::string(RINGLET_VISION_BIN) + " " + args + " 2>/dev/null";
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return r;
  char buffer[4096];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) r.out.append(buffer, n);
  const int status = ::pclose(pipe);
  r.rc = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

class VisionCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("ringlet-vision-cli-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    sim::CameraRenderer renderer(sim::load_world(RINGLET_SIM_WORLDS_DIR "/spl_field.world"), sim::CameraSpec{}, 3);
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
  sim::FrameTruth truth_;
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

}  // namespace
}  // namespace ringlet
