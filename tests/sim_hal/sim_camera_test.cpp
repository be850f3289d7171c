// The simulated camera inside SimRobot: off by default, one frame per `every_n_frames` reads,
// delivered one camera period after its capture with the capture's time, pose and sequence;
// pixels held by a reader stay put; two robots with the same seed see byte-identical frames.
#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>
#include <vector>

#include "ringlet/sim_hal/sim_robot.hpp"
#include "sim_test_support.hpp"

namespace ringlet::sim_hal {
namespace {

World spl_field() { return load_world(RINGLET_SIM_WORLDS_DIR "/spl_field.world"); }

SimConfig camera_config(hal::PixelFormat format = hal::PixelFormat::kYuyv) {
  SimConfig config;
  config.camera.enabled = true;
  config.camera.format = format;
  return config;
}

TEST(SimCamera, OffByDefault) {
  SimRobot robot(spl_field(), SimConfig{});
  EXPECT_EQ(robot.camera(), nullptr);
  EXPECT_EQ(robot.camera_truth(), nullptr);
}

TEST(SimCamera, RejectsBadConfiguration) {
  SimConfig odd = camera_config();
  odd.camera.intrinsics = hal::CameraIntrinsics::from_fov(641, 480, 57.0, 44.0);
  EXPECT_THROW(validate(odd), std::invalid_argument);
  SimConfig never = camera_config();
  never.camera.every_n_frames = 0;
  try {
    validate(never);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "sim.camera.every_n_frames must be in 1..1000, got 0");
  }
  SimConfig gray = camera_config(hal::PixelFormat::kGray8);
  EXPECT_THROW(validate(gray), std::invalid_argument);
  SimConfig disabled = odd;
  disabled.camera.enabled = false;
  EXPECT_NO_THROW(validate(disabled));  // a disabled camera's fields are not looked at
}

TEST(SimCamera, FrameArrivesOneCameraPeriodAfterItsCapture) {
  SimRobot robot(spl_field(), camera_config());
  hal::Camera& camera = *robot.camera();
  hal::SensorFrame frame;
  hal::FrameView view;
  hal::ActuatorCommand cmd;
  cmd.drive = {0.5, 0.8};
  cmd.head = {0.4, 0.35};
  robot.actuators().write(cmd);

  std::vector<hal::Pose2> poses(1);  // true pose after each read, index = step
  std::vector<hal::HeadJoints> heads(1);
  for (int step = 1; step <= 12; ++step) {
    robot.sensors().read(frame);
    poses.push_back(robot.true_state().pose);
    heads.push_back(frame.head);
    const bool delivered = camera.grab_latest(view);
    if (step < 6) {
      EXPECT_FALSE(delivered) << "step " << step;  // captured at step 3, delivered at step 6
      EXPECT_EQ(robot.camera_truth(), nullptr);
      continue;
    }
    ASSERT_TRUE(delivered) << "step " << step;
    // Tick k = step / 3 delivers the capture of tick k - 1, taken at step 3(k - 1).
    const int captured_at = (step / 3 - 1) * 3;
    EXPECT_EQ(view.sequence, static_cast<std::uint64_t>(step / 3 - 1)) << "step " << step;
    EXPECT_EQ(view.capture_time, hal::Nanos{captured_at * 10'000'000LL}) << "step " << step;
    EXPECT_EQ(view.format, hal::PixelFormat::kYuyv);
    EXPECT_EQ(view.width, 640);
    EXPECT_EQ(view.height, 480);
    EXPECT_EQ(view.stride, 1280);
    ASSERT_NE(view.data, nullptr);
    const FrameTruth* truth = robot.camera_truth();
    ASSERT_NE(truth, nullptr);
    const auto at = static_cast<std::size_t>(captured_at);
    EXPECT_EQ(truth->pose.x, poses[at].x);
    EXPECT_EQ(truth->pose.y, poses[at].y);
    EXPECT_EQ(truth->pose.theta, poses[at].theta);
    EXPECT_EQ(truth->head.yaw, heads[at].yaw);
    EXPECT_EQ(truth->head.pitch, heads[at].pitch);
  }
}

TEST(SimCamera, HeldFrameStaysValidUntilTheNextGrab) {
  SimRobot robot(spl_field(), camera_config(hal::PixelFormat::kBgr8));
  hal::SensorFrame frame;
  hal::ActuatorCommand cmd;
  cmd.drive = {0.0, 1.0};
  cmd.head = {-0.5, 0.3};
  robot.actuators().write(cmd);
  for (int i = 0; i < 6; ++i) robot.sensors().read(frame);
  hal::FrameView held;
  ASSERT_TRUE(robot.camera()->grab_latest(held));
  EXPECT_EQ(held.stride, 640 * 3);
  const std::vector<std::uint8_t> copy(held.data, held.data + 640 * 480 * 3);
  for (int i = 0; i < 30; ++i) robot.sensors().read(frame);  // ten more frames, none grabbed
  EXPECT_EQ(std::memcmp(copy.data(), held.data, copy.size()), 0);
  hal::FrameView newer;
  ASSERT_TRUE(robot.camera()->grab_latest(newer));
  EXPECT_EQ(newer.sequence, held.sequence + 10);
  EXPECT_NE(std::memcmp(copy.data(), newer.data, copy.size()), 0);  // it drove and turned its head
}

std::vector<std::uint64_t> frame_hashes(std::uint64_t seed) {
  SimConfig config = camera_config();
  config.seed = seed;
  config.gps_sigma_xy = 0.02;  // noise must not leak into the camera's determinism
  SimRobot robot(spl_field(), config);
  hal::SensorFrame frame;
  hal::FrameView view;
  std::vector<std::uint64_t> hashes;
  for (int step = 1; step <= 60; ++step) {
    hal::ActuatorCommand cmd;
    cmd.drive = {0.3 * std::sin(step * 0.1), 0.8};
    cmd.head = {0.6 * std::sin(step * 0.05), 0.3};
    robot.actuators().write(cmd);
    robot.sensors().read(frame);
    if (step % 3 == 0 && robot.camera()->grab_latest(view)) {
      test::Fnv1a h;
      h.bytes(view.data, static_cast<std::size_t>(view.stride) * static_cast<std::size_t>(view.height));
      h.value(static_cast<std::int64_t>(view.sequence));
      h.value(static_cast<std::int64_t>(view.capture_time.count()));
      hashes.push_back(h.result());
    }
  }
  return hashes;
}

TEST(SimCamera, SameSeedGivesByteIdenticalFrames) {
  const std::vector<std::uint64_t> a = frame_hashes(11);
  const std::vector<std::uint64_t> b = frame_hashes(11);
  EXPECT_EQ(a.size(), 19U);  // 20 ticks, the first delivers nothing yet
  EXPECT_EQ(a, b);
}

TEST(SimCamera, DestroyedWhileRenderingJoinsCleanly) {
  for (int i = 0; i < 5; ++i) {
    SimRobot robot(spl_field(), camera_config());
    hal::SensorFrame frame;
    for (int step = 0; step < 3 + i; ++step) robot.sensors().read(frame);
  }  // each destructor stops and joins the render thread, possibly mid-frame
  SUCCEED();
}

}  // namespace
}  // namespace ringlet::sim_hal
