// The real camera backend is tested by replaying frames the simulator wrote: three frames rendered
// by sim_hal::CameraRenderer are saved as PNG (lossless) and replayed through hal::OpenCvCamera; the
// bytes it hands out must be exactly the renderer's BGR, or hal::bgr_to_yuyv of it.
#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <thread>
#include <unistd.h>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "ringlet/hal/monotonic_clock.hpp"
#include "ringlet/hal/opencv_camera.hpp"
#include "ringlet/hal/yuv.hpp"
#include "ringlet/sim_hal/camera_renderer.hpp"

namespace ringlet {
namespace {

namespace fs = std::filesystem;

struct Rendered {
  std::vector<std::uint8_t> bgr;
  std::vector<std::uint8_t> yuyv;
};

class ReplayRendered : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("ringlet-replay-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    sim_hal::CameraRenderer renderer(sim_hal::load_world(RINGLET_SIM_WORLDS_DIR "/spl_field.world"), sim_hal::CameraSpec{}, 7);
    const hal::CameraIntrinsics& k = renderer.spec().intrinsics;
    // Three different views: the centre circle, a penalty box, a touch line.
    const hal::Pose2 poses[3] = {{2.0, -0.3, -1.5708}, {-1.5, 0.5, -1.5708}, {0.0, -2.0, 0.3}};
    const hal::HeadJoints heads[3] = {{0.0, 0.35}, {0.3, 0.25}, {-0.4, 0.45}};
    for (int i = 0; i < 3; ++i) {
      renderer.render(poses[i], heads[i]);
      Rendered r;
      r.bgr.assign(renderer.bgr().begin(), renderer.bgr().end());
      r.yuyv.resize(static_cast<std::size_t>(k.width) * static_cast<std::size_t>(k.height) * 2U);
      hal::bgr_to_yuyv(r.bgr, k.width, k.height, r.yuyv);
      const cv::Mat mat(k.height, k.width, CV_8UC3, r.bgr.data());
      char name[32];
      std::snprintf(name, sizeof name, "frame_%04d.png", i);
      ASSERT_TRUE(cv::imwrite((dir_ / name).string(), mat));
      frames_.push_back(std::move(r));
    }
  }
  void TearDown() override { fs::remove_all(dir_); }

  void replay(hal::PixelFormat format) {
    hal::MonotonicClock clock;
    hal::OpenCvCamera camera({dir_.string(), 640, 480, 30.0, format}, clock);
    hal::FrameView view;
    for (std::size_t i = 0; i < frames_.size(); ++i) {
      bool got = false;
      for (int t = 0; t < 5000 && !got; ++t) {
        got = camera.grab_latest(view) && view.sequence == i;
        if (!got) std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
      ASSERT_TRUE(got) << "frame " << i << " never arrived: " << camera.error();
      const std::vector<std::uint8_t>& expected = format == hal::PixelFormat::kBgr8 ? frames_[i].bgr : frames_[i].yuyv;
      ASSERT_EQ(view.format, format);
      ASSERT_EQ(static_cast<std::size_t>(view.stride) * static_cast<std::size_t>(view.height), expected.size());
      EXPECT_EQ(std::memcmp(view.data, expected.data(), expected.size()), 0) << "frame " << i;
    }
    EXPECT_TRUE(camera.error().empty()) << camera.error();
  }

  fs::path dir_;
  std::vector<Rendered> frames_;
};

TEST_F(ReplayRendered, BgrBytesAreTheRenderersBytes) { replay(hal::PixelFormat::kBgr8); }

TEST_F(ReplayRendered, YuyvBytesAreBgrToYuyvOfTheRenderersBytes) { replay(hal::PixelFormat::kYuyv); }

}  // namespace
}  // namespace ringlet
