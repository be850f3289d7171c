// A firmware run with [remote] enabled, watched over DDS on loopback from another process: the
// monitor receives every FsmStatus of the lockstep run, in order, nothing lost (the bridge paces a
// lockstep run on the monitor's acknowledgements); the run computes exactly what it computes
// unwatched (same hashes); and [remote] refuses bad settings with file:line:col.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "firmware_test_support.hpp"
#include "ringlet/firmware/mission_report.hpp"
#include "ringlet/firmware/mission_runner.hpp"
#include "ringlet/firmware/stack.hpp"
#include "ringlet/remote/domain.hpp"

namespace ringlet::firmware {
namespace {

using namespace std::chrono_literals;
using test::parse_as_shipped;
using test::shipped_config_text;
using test::with_line;

std::string partition_of_this_test() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return "ringlet-test-" + std::to_string(::getpid()) + "-" + info->name();
}

// The shipped courtyard mission cut to `seconds`, published as robot 4 in `partition`.
std::string remote_config(const std::string& partition, double seconds, int wait_for_monitors) {
  std::string text = shipped_config_text();
  text = with_line(text, "timeout_s", "timeout_s = " + std::to_string(seconds));
  text += "\n[remote]\nenabled = true\nrobot = 4\npartition = \"" + partition + "\"\nwait_for_monitors = " +
          std::to_string(wait_for_monitors) + "\nwait_timeout_s = 30\n";
  return text;
}

MissionSummary run(const std::string& text) {
  const FirmwareConfig cfg = parse_as_shipped(text);
  FirmwareStack stack(cfg);
  std::atomic<bool> interrupt{false};
  std::ostringstream log;
  const RunOutcome o = run_mission(stack, cfg.mission.timeout_s, interrupt, log);
  return summarize(stack, o, false);
}

TEST(FirmwareRemote, AMonitorInAnotherProcessGetsEveryFsmStatusOfALockstepRun) {
  const std::string partition = partition_of_this_test();
  int pipe_fds[2];
  ASSERT_EQ(::pipe(pipe_fds), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {  // the robot: runs 10 s of the mission once the monitor listens
    ::close(pipe_fds[0]);
    int rc = 1;
    try {
      const MissionSummary s = run(remote_config(partition, 10.0, 1));
      const std::uint64_t report[2] = {s.fsm_status_seen, s.remote ? s.remote->fsm_status.sent : 0};
      rc = ::write(pipe_fds[1], report, sizeof report) == sizeof report ? 0 : 2;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "robot process: %s\n", e.what());
      rc = 3;
    }
    ::_exit(rc);
  }
  ::close(pipe_fds[1]);
  std::vector<remote::DdsType<wb::FsmStatus>::Sample> got;
  {
    remote::Participant monitor({0, partition, ""});
    const dds_entity_t reader = monitor.reader<wb::FsmStatus>(true);
    std::vector<remote::DdsType<wb::FsmStatus>::Sample> buf(64);
    void* ptrs[64];
    dds_sample_info_t infos[64];
    for (std::size_t i = 0; i < buf.size(); ++i) ptrs[i] = &buf[i];
    const auto take = [&] {
      for (dds_return_t n = 64; n == 64;) {
        n = dds_take(reader, ptrs, infos, 64, 64);
        for (dds_return_t i = 0; i < n; ++i) {
          if (infos[i].valid_data) got.push_back(buf[static_cast<std::size_t>(i)]);
        }
      }
    };
    int wstatus = 0;
    const auto end = std::chrono::steady_clock::now() + 120s;
    while (::waitpid(child, &wstatus, WNOHANG) == 0 && std::chrono::steady_clock::now() < end) {
      take();
      std::this_thread::sleep_for(1ms);
    }
    take();  // the run acknowledged everything before it ended: it is all here
    ASSERT_TRUE(WIFEXITED(wstatus)) << "the robot process did not finish";
    ASSERT_EQ(WEXITSTATUS(wstatus), 0) << "the robot process: 2 could not report, 3 threw (its message is above)";
  }
  std::uint64_t report[2] = {0, 0};
  ASSERT_EQ(::read(pipe_fds[0], report, sizeof report), static_cast<ssize_t>(sizeof report));
  ::close(pipe_fds[0]);
  const std::uint64_t seen = report[0];  // FsmStatus the robot's own whiteboard subscription saw
  ASSERT_GT(seen, 100U);
  EXPECT_EQ(report[1], seen) << "the bridge sent fewer FsmStatus than the whiteboard carried";
  ASSERT_EQ(got.size(), seen);
  std::vector<bool> generation_seen(seen + 1, false);
  std::map<std::string, std::uint64_t> last_ringlets;
  for (const auto& s : got) {
    EXPECT_EQ(s.robot, 4);
    ASSERT_TRUE(s.generation >= 1 && s.generation <= seen) << s.generation;
    EXPECT_FALSE(generation_seen[s.generation]) << "generation " << s.generation << " twice";
    generation_seen[s.generation] = true;
    std::uint64_t& last = last_ringlets[s.machine];
    EXPECT_GE(s.ringlets, last) << s.machine << " out of order";
    last = s.ringlets;
  }
  EXPECT_EQ(last_ringlets.size(), 3U);  // BallTracker, Mission, Safety
}

TEST(FirmwareRemote, ARunComputesTheSameWithTheBridgeAsWithout) {
  const std::string base = with_line(shipped_config_text(), "timeout_s", "timeout_s = 10");
  const MissionSummary plain = run(base);
  const MissionSummary watched = run(remote_config(partition_of_this_test(), 10.0, 0));
  EXPECT_EQ(watched.trajectory_hash, plain.trajectory_hash);
  EXPECT_EQ(watched.run_hash, plain.run_hash);
  ASSERT_TRUE(watched.remote.has_value());
  EXPECT_FALSE(plain.remote.has_value());
  EXPECT_EQ(watched.remote->fsm_status.sent, watched.fsm_status_seen);
  EXPECT_EQ(watched.remote->totals.missed, 0U);
  EXPECT_EQ(watched.remote->totals.failed, 0U);
}

// A lockstep run of `seconds` as robot 4 accepting FsmControl, with `send` writing requests from a
// monitor (this process) once the robot's bridge reads them, before the first frame.
template <class Send>
MissionSummary run_with_requests(const std::string& partition, double seconds, Send send) {
  const std::string text = remote_config(partition, seconds, 0) + "accept = [\"FsmControl\"]\n";
  const FirmwareConfig cfg = parse_as_shipped(text);
  FirmwareStack stack(cfg);
  remote::Participant monitor({0, partition, ""});
  send(monitor);
  std::atomic<bool> interrupt{false};
  std::ostringstream log;
  const RunOutcome o = run_mission(stack, cfg.mission.timeout_s, interrupt, log);
  return summarize(stack, o, false);
}

// Writes `msg` as a request to robot 4 once a robot reads T's requests, and waits until it has it.
template <wb::Message T>
void send_request(remote::Participant& monitor, const T& msg) {
  const dds_entity_t w = monitor.request_writer<T>();
  const auto end = std::chrono::steady_clock::now() + 20s;
  dds_publication_matched_status_t st{};
  while ((dds_get_publication_matched_status(w, &st) < 0 || st.current_count == 0) && std::chrono::steady_clock::now() < end) {
    std::this_thread::sleep_for(2ms);
  }
  ASSERT_EQ(st.current_count, 1U) << "the robot's bridge never read " << T::kName << " requests";
  typename remote::DdsType<T>::Sample sample{};
  remote::to_sample(msg, 4, 1, sample);
  ASSERT_EQ(dds_write(w, &sample), DDS_RETCODE_OK);
  ASSERT_EQ(dds_wait_for_acks(w, DDS_SECS(20)), DDS_RETCODE_OK);
}

const MachineSummary* machine(const MissionSummary& s, std::string_view name) {
  for (const auto& m : s.machines) {
    if (m.name == name) return &m;
  }
  return nullptr;
}

TEST(FirmwareRemote, AnAllowedRemoteControlSuspendsAMachine) {
  // BallTracker: nothing else in the controller suspends or resumes it (Safety does Mission).
  const MissionSummary s = run_with_requests(partition_of_this_test(), 5.0, [](remote::Participant& monitor) {
    wb::FsmControl suspend;
    suspend.machine = "BallTracker";
    suspend.command = wb::kSuspend;
    send_request(monitor, suspend);
  });
  ASSERT_TRUE(s.remote.has_value());
  EXPECT_EQ(s.remote->requests.accepted, 1U);
  const MachineSummary* tracker = machine(s, "BallTracker");
  ASSERT_NE(tracker, nullptr);
  EXPECT_TRUE(tracker->suspended) << "BallTracker ends in " << tracker->state;
  // Delivered at the second frame's whiteboard task, applied at the next turn: of 500 turns it ran
  // only the first few.
  EXPECT_LT(tracker->ringlets, 5U);
}

TEST(FirmwareRemote, RefusedRemoteWritesAreCountedAndChangeNothing) {
  const std::string base = with_line(shipped_config_text(), "timeout_s", "timeout_s = 5");
  const MissionSummary plain = run(base);
  const MissionSummary s = run_with_requests(partition_of_this_test(), 5.0, [](remote::Participant& monitor) {
    wb::FsmControl unknown_machine;  // malformed: this robot has no such machine
    unknown_machine.machine = "Goalkeeper";
    unknown_machine.command = wb::kSuspend;
    send_request(monitor, unknown_machine);
    wb::MotionCommand drive;  // not on the allow-list
    drive.velocity = 3.0;
    send_request(monitor, drive);
  });
  ASSERT_TRUE(s.remote.has_value());
  EXPECT_EQ(s.remote->requests.accepted, 0U);
  EXPECT_EQ(s.remote->requests.malformed, 1U);
  EXPECT_EQ(s.remote->requests.unauthorized, 1U);
  // Nothing of them reached the whiteboard: the run is bit-identical to one nobody wrote to.
  EXPECT_EQ(s.trajectory_hash, plain.trajectory_hash);
  EXPECT_EQ(s.run_hash, plain.run_hash);
}

TEST(FirmwareRemote, ATypeWithAWriterInTheControllerCannotBeAccepted) {
  try {
    (void)FirmwareStack(parse_as_shipped(remote_config("x", 5.0, 0) + "accept = [\"MissionGoals\"]\n"));
    FAIL() << "accepted a second writer of MissionGoals";
  } catch (const ConfigError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("remote.accept: \"MissionGoals\" is posted by task 'goals' ("), std::string::npos) << what;
    EXPECT_NE(what.find("a remote writer would be its second writer"), std::string::npos) << what;
  }
}

TEST(FirmwareRemote, BadRemoteSettingsAreRefusedWithWhere) {
  const std::string base = shipped_config_text();
  const auto fails_with = [&](const std::string& section, const std::string& expected) {
    try {
      (void)parse_as_shipped(base + "\n[remote]\n" + section + "\n");
      ADD_FAILURE() << "accepted: " << section;
    } catch (const ConfigError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(expected), std::string::npos) << what;
      EXPECT_NE(what.find("courtyard.toml:"), std::string::npos) << what;
    }
  };
  fails_with("domain = 300", "remote.domain: must be between 0 and 232");
  fails_with("robot = -1", "remote.robot");
  fails_with("max_rate_hz = { Laserscan = 10 }", "remote.max_rate_hz.Laserscan: no whiteboard type");
  fails_with("max_rate_hz = { LaserScan = 0 }", "remote.max_rate_hz.LaserScan: must be");
  fails_with("unpublished = [\"Nope\"]", "remote.unpublished: no whiteboard type \"Nope\"");
  fails_with("partition = \"\"", "remote.partition: must be 1 to 256");
  fails_with("enable = true", "remote.enable: unknown key");
  fails_with("accept = [\"FsmKontrol\"]", "remote.accept: no whiteboard type \"FsmKontrol\"");
  fails_with("accept = \"FsmControl\"", "remote.accept: must be an array of type names");
}

}  // namespace
}  // namespace ringlet::firmware
