// The configuration file: every bad value is refused with "file:line:col: key: message" and no
// configuration comes back; the shipped one and an 83 Hz variant load.
#include <gtest/gtest.h>

#include <algorithm>

#include "firmware_test_support.hpp"

namespace ringlet::firmware {
namespace {

using test::parse_as_shipped;
using test::shipped_config_text;
using test::with_line;
using test::error_of;

TEST(FirmwareConfig, ShippedConfigLoads) {
  const auto cfg = load_config(test::kShippedConfig);
  EXPECT_EQ(cfg.backend, "sim");
  EXPECT_EQ(cfg.executive.period, hal::Nanos{10'000'000});
  ASSERT_EQ(cfg.tasks.size(), 7U);
  EXPECT_EQ(cfg.tasks[0].name, "sense");
  ASSERT_NE(cfg.backend_settings, nullptr);
  EXPECT_EQ(cfg.backend_settings->source_name(), "courtyard.world");
  EXPECT_EQ(cfg.seed(), 42U);
  ASSERT_EQ(cfg.mission.goals.size(), 7U) << "the mission's goals come from the configuration";
  EXPECT_EQ(cfg.mission.goals[0].x, 2.0);
  EXPECT_EQ(cfg.mission.goals[6].y, 2.5);
}

TEST(FirmwareConfig, SeedOverrideWinsOverTheBackends) {
  auto cfg = load_config(test::kShippedConfig);
  cfg.seed_override = 7;
  EXPECT_EQ(cfg.seed(), 7U);
}

TEST(FirmwareConfig, SplConfigHasTheCameraAndAVisionTask) {
  const auto cfg = load_config(test::kSplConfig);
  EXPECT_EQ(cfg.camera.backend, "robot") << "the simulator renders the camera";
  EXPECT_EQ(cfg.camera.intrinsics.width, 640);
  EXPECT_EQ(cfg.vision.max_trials, 30);
  EXPECT_EQ(cfg.vision.skip, 10);
  EXPECT_EQ(cfg.vision.colour, "adaptive") << "no lut: the field colour is estimated per frame";
  const auto vision = std::find_if(cfg.tasks.begin(), cfg.tasks.end(), [](const auto& t) { return t.name == "vision"; });
  ASSERT_NE(vision, cfg.tasks.end());
  EXPECT_EQ(vision->every, 3);
  EXPECT_EQ(vision->budget, hal::Nanos{3'000'000});
  EXPECT_EQ(vision->policy, executive::OverrunPolicy::kDegrade);
}

// The black-and-white ball and the HOG/SVM models: relative model paths resolve against the
// configuration file's folder, like lut; the defaults are the orange ball, no models, robots on.
TEST(FirmwareConfig, VisionBallModeAndModels) {
  const auto defaults = parse_as_shipped(shipped_config_text());
  EXPECT_EQ(defaults.vision.ball, "orange");
  EXPECT_TRUE(defaults.vision.ball_model.empty());
  EXPECT_TRUE(defaults.vision.robot_model.empty());
  EXPECT_TRUE(defaults.vision.robots);
  const auto cfg = parse_as_shipped(with_line(shipped_config_text(), "[telemetry]",
                                              "[vision]\nball = \"bw\"\nball_model = \"models/b.hog\"\n"
                                              "robot_model = \"/abs/r.hog\"\nrobots = false\n[telemetry]"));
  EXPECT_EQ(cfg.vision.ball, "bw");
  EXPECT_EQ(cfg.vision.ball_model, test::kShippedConfig.parent_path() / "models/b.hog");
  EXPECT_EQ(cfg.vision.robot_model, std::filesystem::path("/abs/r.hog"));
  EXPECT_FALSE(cfg.vision.robots);
}

TEST(FirmwareConfig, EightyThreeHertzByConfiguration) {
  const auto cfg = parse_as_shipped(with_line(shipped_config_text(), "period_us", "period_us = 12000"));
  EXPECT_EQ(cfg.executive.period, hal::Nanos{12'000'000});
}

TEST(FirmwareConfig, MissingFileNamesIt) {
  try {
    (void)load_config("/nonexistent/ringlet.toml");
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/ringlet.toml: cannot read configuration file: No such file or directory");
  }
}

struct BadCase {
  const char* key;
  const char* line;
  const char* expected;  // a substring of the message, after "<file>:"
};

class BadConfig : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadConfig, IsRefusedWithFileLineAndKey) {
  const auto& c = GetParam();
  const std::string message = error_of(with_line(shipped_config_text(), c.key, c.line));
  EXPECT_EQ(message.rfind(test::kShippedConfig.string() + ":", 0), 0U) << message;
  EXPECT_NE(message.find(c.expected), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, BadConfig,
    ::testing::Values(
        BadCase{"backend", "backend = \"ros\"", "robot.backend: must be one of \"sim\", \"replay\", \"can\", got \"ros\""},
        BadCase{"seed", "seed = -3", "sim.seed: must be a non-negative integer"},
        BadCase{"max_speed", "max_speed = \"fast\"", "sim.max_speed: must be a number"},
        BadCase{"laser_beams", "laser_beams = 5000", "sim.laser_beams: must be between 1 and 721"},
        BadCase{"laser_beams", "laser_beams = 181\nbody_roll_deg = 25", "sim.body_roll_deg: must be between -20 and 20, got 25"},
        BadCase{"laser_beams", "laser_beams = 181\nbody_pitch_deg = nan", "sim.body_pitch_deg: must be between -30 and 30, got nan"},
        BadCase{"laser_beams", "laser_beams = 181\nbody_sway_period = 0", "sim.body_sway_period: must be between 0.05 and 60"},
        BadCase{"laser_beams", "laser_beams = 181\nkidnap = 3", "sim.kidnap: must be a table, e.g. { at_s = 10.0"},
        BadCase{"laser_beams", "laser_beams = 181\nkidnap = { at_s = 1.0, x = 0.0 }", "sim.kidnap.y: required in sim.kidnap"},
        BadCase{"laser_beams", "laser_beams = 181\nkidnap = { at_s = 1.0, x = 0.0, y = 0.0, z = 1 }",
                "sim.kidnap.z: unknown key in [sim.kidnap]"},
        BadCase{"period_us", "period_us = 10", "executive.period_us: must be between 1000 and 1000000"},
        BadCase{"clock", "clock = \"sundial\"", "executive.clock: must be one of"},
        BadCase{"cpu =", "cpu = 1.5", "executive.cpu: must be an integer"},
        BadCase{"gain", "gian = 2.0", "follower.gian: unknown key in [follower]"},
        BadCase{"[telemetry]", "[telemetri]", "telemetri: unknown key"},
        BadCase{"timeout_s", "timeout_s = ", ":"},  // TOML syntax error, still file:line:col
        BadCase{"  { name = \"sense\"", "  { name = \"sense\", every = 3, phase = 3, budget_us = 200 },",
                "executive.tasks[0].phase: must be between 0 and 2, got 3"},
        BadCase{"  { name = \"sense\"", "  { name = \"sense\", rate_hz = 30, budget_us = 200 },",
                "rate 30 Hz does not divide the base rate 100 Hz"},
        BadCase{"  { name = \"sense\"", "  { name = \"sense\", budget_us = 20000 },",
                "is larger than the period"},
        BadCase{"  { name = \"sense\"", "  { name = \"sense\", budget_us = 9900 },", "is overloaded: budgets of sense, goals, ball_sensor, fsm, actuate, telemetry, whiteboard"},
        BadCase{"  { name = \"sense\"", "  { name = \"sense\" },", "executive.tasks[0].budget_us: every task needs a budget"},
        BadCase{"  { name = \"sense\"", "  { name = \"sense\", budget_us = 200, policy = \"panic\" },",
                "policy: must be one of \"warn\", \"skip\", \"degrade\", \"failsafe\""},
        BadCase{"min_speed", "min_speed = 5.0", "follower.min_speed: must not exceed max_speed"},
        BadCase{"release_range_m", "release_range_m = 0.5", "safety.release_range_m: must be larger than stop_range_m"},
        BadCase{"[telemetry]", "[camera]\nwidth = 641\n[telemetry]", "camera.width: must be even"},
        BadCase{"[telemetry]", "[camera]\nbackend = \"opencv\"\n[telemetry]",
                "camera.source: the \"opencv\" camera needs a source"},
        BadCase{"[telemetry]", "[camera]\nformat = \"rgb565\"\n[telemetry]", "camera.format: must be one of \"yuyv\", \"bgr\""},
        BadCase{"[telemetry]", "[camera]\npitch_deg = 20\n[telemetry]", "camera.pitch_deg: must be between -15 and 15, got 20"},
        BadCase{"[telemetry]", "[vision]\nskip = 0\n[telemetry]", "vision.skip: must be between 1 and 1000"},
        BadCase{"[telemetry]", "[vision]\ncolour = \"lut\"\n[telemetry]",
                "vision.colour: must be one of \"adaptive\", \"table\", got \"lut\""},
        BadCase{"[telemetry]", "[vision]\nball = \"pink\"\n[telemetry]",
                "vision.ball: must be one of \"orange\", \"bw\", got \"pink\""},
        BadCase{"[telemetry]", "[vision]\nrobots = 1\n[telemetry]", "vision.robots: must be true or false"},
        BadCase{"[telemetry]", "[vision]\nball_model = 3\n[telemetry]", "vision.ball_model: must be a string"},
        BadCase{"[telemetry]", "[vision]\nrobot_model = false\n[telemetry]", "vision.robot_model: must be a string"},
        BadCase{"  { name = \"sense\"", "  { name = \"sense\", budget_us = 1.9 },",
                "executive.tasks[0].budget_us: must be a whole number of microseconds, got 1.9"},
        BadCase{"timeout_s", "timeout_s = 1e6", "mission.timeout_s: must be between 0.01 and 86400, got 1e+06"},
        BadCase{"timeout_s", "timeout_s = nan", "mission.timeout_s: must be between 0.01 and 86400, got nan"},
        BadCase{"goals", "# no goals", "mission.goals: the mission needs its goals"},
        BadCase{"timeout_s", "timeout_s = 300\nball_tracking = \"no\"", "mission.ball_tracking: must be true or false"},
        BadCase{"goals", "goals = []", "mission.goals: must be a non-empty array of [x, y] pairs"},
        BadCase{"goals", "goals = [[1, 2], [3]]", "mission.goals[1]: must be a pair of finite numbers [x, y]"},
        BadCase{"goals", "goals = [[1, \"north\"]]", "mission.goals[0]: must be a pair of finite numbers [x, y]"},
        BadCase{"goals", "goals = [[1, nan]]", "mission.goals[0]: must be a pair of finite numbers [x, y]"}));

TEST(FirmwareConfig, SimBackendNeedsAWorld) {
  const std::string message = error_of(with_line(shipped_config_text(), "world", "# no world"));
  EXPECT_NE(message.find("sim.world: the simulated robot needs a world file"), std::string::npos) << message;
}

}  // namespace
}  // namespace ringlet::firmware
