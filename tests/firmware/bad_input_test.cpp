// Bad input to the firmware binary, at library level: flag values (--duration, --seed), the run
// length the recording allows, input files that are not regular files, output paths checked
// before the run, and errors found after parsing that still name file:line:col. The binary's exit
// codes for the same cases are the FirmwareCli tests (tests/firmware/CMakeLists.txt).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <future>
#include <optional>
#include <regex>
#include <sstream>
#include <string>

#include "firmware_test_support.hpp"
#include "ringlet/firmware/command_line.hpp"
#include "ringlet/firmware/mission_report.hpp"
#include "ringlet/firmware/mission_runner.hpp"
#include "ringlet/firmware/output_file.hpp"
#include "ringlet/firmware/stack.hpp"
#include "ringlet/hal/read_file.hpp"
#include "ringlet/sim_hal/world.hpp"
#include "temp_dir.hpp"

namespace ringlet::firmware {
namespace {

namespace fs = std::filesystem;
using test::parse_as_shipped;
using test::shipped_config_text;
using test::with_line;

const fs::path kData = test::kShippedConfig.parent_path().parent_path().parent_path() / "tests/firmware/data";

template <typename Error, typename F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

using ringlet::test::TempDir;

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// --duration ---------------------------------------------------------------------------------

TEST(CommandLine, DurationRefusesWhatIsNotAFiniteNumberInRange) {
  for (const char* bad : {"nan", "inf", "-inf", "-1", "0", "-0", "1e12", "1e300", "1e999", "86400.001", "12abc", "",
                          " 5", "0x10", "5s"}) {
    const std::string m = error_of<UsageError>([&] { (void)parse_duration(bad); });
    EXPECT_EQ(m, "--duration: must be a number of seconds greater than 0 and at most 86400, got '" + std::string(bad) +
                     "'")
        << bad;
  }
}

TEST(CommandLine, DurationAcceptsTheRange) {
  EXPECT_EQ(parse_duration("2.5"), 2.5);
  EXPECT_EQ(parse_duration("86400"), kMaxRunSeconds);
  EXPECT_EQ(parse_duration("1e-3"), 1e-3);
}

TEST(CommandLine, LongValuesAreShortenedInTheMessage) {
  const std::string m = error_of<UsageError>([] { (void)parse_duration(std::string(5000, '9')); });
  EXPECT_LT(m.size(), 200U) << m;
  EXPECT_NE(m.find("...'"), std::string::npos) << m;
}

// --seed -------------------------------------------------------------------------------------

TEST(CommandLine, SeedRefusesSignsFractionsAndOverflow) {
  const std::string rule = "--seed: must be a whole number from 0 to 18446744073709551615, got ";
  for (const char* bad : {"-1", "+1", "1.5", "1e3", "", " 1", "seven", "0x10"}) {
    EXPECT_EQ(error_of<UsageError>([&] { (void)parse_seed(bad); }), rule + "'" + bad + "'") << bad;
  }
  EXPECT_EQ(error_of<UsageError>([] { (void)parse_seed("18446744073709551616"); }),
            rule + "'18446744073709551616' (too large)");
}

TEST(CommandLine, SeedAcceptsTheWholeRange) {
  EXPECT_EQ(parse_seed("0"), 0U);
  EXPECT_EQ(parse_seed("42"), 42U);
  EXPECT_EQ(parse_seed("18446744073709551615"), UINT64_MAX);
}

// Run length and recording ---------------------------------------------------------------------

TEST(RunLength, ShippedConfigurationAcceptsADay) {
  const auto cfg = load_config(test::kShippedConfig);
  EXPECT_EQ(run_length_problem(cfg, cfg.mission.timeout_s), "");
  EXPECT_EQ(run_length_problem(cfg, kMaxRunSeconds), "") << "10 ms, a sample every 10 frames: 864,002 samples";
  EXPECT_NE(run_length_problem(cfg, std::nan("")).find("got nan"), std::string::npos);
  EXPECT_NE(run_length_problem(cfg, 1e300).find("at most 86400"), std::string::npos);
}

TEST(RunLength, RecordingThatWouldNotFitIsRefusedWithTheFix) {
  const auto cfg = load_config(kData / "dense_trajectory.toml");  // 1 kHz, a sample every frame
  EXPECT_EQ(trajectory_samples(cfg, 2000.0), 2'000'002U);
  const std::string why = run_length_problem(cfg, 2000.0);
  EXPECT_NE(why.find("more than the 1000000 the firmware keeps"), std::string::npos) << why;
  EXPECT_NE(why.find("telemetry.trajectory_every to at least 3"), std::string::npos) << why;
  EXPECT_EQ(run_length_problem(cfg, 900.0), "");
}

TEST(RunLength, TimeoutThatWouldNotFitIsAConfigError) {
  auto text = with_line(shipped_config_text(), "timeout_s", "timeout_s = 86400");
  text = with_line(text, "trajectory_every", "trajectory_every = 1");
  const std::string m = error_of<ConfigError>([&] { (void)parse_as_shipped(text); });
  EXPECT_TRUE(std::regex_search(m, std::regex(R"(:\d+:\d+: mission\.timeout_s: a run of 86400 s records)"))) << m;
}

TEST(RunLength, TelemetryNeverReservesBeyondTheCap) {
  // 2^40 poses would be 24 TiB: a capacity no configuration is allowed to ask for.
  std::optional<Telemetry> telemetry;
  ASSERT_NO_THROW(telemetry.emplace(std::size_t{1} << 40, 16));
  Telemetry& t = *telemetry;
  for (int i = 0; i < 3; ++i) t.record_pose(hal::Pose2{});
  EXPECT_EQ(t.trajectory().size(), 3U);
  EXPECT_EQ(t.dropped_samples(), 0U);
}

// Input files ----------------------------------------------------------------------------------

TEST(InputFiles, ConfigThatIsADirectoryIsRefusedAsOne) {
  const std::string m = error_of<ConfigError>([] { (void)load_config(kData); });
  EXPECT_EQ(m, kData.string() + ": cannot read configuration file: not a regular file (a directory)");
}

TEST(InputFiles, ConfigThatIsADeviceIsNotRead) {
  const std::string m = error_of<ConfigError>([] { (void)load_config("/dev/zero"); });
  EXPECT_EQ(m, "/dev/zero: cannot read configuration file: not a regular file (a character device)");
}

TEST(InputFiles, ConfigThatIsAFifoDoesNotBlock) {
  TempDir dir;
  const fs::path fifo = dir.path() / "config.toml";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  auto result = std::async(std::launch::async, [&] { return error_of<ConfigError>([&] { (void)load_config(fifo); }); });
  ASSERT_EQ(result.wait_for(std::chrono::seconds(10)), std::future_status::ready) << "load_config blocked on a FIFO";
  EXPECT_EQ(result.get(), fifo.string() + ": cannot read configuration file: not a regular file (a FIFO)");
}

TEST(InputFiles, ConfigLargerThanTheLimitIsRefused) {
  TempDir dir;
  const fs::path big = dir.path() / "big.toml";
  {
    std::ofstream out(big);
    out << std::string(hal::kMaxTextFileBytes + 1, '#');
  }
  const std::string m = error_of<ConfigError>([&] { (void)load_config(big); });
  EXPECT_NE(m.find("too large"), std::string::npos) << m;
}

TEST(InputFiles, WorldThatIsADeviceOrDirectoryIsNotRead) {
  EXPECT_EQ(error_of<sim_hal::WorldError>([] { (void)sim_hal::load_world("/dev/zero"); }),
            "/dev/zero: cannot read world file: not a regular file (a character device)");
  EXPECT_EQ(error_of<sim_hal::WorldError>([] { (void)sim_hal::load_world(kData); }),
            kData.string() + ": cannot read world file: not a regular file (a directory)");
}

TEST(InputFiles, UnreadableWorldNamesTheConfigKeyThatNamedIt) {
  const auto cfg = load_config(kData / "world_dev_zero.toml");
  const std::string m = error_of<ConfigError>([&] { FirmwareStack stack(cfg); });
  EXPECT_EQ(m, (kData / "world_dev_zero.toml").string() +
                   ":3:9: sim.world: /dev/zero: cannot read world file: not a regular file (a character device)");
}

// Where errors found after parsing point -------------------------------------------------------

TEST(ConfigPositions, KeysAndTheirFallbacks) {
  const auto cfg = load_config(kData / "unknown_task.toml");
  const std::string file = (kData / "unknown_task.toml").string();
  EXPECT_EQ(cfg.positions.at("executive.tasks[0].name"), file + ":7:12");
  EXPECT_EQ(cfg.positions.at("executive.tasks[0]"), file + ":7:3");
  EXPECT_EQ(cfg.positions.at("executive.tasks[0].policy"), file + ":7:3") << "a default: the row";
  EXPECT_EQ(cfg.positions.at("executive.period_us"), file + ":5:1") << "a default: the table";
  EXPECT_EQ(cfg.positions.at("robot.backend"), file) << "no [robot] at all: the file";
}

TEST(ConfigPositions, UnknownTaskNamesItsRow) {
  const auto cfg = load_config(kData / "unknown_task.toml");
  const std::string m = error_of<ConfigError>([&] { FirmwareStack stack(cfg); });
  const std::string file = (kData / "unknown_task.toml").string();
  EXPECT_EQ(m.rfind(file + ":6:9: executive.tasks: the table names unknown tasks:", 0), 0U) << m;
  EXPECT_NE(m.find("\n  - " + file + ":7:12: executive.tasks[0].name: task 'senze' is not a task this firmware has ("),
            std::string::npos)
      << m;
}

TEST(ConfigPositions, StartPoseCollisionNamesTheWorldLineAndTheRadius) {
  const auto cfg = load_config(kData / "start_collides.toml");
  const std::string m = error_of<ConfigError>([&] { FirmwareStack stack(cfg); });
  EXPECT_EQ(m, (kData / "start_collides.world").string() +
                   ":5: start pose (2, 2) collides with an obstacle or the bounds for a robot of radius 0.25 m "
                   "(sim.robot_radius, " +
                   (kData / "start_collides.toml").string() + ":5:16)");
}

TEST(ConfigPositions, GoalOutsideTheWorldNamesTheGoalAndTheWorld) {
  const auto cfg = parse_as_shipped(with_line(shipped_config_text(), "goals", "goals = [[2, 6], [30, 6]]"));
  const std::string m = error_of<ConfigError>([&] { FirmwareStack stack(cfg); });
  EXPECT_TRUE(std::regex_search(m, std::regex(R"(^.*courtyard\.toml:\d+:\d+: mission\.goals\[1\]: \(30, 6\) lies outside the world .*courtyard\.world \(bounds 0 0 20 14\)$)")))
      << m;
}

TEST(ConfigPositions, TheCanSectionIsReadAndItsBadValuesNamed) {
  const FirmwareConfig cfg = load_config(kData / "can_backend.toml");
  EXPECT_EQ(cfg.backend, "can");
  EXPECT_EQ(cfg.backend_settings->source_name(), "CAN ringletcan9");
  const auto bad = [](const std::string& line) {
    return error_of<ConfigError>([&] { (void)parse_as_shipped(with_line(shipped_config_text(), "[mission]", line + "\n[mission]")); });
  };
  EXPECT_NE(bad("[can]\ninterface = \"a-name-longer-than-15\"").find("can.interface: must be a network interface name of 1 to 15"),
            std::string::npos);
  EXPECT_NE(bad("[can]\nheartbeat_timeout_ms = 5").find("can.heartbeat_timeout_ms"), std::string::npos);
  EXPECT_NE(bad("[can]\nbitrate = 500000").find("can.bitrate: unknown key in [can]"), std::string::npos);
}

TEST(ConfigPositions, BudgetMustBeWholeMicroseconds) {
  const std::string m = error_of<ConfigError>([] { (void)load_config(kData / "budget_fraction.toml"); });
  EXPECT_EQ(m, (kData / "budget_fraction.toml").string() +
                   ":7:38: executive.tasks[0].budget_us: must be a whole number of microseconds, got 1.9");
  const auto cfg = parse_as_shipped(with_line(shipped_config_text(), "  { name = \"sense\"",
                                              "  { name = \"sense\", budget_us = 200.0 },"));
  EXPECT_EQ(cfg.tasks[0].budget, hal::Nanos{200'000}) << "a whole number written as a float is fine";
}

TEST(ConfigPositions, OverloadedHyperperiodListsTwentyProblemsAndCountsTheRest) {
  const std::string m = error_of<ConfigError>([] { (void)load_config(kData / "overloaded_table.toml"); });
  EXPECT_LT(m.size(), 8000U);
  EXPECT_NE(m.find("frame 19 (mod 100000) is overloaded"), std::string::npos) << m;
  EXPECT_EQ(m.find("frame 20 (mod"), std::string::npos) << m;
  EXPECT_NE(m.find("\n  - ... and 99980 more problems"), std::string::npos) << m;
}

TEST(ConfigPositions, TableWithTooManyRowsIsRefusedAtTheArray) {
  std::string rows;
  for (int i = 0; i < 65; ++i) rows += "  { name = \"t" + std::to_string(i) + "\", budget_us = 1 },\n";
  const std::string text = "[sim]\nworld = \"blocked.world\"\n[executive]\ntasks = [\n" + rows + "]\n";
  const std::string m = error_of<ConfigError>([&] { (void)parse_config(text, "many.toml", kData); });
  EXPECT_EQ(m, "many.toml:4:9: executive.tasks: has 65 rows; at most 64 are allowed");
}

// Outputs --------------------------------------------------------------------------------------

TEST(OutputFile, MissingFolderIsRefusedBeforeAnythingRuns) {
  const std::string m =
      error_of<OutputError>([] { PendingOutput out("/nonexistent/folder/report.json", "--report", "the report"); });
  EXPECT_EQ(m, "--report /nonexistent/folder/report.json: cannot write the report: the folder /nonexistent/folder does "
               "not exist");
}

TEST(OutputFile, DirectoryOrDeviceIsRefused) {
  TempDir dir;
  EXPECT_EQ(error_of<OutputError>([&] { PendingOutput out(dir.path(), "--svg", "the picture"); }),
            "--svg " + dir.path().string() + ": cannot write the picture: the path is a directory, not a file");
  EXPECT_EQ(error_of<OutputError>([] { PendingOutput out("/dev/null", "--svg", "the picture"); }),
            "--svg /dev/null: cannot write the picture: the path is a character device, not a file");
  EXPECT_EQ(error_of<OutputError>([&] { PendingOutput out(dir.path() / "x" / "..", "--svg", "the picture"); }),
            "--svg " + (dir.path() / "x" / "..").string() + ": cannot write the picture: the path names a directory, not a file");
}

TEST(OutputFile, WrittenWholeAtCommitAndTheOldFileKeptUntilThen) {
  TempDir dir;
  const fs::path target = dir.path() / "report.json";
  {
    std::ofstream(target) << "old";
  }
  {
    PendingOutput out(target, "--report", "the report");
    EXPECT_EQ(read_text(target), "old") << "claiming does not touch the target";
    EXPECT_EQ(out.commit("new\n"), "");
  }
  EXPECT_EQ(read_text(target), "new\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator{}), 1) << "no temporary left";
  struct stat st {};
  ASSERT_EQ(::stat(target.c_str(), &st), 0);
  EXPECT_NE(st.st_mode & S_IRGRP, 0U) << "permissions as a plain new file, not mkstemp's 0600";
}

TEST(OutputFile, AnAbandonedOutputLeavesNothingBehind) {
  TempDir dir;
  { PendingOutput out(dir.path() / "run.svg", "--svg", "the picture"); }
  EXPECT_TRUE(fs::is_empty(dir.path()));
}

TEST(OutputFile, AFailedCommitNamesThePathAndLeavesTheTargetAlone) {
  TempDir dir;
  const fs::path folder = dir.path() / "vanishing";
  fs::create_directory(folder);
  PendingOutput out(folder / "report.json", "--report", "the report");
  fs::remove_all(folder);  // the folder disappears during the run
  const std::string m = out.commit("{}\n");
  EXPECT_EQ(m.rfind("--report " + (folder / "report.json").string() + ": cannot write the report: ", 0), 0U) << m;
  EXPECT_FALSE(fs::exists(folder / "report.json"));
}

// Signals --------------------------------------------------------------------------------------

TEST(Signals, InterruptedRunIsASafeStateWithTheSignalNamedAndExitCode128PlusN) {
  auto text = with_line(shipped_config_text(), "timeout_s", "timeout_s = 60");
  const auto cfg = parse_as_shipped(text);
  FirmwareStack stack(cfg);
  std::atomic<bool> interrupt{true};  // as the handler leaves it: interrupt and the executive's stop flag
  stack.executive().request_stop();
  std::ostringstream log;
  auto outcome = run_mission(stack, cfg.mission.timeout_s, interrupt, log);
  outcome.signal = SIGTERM;
  const auto s = summarize(stack, outcome, false);
  EXPECT_TRUE(s.interrupted);
  EXPECT_TRUE(s.safe_state);
  EXPECT_TRUE(s.safe_at_end);
  EXPECT_EQ(s.safe_state_reason, "SIGTERM");
  EXPECT_EQ(exit_code(s), 143);
  std::ostringstream printed;
  print_summary(printed, s);
  EXPECT_NE(printed.str().find("safe state forced: yes (SIGTERM)"), std::string::npos) << printed.str();
  const auto j = summary_json(s);
  EXPECT_EQ(j.at("safe_state_forced"), true);
  EXPECT_EQ(j.at("safe_state_reason"), "SIGTERM");
  EXPECT_EQ(j.at("signal"), "SIGTERM");
  EXPECT_EQ(j.at("safe_state_at_end"), true);
}

TEST(Signals, ExitCodesFollow128PlusTheSignalNumber) {
  MissionSummary s;
  s.interrupted = true;
  for (const int signo : kStopSignals) {
    s.signal = signo;
    EXPECT_EQ(exit_code(s), 128 + signo) << signal_name(signo);
  }
  s.signal = 0;
  EXPECT_EQ(exit_code(s), 130) << "an interrupt of unknown origin counts as SIGINT";
  EXPECT_EQ(signal_name(SIGHUP), "SIGHUP");
  EXPECT_EQ(signal_name(SIGQUIT), "SIGQUIT");
}

TEST(Signals, ANormalRunRecordsNoSafeStateReason) {
  MissionSummary s;
  s.complete = true;
  const auto j = summary_json(s);
  EXPECT_TRUE(j.at("safe_state_reason").is_null());
  EXPECT_TRUE(j.at("signal").is_null());
  EXPECT_EQ(exit_code(s), 0);
}

}  // namespace
}  // namespace ringlet::firmware
