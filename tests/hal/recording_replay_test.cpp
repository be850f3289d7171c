// RecordingRobot and ReplayRobot: a run through a scripted robot, recorded and replayed, gives the
// controller the same sensor frames, ball sightings and camera frames at the same reads; the same
// run records the same bytes; drops are counted and marked; write errors are reported.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <csignal>
#include <cstring>
#include <string>
#include <vector>

#include "fake_robot.hpp"
#include "log_test_support.hpp"
#include "ringlet/hal/recording_robot.hpp"
#include "ringlet/hal/replay_robot.hpp"

namespace {

using namespace ringlet::hal;
using namespace ringlet::hal::test;

constexpr Nanos kPeriod{10'000'000};

/// What the controller saw in one cycle.
struct Cycle {
  bool ok = false;
  SensorFrame frame{};
  bool ball_ok = false;
  BallSighting ball{};
  bool grabbed = false;
  std::uint64_t sequence = 0;
  Nanos capture{0};
  int width = 0, height = 0, stride = 0;
  std::vector<std::uint8_t> pixels;
};

/// A firmware-like loop: a grab before the first read, then per cycle: sense, ball, and (every
/// other cycle, like a slower vision task) a camera grab.
std::vector<Cycle> run(Robot& robot, std::size_t cycles) {
  std::vector<Cycle> seen;
  if (robot.camera() != nullptr) {
    FrameView v;
    EXPECT_FALSE(robot.camera()->grab_latest(v));  // nothing captured before the first read
  }
  for (std::size_t i = 0; i < cycles; ++i) {
    Cycle c;
    c.ok = robot.sensors().read(c.frame);
    if (robot.ball_sensor() != nullptr) c.ball_ok = robot.ball_sensor()->read(c.ball);
    FrameView v;
    if (robot.camera() != nullptr && i % 2 == 0 && robot.camera()->grab_latest(v)) {
      c.grabbed = true;
      c.sequence = v.sequence;
      c.capture = v.capture_time;
      c.width = v.width;
      c.height = v.height;
      c.stride = v.stride;
      c.pixels.assign(v.data, v.data + static_cast<std::ptrdiff_t>(v.stride) * v.height);
    }
    robot.actuators().write(ActuatorCommand{DriveCommand{0.1, 0.2 + static_cast<double>(i)}, HeadTarget{}});
    seen.push_back(std::move(c));
  }
  return seen;
}

RecordingOptions options_for(const FakeRobot& robot, RecordMode mode = RecordMode::kLossless) {
  RecordingOptions o;
  o.mode = mode;
  o.period = kPeriod;
  o.note = "fake robot";
  o.max_camera_frame_bytes = robot.frame_bytes();
  return o;
}

std::vector<Cycle> record(const std::filesystem::path& path, std::size_t cycles, FakeRobotSetup setup = {}) {
  FakeRobot fake(setup);
  RecordingRobot recorder(fake, path, options_for(fake));
  auto seen = run(recorder, cycles);
  const RecordingStatus st = recorder.stop();
  EXPECT_TRUE(st.ok()) << st.error;
  EXPECT_EQ(st.dropped, 0u);
  EXPECT_EQ(fake.fake_actuators().writes, cycles);  // commands pass through
  return seen;
}

TEST(RecordingRobot, PassesEverythingThrough) {
  FakeRobot fake;
  const auto path = log_dir() / "pass.rlog";
  RecordingRobot recorder(fake, path, options_for(fake));
  EXPECT_EQ(recorder.backend_name(), "fake");
  EXPECT_NE(recorder.camera(), nullptr);
  EXPECT_NE(recorder.ball_sensor(), nullptr);
  EXPECT_EQ(recorder.ground_truth(), nullptr);
  recorder.actuators().enter_safe_state();
  EXPECT_TRUE(fake.actuators().in_safe_state());
  FakeRobot plain;
  const auto through = run(recorder, 20);
  const auto direct = run(plain, 20);
  for (std::size_t i = 0; i < through.size(); ++i) {
    expect_same_frame(through[i].frame, direct[i].frame, i);
    EXPECT_EQ(through[i].pixels, direct[i].pixels);
  }
}

TEST(RecordingRobot, TheSameRunRecordsTheSameBytes) {
  const auto a = log_dir() / "same_a.rlog";
  const auto b = log_dir() / "same_b.rlog";
  record(a, 60);
  record(b, 60);
  const auto bytes_a = file_bytes(a);
  EXPECT_GT(bytes_a.size(), 60u * (kSensorFixedBytes + 721 * kBytesPerBeam));
  EXPECT_EQ(bytes_a, file_bytes(b));
}

TEST(ReplayRobot, ReplaysWhatTheRecordedRunSawAtTheSameReads) {
  const auto path = log_dir() / "replay.rlog";
  constexpr std::size_t kCycles = 100;
  const auto recorded = record(path, kCycles);

  ReplayRobot replay(path);
  EXPECT_EQ(replay.backend_name(), "replay");
  EXPECT_EQ(replay.period(), kPeriod);
  EXPECT_EQ(replay.summary().header.note, "fake robot");
  EXPECT_EQ(replay.ground_truth(), nullptr);
  ASSERT_NE(replay.camera(), nullptr);
  ASSERT_NE(replay.ball_sensor(), nullptr);
  EXPECT_EQ(replay.summary().sensor_records, kCycles);
  EXPECT_TRUE(replay.summary().complete);

  const auto replayed = run(replay, kCycles);
  std::size_t grabs = 0;
  for (std::size_t i = 0; i < kCycles; ++i) {
    const Cycle& r = recorded[i];
    const Cycle& p = replayed[i];
    EXPECT_EQ(r.ok, p.ok) << i;
    expect_same_frame(r.frame, p.frame, i);
    EXPECT_EQ(r.ball_ok, p.ball_ok) << i;
    EXPECT_EQ(r.ball.stamp, p.ball.stamp) << i;
    EXPECT_EQ(r.ball.seen, p.ball.seen) << i;
    EXPECT_EQ(r.ball.at.x, p.ball.at.x) << i;
    EXPECT_EQ(r.grabbed, p.grabbed) << i;
    EXPECT_EQ(r.sequence, p.sequence) << i;
    EXPECT_EQ(r.capture, p.capture) << i;
    EXPECT_EQ(r.width, p.width) << i;
    EXPECT_EQ(r.height, p.height) << i;
    EXPECT_EQ(r.stride, p.stride) << i;
    EXPECT_EQ(r.pixels, p.pixels) << i;
    grabs += p.grabbed ? 1 : 0;
  }
  EXPECT_EQ(grabs, kCycles / 2);
  EXPECT_FALSE(replay.end_of_log());
  EXPECT_EQ(replay.reads(), kCycles);
  SensorFrame after;
  EXPECT_FALSE(replay.sensors().read(after));
  EXPECT_TRUE(replay.end_of_log());
  EXPECT_TRUE(replay.error().empty()) << replay.error();

  // Actuators: counted, the last kept, ignored once the safe state is latched.
  EXPECT_EQ(replay.replay_actuators().commands(), kCycles);
  EXPECT_EQ(replay.replay_actuators().last_command().drive.velocity, 0.2 + static_cast<double>(kCycles - 1));
  replay.actuators().enter_safe_state();
  replay.actuators().write(ActuatorCommand{});
  EXPECT_TRUE(replay.actuators().in_safe_state());
  EXPECT_EQ(replay.replay_actuators().commands(), kCycles);
}

TEST(ReplayRobot, HasACameraAndABallSensorOnlyIfTheLogHasTheirRecords) {
  const auto path = log_dir() / "bare.rlog";
  FakeRobotSetup setup;
  setup.camera = false;
  setup.ball = false;
  setup.beams = 0;
  record(path, 5, setup);
  ReplayRobot replay(path);
  EXPECT_EQ(replay.camera(), nullptr);
  EXPECT_EQ(replay.ball_sensor(), nullptr);
  EXPECT_EQ(replay.summary().sensor_records, 5u);
}

TEST(ReplayRobot, LogsWithGapsAreRefusedUnlessAllowed) {
  // Camera slots too small for the camera's frames: every new frame is dropped and marked.
  FakeRobot fake;
  const auto path = log_dir() / "gaps.rlog";
  {
    RecordingOptions o = options_for(fake);
    o.max_camera_frame_bytes = fake.frame_bytes() - 1;
    RecordingRobot recorder(fake, path, o);
    (void)run(recorder, 12);
    const RecordingStatus st = recorder.stop();
    // Grabs at cycles 0, 2, 4, 6, 8, 10 see frames 0, 0, 1, 2, 2, 3: four new sequences.
    EXPECT_EQ(st.dropped, 4u);
    EXPECT_NE(st.error.find("4 camera frame(s) not recorded"), std::string::npos) << st.error;
  }
  try {
    ReplayRobot replay(path);
    ADD_FAILURE() << "a log with gaps was accepted";
  } catch (const LogError& e) {
    EXPECT_NE(std::string(e.what()).find("the recorder dropped 4 records (0 sensor, 0 ball, 4 camera), the first "
                                         "after read 1"),
              std::string::npos)
        << e.what();
  }
  ReplayRobot replay(path, ReplayOptions{true, false});
  EXPECT_EQ(replay.summary().dropped_camera, 4u);
  EXPECT_EQ(replay.camera(), nullptr);  // nothing of it was recorded
  EXPECT_EQ(replay.summary().sensor_records, 12u);
}

TEST(RecordingRobot, DropOnFullNeverWaitsAndCountsWhatItDrops) {
  FakeRobot fake;
  const auto path = log_dir() / "drop.rlog";
  RecordingOptions o = options_for(fake, RecordMode::kDropOnFull);
  o.record_slots = 2;
  o.camera_slots = 1;
  RecordingRobot recorder(fake, path, o);
  (void)run(recorder, 3000);
  const RecordingStatus st = recorder.stop();
  EXPECT_TRUE(st.ok()) << st.error;
  // The writer cannot keep up with a 2-slot queue fed this fast, but how much it drops depends on
  // scheduling: what must hold is that the log accounts for every record, kept or dropped.
  const RobotLogSummary s = scan_robot_log(path);
  EXPECT_TRUE(s.complete);
  EXPECT_EQ(s.dropped(), st.dropped);
  EXPECT_EQ(s.sensor_reads, 3000u);
  EXPECT_EQ(s.sensor_records + s.dropped_sensor, 3000u);
  EXPECT_EQ(s.ball_records + s.dropped_ball, 3000u);
  EXPECT_EQ(s.sensor_records + s.ball_records + s.camera_records, st.records_written);
}

TEST(RecordingRobot, RefusesAPathItCannotCreateAndBadOptions) {
  FakeRobot fake;
  try {
    RecordingRobot recorder(fake, "/nonexistent/dir/run.rlog", options_for(fake));
    ADD_FAILURE() << "created";
  } catch (const LogError& e) {
    EXPECT_EQ(std::string(e.what()), "/nonexistent/dir/run.rlog: cannot create HAL log: No such file or directory");
  }
  EXPECT_THROW(RecordingRobot(fake, log_dir(), options_for(fake)), LogError);
  RecordingOptions no_frames = options_for(fake);
  no_frames.max_camera_frame_bytes = 0;
  EXPECT_THROW(RecordingRobot(fake, log_dir() / "x.rlog", no_frames), std::invalid_argument);
}

TEST(RecordingRobot, AWriteErrorIsReportedNotACrash) {
  // A file size limit makes write() fail with EFBIG once the log reaches it.
  std::signal(SIGXFSZ, SIG_IGN);
  rlimit old{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old), 0);
  rlimit small = old;
  small.rlim_cur = 64 * 1024;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  RecordingStatus st;
  {
    FakeRobot fake;
    RecordingRobot recorder(fake, log_dir() / "full.rlog", options_for(fake));
    (void)run(recorder, 200);
    st = recorder.stop();
  }
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &old), 0);
  EXPECT_FALSE(st.ok());
  EXPECT_NE(st.error.find("full.rlog: cannot write HAL log: File too large"), std::string::npos) << st.error;
  EXPECT_GT(st.records_written, 400u);  // the queue kept draining (else the run would hang)
}

}  // namespace
