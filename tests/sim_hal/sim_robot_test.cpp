// SimRobot: lockstep timing, determinism, collisions, the safe state, head, power and validate().
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <numbers>
#include <ostream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "ringlet/sim_hal/sim_robot.hpp"
#include "sim_test_support.hpp"

namespace ringlet::sim_hal {
namespace {

using test::box_world;

hal::ActuatorCommand drive(double velocity, double curvature = 0.0) {
  hal::ActuatorCommand cmd;
  cmd.drive.velocity = velocity;
  cmd.drive.curvature = curvature;
  return cmd;
}

/// Writes `cmd` and reads `steps` times; returns the last frame.
hal::SensorFrame run(SimRobot& robot, const hal::ActuatorCommand& cmd, int steps) {
  hal::SensorFrame frame;
  for (int i = 0; i < steps; ++i) {
    robot.actuators().write(cmd);
    robot.sensors().read(frame);
  }
  return frame;
}

TEST(SimRobot, IsTheSimBackendWithoutCamera) {
  SimRobot robot(box_world(10.0, 10.0, {2.0, 3.0, 1.0}), SimConfig{});
  EXPECT_EQ(robot.backend_name(), "sim");
  EXPECT_EQ(robot.camera(), nullptr);
  EXPECT_EQ(robot.true_state().pose.x, 2.0);
  EXPECT_EQ(robot.true_state().pose.y, 3.0);
  EXPECT_EQ(robot.true_state().pose.theta, 1.0);
  EXPECT_EQ(robot.steps(), 0U);
}

TEST(SimRobot, TrueBallIsInTheRobotFrameAndFollowsTheRobot) {
  World world = box_world(10.0, 10.0, {2.0, 2.0, 0.0});  // facing north
  EXPECT_FALSE(SimRobot(world, SimConfig{}).true_ball_in_robot_frame().has_value());
  world.ball = Ball{{1.0, 5.0}, 0.1};  // 3 m ahead, 1 m to the left
  SimRobot robot(world, SimConfig{});
  auto ball = robot.true_ball_in_robot_frame();
  ASSERT_TRUE(ball.has_value());
  EXPECT_NEAR(ball->x, 3.0, 1e-12);
  EXPECT_NEAR(ball->y, 1.0, 1e-12);
  (void)run(robot, drive(1.0), 100);  // drives north towards it
  ball = robot.true_ball_in_robot_frame();
  EXPECT_NEAR(ball->x, 5.0 - robot.true_state().pose.y, 1e-9);
  EXPECT_NEAR(ball->y, 1.0, 1e-9);
}

TEST(SimRobot, EachReadAdvancesExactlyOnePeriod) {
  SimConfig config;
  config.period = std::chrono::milliseconds(20);
  SimRobot robot(box_world(10.0, 10.0, {5.0, 5.0, 0.0}), config);
  hal::SensorFrame frame;
  for (int i = 1; i <= 3; ++i) {
    ASSERT_TRUE(robot.sensors().read(frame));
    EXPECT_EQ(frame.stamp, i * config.period);
    EXPECT_EQ(frame.pose.stamp, frame.stamp);
    EXPECT_EQ(frame.odometry.stamp, frame.stamp);
    EXPECT_EQ(frame.laser.stamp, frame.stamp);
  }
  EXPECT_EQ(robot.steps(), 3U);
  EXPECT_EQ(robot.sim_time(), 3 * config.period);
  // Without a command nothing moves, and without noise the GPS is the truth.
  EXPECT_TRUE(frame.pose.valid);
  EXPECT_EQ(frame.pose.pose.x, 5.0);
  EXPECT_EQ(frame.pose.pose.y, 5.0);
}

TEST(SimRobot, DrivesAlongTheHeadingWithRateLimitedSpeed) {
  SimRobot robot(box_world(20.0, 20.0, {10.0, 2.0, 0.0}), SimConfig{});
  hal::SensorFrame frame = run(robot, drive(1.0), 1);
  EXPECT_DOUBLE_EQ(frame.odometry.velocity, 0.01);  // max_acceleration 1 m/s^2 over 10 ms
  frame = run(robot, drive(1.0), 299);
  EXPECT_DOUBLE_EQ(frame.odometry.velocity, 1.0);
  EXPECT_NEAR(robot.true_state().pose.x, 10.0, 1e-12);
  // 1 s accelerating (0.505 m with the step-wise ramp) and 2 s at 1 m/s.
  EXPECT_NEAR(robot.true_state().pose.y, 2.0 + 0.505 + 2.0, 1e-9);
  EXPECT_NEAR(frame.odometry.distance, 2.505, 1e-9);
}

World noisy_test_world() {
  World world = box_world(20.0, 20.0, {10.0, 10.0, 0.3});
  world.circles.push_back({{14.0, 12.0}, 1.0});
  world.circles.push_back({{6.0, 7.0}, 0.5});
  world.polygons.push_back({{{3.0, 14.0}, {6.0, 14.0}, {4.5, 17.0}}});
  return world;
}

SimConfig noisy_config(std::uint64_t seed) {
  SimConfig config;
  config.seed = seed;
  config.gps_sigma_xy = 0.05;
  config.gps_sigma_theta = 0.01;
  config.laser_sigma = 0.02;
  return config;
}

std::uint64_t run_hash(std::uint64_t seed) {
  SimRobot robot(noisy_test_world(), noisy_config(seed));
  test::Fnv1a hash;
  hal::SensorFrame frame;
  for (int i = 0; i < 2000; ++i) {
    robot.actuators().write(drive(0.3 + 0.5 * std::sin(i * 0.004), 1.5 * std::sin(i * 0.007)));
    robot.sensors().read(frame);
    hash.frame(frame);
  }
  return hash.result();
}

TEST(SimRobot, SameSeedSameFramesBitForBit) {
  const std::uint64_t first = run_hash(42);
  EXPECT_EQ(first, run_hash(42));
  EXPECT_NE(first, run_hash(43));
}

TEST(SimRobot, NoiseIsAddedToGpsAndLaser) {
  SimRobot robot(noisy_test_world(), noisy_config(7));
  hal::SensorFrame frame;
  robot.sensors().read(frame);
  const hal::Pose2& truth = robot.true_state().pose;
  EXPECT_NE(frame.pose.pose.x, truth.x);
  EXPECT_NE(frame.pose.pose.y, truth.y);
  EXPECT_NE(frame.pose.pose.theta, truth.theta);
  EXPECT_NEAR(frame.pose.pose.x, truth.x, 0.5);  // 10 sigma
  // Beam straight ahead: compare with a noiseless twin.
  SimConfig clean = noisy_config(7);
  clean.laser_sigma = 0.0;
  SimRobot twin(noisy_test_world(), clean);
  hal::SensorFrame clean_frame;
  twin.sensors().read(clean_frame);
  int differing = 0;
  for (std::size_t i = 0; i < frame.laser.beam_count; ++i) {
    ASSERT_EQ(frame.laser.valid[i], clean_frame.laser.valid[i]) << i;
    if (frame.laser.range[i] != clean_frame.laser.range[i]) ++differing;
    EXPECT_NEAR(frame.laser.range[i], clean_frame.laser.range[i], 0.2);
  }
  EXPECT_GT(differing, 0);
}

/// 10 m x 10 m, robot at (5, 2) facing north, a circle of radius 1 at (5, 6): contact at y = 4.75.
World corridor_world() {
  World world = box_world(10.0, 10.0, {5.0, 2.0, 0.0});
  world.circles.push_back({{5.0, 6.0}, 1.0});
  return world;
}

TEST(SimRobot, DrivingIntoACircleStopsWithOneCollision) {
  SimRobot robot(corridor_world(), SimConfig{});
  hal::SensorFrame frame = run(robot, drive(1.0), 100);
  EXPECT_FALSE(frame.collided);
  EXPECT_EQ(robot.collisions(), 0U);

  frame = run(robot, drive(1.0), 500);  // keeps pushing for seconds after the contact
  EXPECT_EQ(robot.collisions(), 1U);
  EXPECT_TRUE(frame.collided);
  EXPECT_EQ(frame.odometry.velocity, 0.0);
  EXPECT_EQ(robot.true_state().velocity, 0.0);
  // Stopped short of the rim by less than one step's travel, never inside it.
  EXPECT_LE(robot.true_state().pose.y, 4.75);
  EXPECT_GT(robot.true_state().pose.y, 4.74);
  EXPECT_NEAR(robot.true_state().pose.x, 5.0, 1e-12);
}

TEST(SimRobot, BackingOffAndHittingAgainIsASecondCollision) {
  SimRobot robot(corridor_world(), SimConfig{});
  run(robot, drive(1.0), 600);
  ASSERT_EQ(robot.collisions(), 1U);
  hal::SensorFrame frame = run(robot, drive(-0.5), 150);
  EXPECT_FALSE(frame.collided);
  EXPECT_LT(frame.odometry.velocity, 0.0);
  frame = run(robot, drive(1.0), 300);
  EXPECT_TRUE(frame.collided);
  EXPECT_EQ(robot.collisions(), 2U);
}

TEST(SimRobot, WallsStopTheRobotToo) {
  SimRobot robot(box_world(10.0, 10.0, {5.0, 8.0, 0.0}), SimConfig{});
  const hal::SensorFrame frame = run(robot, drive(1.0), 400);
  EXPECT_TRUE(frame.collided);
  EXPECT_EQ(robot.collisions(), 1U);
  EXPECT_LE(robot.true_state().pose.y, 9.75);
}

TEST(SimRobot, SafeStateDeceleratesHoldsTheHeadAndIgnoresWrites) {
  SimRobot robot(box_world(30.0, 30.0, {15.0, 2.0, 0.0}), SimConfig{});
  hal::ActuatorCommand cmd = drive(1.0);
  cmd.head.yaw = 1.0;
  hal::SensorFrame frame = run(robot, cmd, 150);
  ASSERT_DOUBLE_EQ(frame.odometry.velocity, 1.0);
  const double yaw_before = frame.head.yaw;

  EXPECT_FALSE(robot.actuators().in_safe_state());
  robot.actuators().enter_safe_state();
  robot.actuators().enter_safe_state();  // any number of times
  EXPECT_TRUE(robot.actuators().in_safe_state());

  cmd.head.yaw = -1.0;
  frame = run(robot, cmd, 1);  // this write is ignored
  EXPECT_DOUBLE_EQ(frame.odometry.velocity, 0.99);
  EXPECT_EQ(frame.head.yaw, yaw_before);
  frame = run(robot, cmd, 99);  // 1 m/s at 1 m/s^2: stopped after 100 steps, up to rounding
  EXPECT_NEAR(frame.odometry.velocity, 0.0, 1e-12);
  frame = run(robot, cmd, 100);
  EXPECT_EQ(frame.odometry.velocity, 0.0);
  EXPECT_EQ(frame.head.yaw, yaw_before);
  EXPECT_TRUE(robot.actuators().in_safe_state());
}

TEST(SimRobot, SafeStateFromAnotherThread) {
  SimRobot robot(box_world(30.0, 30.0, {15.0, 2.0, 0.0}), SimConfig{});
  run(robot, drive(1.0), 100);
  std::thread watchdog([&robot] { robot.actuators().enter_safe_state(); });
  watchdog.join();
  EXPECT_TRUE(robot.actuators().in_safe_state());
  const hal::SensorFrame frame = run(robot, drive(1.0), 200);
  EXPECT_EQ(frame.odometry.velocity, 0.0);
}

TEST(SimRobot, HeadMovesNoFasterThanItsRate) {
  SimConfig config;
  config.head_max_rate = 2.0;  // 0.02 rad per 10 ms step
  SimRobot robot(box_world(10.0, 10.0, {5.0, 5.0, 0.0}), config);
  hal::ActuatorCommand cmd;
  cmd.head.yaw = 0.5;
  cmd.head.pitch = -0.05;
  hal::SensorFrame frame = run(robot, cmd, 1);
  EXPECT_DOUBLE_EQ(frame.head.yaw, 0.02);
  EXPECT_DOUBLE_EQ(frame.head.pitch, -0.02);
  frame = run(robot, cmd, 2);
  EXPECT_DOUBLE_EQ(frame.head.yaw, 0.06);
  EXPECT_DOUBLE_EQ(frame.head.pitch, -0.05);
  frame = run(robot, cmd, 30);
  EXPECT_DOUBLE_EQ(frame.head.yaw, 0.5);
}

TEST(SimRobot, BatteryDrainsWithDistanceAndOdometryIsSigned) {
  SimRobot robot(box_world(30.0, 30.0, {15.0, 10.0, 0.0}), SimConfig{});
  hal::SensorFrame frame = run(robot, drive(1.0), 400);
  const double forward = robot.distance_travelled();
  EXPECT_NEAR(forward, 3.505, 1e-9);
  EXPECT_NEAR(frame.power.battery_volts, 12.6 - 0.01 * forward, 1e-12);
  EXPECT_NEAR(frame.power.bus_volts, frame.power.battery_volts - 0.2, 1e-12);

  frame = run(robot, drive(-1.0), 400);  // 1 s braking, 1 s reversing, 2 s at -1 m/s
  EXPECT_GT(robot.distance_travelled(), forward + 2.0);
  EXPECT_LT(frame.odometry.distance, forward - 2.0);
  EXPECT_NEAR(frame.power.battery_volts, 12.6 - 0.01 * robot.distance_travelled(), 1e-12);
}

TEST(SimRobot, StartPoseInsideAnObstacleIsRefused) {
  World world = box_world(10.0, 10.0, {5.0, 5.0, 0.0});
  world.circles.push_back({{5.0, 5.5}, 0.5});
  try {
    SimRobot robot(world, SimConfig{});
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "start pose (5, 5) collides with an obstacle or the bounds");
  }
  EXPECT_THROW(SimRobot(box_world(10.0, 10.0, {0.1, 5.0, 0.0}), SimConfig{}), std::invalid_argument);
}

struct BadConfig {
  const char* name;
  std::function<void(SimConfig&)> spoil;
  std::string field;  // must appear in the message
};

const double kNan = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

const BadConfig kBadConfigs[] = {
    {"period", [](SimConfig& c) { c.period = hal::Nanos{0}; }, "sim.period must be > 0 ns, got 0 ns"},
    {"max_speed", [](SimConfig& c) { c.limits.max_speed = 0.0; }, "sim.limits.max_speed"},
    {"max_curvature", [](SimConfig& c) { c.limits.max_curvature = -1.0; }, "sim.limits.max_curvature"},
    {"max_acceleration", [](SimConfig& c) { c.limits.max_acceleration = kNan; }, "sim.limits.max_acceleration"},
    {"max_curvature_rate", [](SimConfig& c) { c.limits.max_curvature_rate = kInf; }, "sim.limits.max_curvature_rate"},
    {"robot_radius", [](SimConfig& c) { c.robot_radius = 0.0; }, "sim.robot_radius must be finite and > 0, got 0"},
    {"gps_sigma_xy", [](SimConfig& c) { c.gps_sigma_xy = -0.1; }, "sim.gps_sigma_xy must be finite and >= 0, got -0.1"},
    {"gps_sigma_theta", [](SimConfig& c) { c.gps_sigma_theta = kNan; }, "sim.gps_sigma_theta"},
    {"laser_beams_zero", [](SimConfig& c) { c.laser_beams = 0; }, "sim.laser_beams must be in 1..721, got 0"},
    {"laser_beams_many", [](SimConfig& c) { c.laser_beams = 722; }, "sim.laser_beams must be in 1..721, got 722"},
    {"laser_fov_zero", [](SimConfig& c) { c.laser_fov = 0.0; }, "sim.laser_fov"},
    {"laser_fov_wide", [](SimConfig& c) { c.laser_fov = 7.0; }, "sim.laser_fov"},
    {"laser_range", [](SimConfig& c) { c.laser_range = 0.0; }, "sim.laser_range"},
    {"laser_sigma", [](SimConfig& c) { c.laser_sigma = -1.0; }, "sim.laser_sigma"},
    {"head_max_rate", [](SimConfig& c) { c.head_max_rate = 0.0; }, "sim.head_max_rate"},
    {"battery_volts", [](SimConfig& c) { c.battery_volts = -1.0; }, "sim.battery_volts"},
    {"body_pitch", [](SimConfig& c) { c.body.pitch = 0.6; }, "sim.body.pitch must be finite and within ±0.5235987755982988 rad (30°), got 0.6"},
    {"body_roll", [](SimConfig& c) { c.body.roll = kNan; }, "sim.body.roll must be finite"},
    {"body_sway", [](SimConfig& c) { c.body.roll = -0.3; c.body.sway_roll = 0.1; }, "sim.body.roll + |sway_roll|"},
    {"body_sway_period", [](SimConfig& c) { c.body.sway_period = 0.0; }, "sim.body.sway_period must be in [0.05, 60] s"},
};

void PrintTo(const BadConfig& bad, std::ostream* out) { *out << bad.name; }

class SimValidateRejects : public testing::TestWithParam<BadConfig> {};

TEST_P(SimValidateRejects, NamingTheField) {
  SimConfig config;
  GetParam().spoil(config);
  try {
    validate(config);
    FAIL() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(GetParam().field), std::string::npos) << e.what();
  }
  EXPECT_THROW(SimRobot(box_world(10.0, 10.0, {5.0, 5.0, 0.0}), config), std::invalid_argument);
}

INSTANTIATE_TEST_SUITE_P(SimValidate, SimValidateRejects, testing::ValuesIn(kBadConfigs),
                         [](const testing::TestParamInfo<BadConfig>& param) { return std::string(param.param.name); });

TEST(SimValidate, DefaultsAndEdgesAreAccepted) {
  EXPECT_NO_THROW(validate(SimConfig{}));
  SimConfig config;
  config.laser_beams = 721;
  config.laser_fov = 2.0 * std::numbers::pi;
  config.gps_sigma_xy = 0.0;
  EXPECT_NO_THROW(validate(config));
}

// ---- the torso's tilt (inertial unit) ----------------------------------------------------------

TEST(SimRobotBody, UprightByDefaultAndTheStaticLeanIsReported) {
  hal::SensorFrame frame;
  SimRobot upright(box_world(10.0, 10.0, {5.0, 5.0, 0.0}), SimConfig{});
  frame = run(upright, drive(1.0), 50);
  EXPECT_TRUE(frame.body.valid);
  EXPECT_EQ(frame.body.stamp, frame.stamp);
  EXPECT_EQ(frame.body.tilt.pitch, 0.0);
  EXPECT_EQ(frame.body.tilt.roll, 0.0);

  SimConfig config;
  config.body.pitch = 0.08;
  config.body.roll = -0.03;
  SimRobot leaning(box_world(10.0, 10.0, {5.0, 5.0, 0.0}), config);
  frame = run(leaning, drive(1.0), 50);
  EXPECT_EQ(frame.body.tilt.pitch, 0.08);
  EXPECT_EQ(frame.body.tilt.roll, -0.03);
}

// The sway: none standing still, up to its amplitude at full speed, the same for the same seed,
// shifted in phase for another seed.
TEST(SimRobotBody, SwayGrowsWithSpeedAndIsSeeded) {
  SimConfig config;
  config.body.pitch = 0.05;
  config.body.sway_pitch = 0.02;
  config.body.sway_roll = 0.04;
  config.body.sway_period = 0.5;
  const auto trace = [&](std::uint64_t seed, double velocity) {
    SimConfig c = config;
    c.seed = seed;
    SimRobot robot(box_world(40.0, 40.0, {20.0, 2.0, 0.0}), c);
    std::vector<hal::BodyTilt> tilts;
    hal::SensorFrame frame;
    for (int i = 0; i < 300; ++i) {
      robot.actuators().write(drive(velocity));
      robot.sensors().read(frame);
      tilts.push_back(frame.body.tilt);
    }
    return tilts;
  };
  const auto still = trace(1, 0.0);
  for (const auto& t : still) {
    EXPECT_EQ(t.pitch, 0.05);
    EXPECT_EQ(t.roll, 0.0);
  }
  const auto a = trace(1, 1.0);
  double max_roll = 0.0, max_pitch_sway = 0.0;
  for (std::size_t i = 150; i < a.size(); ++i) {  // at full speed (1 m/s after 1 s)
    max_roll = std::max(max_roll, std::fabs(a[i].roll));
    max_pitch_sway = std::max(max_pitch_sway, std::fabs(a[i].pitch - 0.05));
  }
  EXPECT_LE(max_roll, 0.04 + 1e-12);
  EXPECT_GT(max_roll, 0.039);  // a 0.5 s cycle sampled every 10 ms comes close to its peak
  EXPECT_LE(max_pitch_sway, 0.02 + 1e-12);
  EXPECT_GT(max_pitch_sway, 0.019);
  const auto again = trace(1, 1.0);
  const auto other = trace(2, 1.0);
  bool same = true, differs = false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    same = same && a[i].pitch == again[i].pitch && a[i].roll == again[i].roll;
    differs = differs || a[i].roll != other[i].roll;
  }
  EXPECT_TRUE(same);
  EXPECT_TRUE(differs);
}

// What the camera renders is the tilted view: the frame equals a renderer's picture for the
// reported torso tilt and head joints, and not the upright picture.
TEST(SimRobotBody, TheCameraRendersWithTheReportedTilt) {
  const World world = load_world(RINGLET_SIM_WORLDS_DIR "/spl_field.world");
  SimConfig config;
  config.camera.enabled = true;
  config.camera.format = hal::PixelFormat::kBgr8;
  config.body.pitch = hal::deg_to_rad(6.0);
  config.body.roll = hal::deg_to_rad(-4.0);
  config.seed = 5;
  SimRobot robot(world, config);
  hal::ActuatorCommand cmd;
  cmd.head = {0.2, 0.3};
  std::vector<hal::SensorFrame> frames(1);
  std::vector<hal::Pose2> poses(1);
  hal::FrameView view;
  bool delivered = false;
  for (int step = 1; step <= 6 && !delivered; ++step) {
    robot.actuators().write(cmd);
    hal::SensorFrame f;
    robot.sensors().read(f);
    frames.push_back(f);
    poses.push_back(robot.true_state().pose);
    delivered = robot.camera()->grab_latest(view);
  }
  ASSERT_TRUE(delivered);
  const FrameTruth* truth = robot.camera_truth();
  ASSERT_NE(truth, nullptr);
  const auto at = static_cast<std::size_t>(view.capture_time.count() / 10'000'000);
  const hal::SensorFrame& sensed = frames.at(at);
  EXPECT_EQ(truth->body.pitch, sensed.body.tilt.pitch);
  EXPECT_EQ(truth->body.roll, sensed.body.tilt.roll);

  CameraRenderer renderer(world, CameraSpec{config.camera.intrinsics, config.camera.mount}, config.seed);
  renderer.render(poses.at(at), hal::CameraPosture{sensed.body.tilt, sensed.head});
  const auto bytes = static_cast<std::size_t>(view.stride) * static_cast<std::size_t>(view.height);
  ASSERT_EQ(renderer.bgr().size(), bytes);
  EXPECT_EQ(std::memcmp(renderer.bgr().data(), view.data, bytes), 0);
  renderer.render(poses.at(at), sensed.head);
  EXPECT_NE(std::memcmp(renderer.bgr().data(), view.data, bytes), 0);
}

}  // namespace
}  // namespace ringlet::sim_hal
