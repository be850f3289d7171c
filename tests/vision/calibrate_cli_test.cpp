// ringlet-vision-calibrate on pictures written here: --auto refuses a photo with no field in it
// (naming it, exit 2) and builds a table and a report from a rendered one; labelled examples with the "not labelled" value 255 are partial labels: those
// pixels neither train nor count.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
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

using CalibrateRun = test::CommandRun;

CalibrateRun calibrate(const std::string& args) {
  return test::run_command(std::string(RINGLET_VISION_CALIBRATE_BIN) + " " + args + " 2>&1");
}

class CalibrateCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("ringlet-calibrate-cli-" + std::to_string(::getpid()));
    fs::create_directories(dir_ / "labelled");
    sim_hal::CameraRenderer renderer(sim_hal::load_world(RINGLET_SIM_WORLDS_DIR "/spl_field.world"), sim_hal::CameraSpec{}, 3);
    renderer.render({2.1, -0.3, -std::acos(0.0)}, {0.0, hal::deg_to_rad(20.0)});
    field_ = cv::Mat(480, 640, CV_8UC3, const_cast<std::uint8_t*>(renderer.bgr().data())).clone();
    ASSERT_TRUE(cv::imwrite((dir_ / "field.png").string(), field_));
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path dir_;
  cv::Mat field_;
};

TEST_F(CalibrateCli, AutoRefusesAPhotoWithoutAFieldNamingIt) {
  // A blue-grey room with a white door: no green-ish dominant colour below the horizon.
  cv::Mat room(480, 640, CV_8UC3);
  for (int y = 0; y < 480; ++y)
    for (int x = 0; x < 640; ++x)
      room.at<cv::Vec3b>(y, x) = cv::Vec3b(static_cast<std::uint8_t>(120 + y / 8), static_cast<std::uint8_t>(110 + y / 8),
                                           static_cast<std::uint8_t>(100 + x / 16));
  cv::rectangle(room, {200, 100}, {300, 470}, {240, 240, 240}, cv::FILLED);
  ASSERT_TRUE(cv::imwrite((dir_ / "room.jpg").string(), room));
  const fs::path lut = dir_ / "never.lut";
  const CalibrateRun r = calibrate("--auto " + (dir_ / "field.png").string() + " " + (dir_ / "room.jpg").string() + " --out " + lut.string());
  EXPECT_EQ(r.rc, 2) << r.out;
  EXPECT_NE(r.out.find("room.jpg: no dominant field colour below the horizon"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(lut)) << "nothing is written when a photo is refused";
}

TEST_F(CalibrateCli, AutoTableClassifiesItsPhotoAndTheReportSaysHow) {
  const fs::path lut = dir_ / "auto.lut", report = dir_ / "report.json", classes = dir_ / "classes";
  const CalibrateRun r = calibrate("--auto " + (dir_ / "field.png").string() + " --out " + lut.string() + " --report " +
                          report.string() + " --classes-dir " + classes.string());
  ASSERT_EQ(r.rc, 0) << r.out;
  ASSERT_TRUE(fs::exists(lut));
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(report));
  ASSERT_EQ(j.at("photos").size(), 1U);
  const auto& photo = j.at("photos").at(0);
  EXPECT_GT(photo.at("field").at("confidence").get<double>(), 0.5);
  EXPECT_GT(photo.at("fractions").at("field").get<double>(), 0.5);
  EXPECT_GT(photo.at("fractions").at("line").get<double>(), 0.005);
  const cv::Mat drawn = cv::imread((classes / "field_classes.png").string());
  ASSERT_FALSE(drawn.empty());
  EXPECT_EQ(drawn.cols, 640);
}

TEST_F(CalibrateCli, PartialLabelsIgnoreTheNotLabelledValue) {
  // Only a block of carpet and nothing else labelled; the rest is 255.
  cv::imwrite((dir_ / "labelled" / "f.png").string(), field_);
  cv::Mat labels(480, 640, CV_8UC1, cv::Scalar(255));
  labels(cv::Rect(0, 400, 100, 80)).setTo(1);  // bottom-left corner: carpet in this view
  ASSERT_TRUE(cv::imwrite((dir_ / "labelled" / "f_labels.png").string(), labels));
  const fs::path lut = dir_ / "partial.lut";
  const CalibrateRun r = calibrate("--examples " + (dir_ / "labelled").string() + " --out " + lut.string() + " --evaluate " +
                          (dir_ / "labelled").string() + " --stride 4 -q");
  ASSERT_EQ(r.rc, 0) << r.out;
  // 100 × 80 labelled pixels sampled every 4th in both directions: 500 samples, not 19200.
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex("([0-9]+) samples"))) << r.out;
  EXPECT_EQ(std::stoi(m[1]), 500) << r.out;
  EXPECT_NE(r.out.find("field "), std::string::npos);
  // A label that is neither a class nor 255 is still refused, naming the pixel.
  labels.at<std::uint8_t>(4, 5) = 9;  // row 4, column 5: a sampled pixel at stride 4
  ASSERT_TRUE(cv::imwrite((dir_ / "labelled" / "f_labels.png").string(), labels));
  const CalibrateRun bad = calibrate("--examples " + (dir_ / "labelled").string() + " --out " + lut.string() + " -q");
  EXPECT_EQ(bad.rc, 2) << bad.out;
  EXPECT_NE(bad.out.find("pixel (5, 4) has label 9"), std::string::npos) << bad.out;
}

}  // namespace
}  // namespace ringlet
