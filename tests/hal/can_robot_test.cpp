// The SocketCAN board backend (hal/can/can_robot.hpp) over a socketpair that carries struct
// can_frame: the test plays the board. Sensors decode into the SensorFrame, commands go out, and
// every fault class gets its response: stale sensor, missed heartbeat, bus-off and error-passive,
// full transmit queue, malformed frame, unknown ID, socket failure and reconnection.
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cmath>
#include <initializer_list>
#include <memory>
#include <vector>

#include "ringlet/hal/can/can_robot.hpp"
#include "ringlet/hal/virtual_clock.hpp"

namespace ringlet::hal::can {
namespace {

using namespace std::chrono_literals;

std::pair<CanSocket, CanSocket> socket_pair() {
  int sv[2];
  if (::socketpair(AF_UNIX, SOCK_SEQPACKET, 0, sv) != 0) return {};
  return {CanSocket::adopt(sv[0]), CanSocket::adopt(sv[1])};
}

struct Bench {
  Bench() : clock(Nanos{1'000'000'000}) {
    auto [controller, b] = socket_pair();
    board = std::move(b);
    robot = std::make_unique<CanRobot>(settings, std::move(controller), clock, [this] {
      ++reopened;
      auto [controller2, b2] = socket_pair();
      board = std::move(b2);
      return std::move(controller2);
    });
  }
  void send(std::uint32_t id, std::initializer_list<double> v) {
    RawFrame raw;
    ASSERT_TRUE(encode(*find_frame(id), values_of(v), raw).ok());
    ASSERT_EQ(board.send(raw), SendStatus::kSent);
  }
  // The board's every-10-ms frames, with a heartbeat.
  void beat(double x = 1.0) {
    send(kBoardHeartbeatId, {7, 2, 0, 0});
    send(kPoseId, {x, 2.0, 0.25});
    send(kOdometryId, {12.5, 0.8, -0.1});
    send(kHeadJointsId, {0.3, 0.1});
    send(kInertialId, {0.02, -0.01});
    send(kBumperId, {0});
    send(kPowerId, {12.1, 24.0});
  }
  void scan(int number, int beams) {
    send(kLaserHeaderId, {static_cast<double>(number), static_cast<double>(beams), -1.5, 0.01, 10.0});
    const int chunks = (beams + 2) / 3;
    for (int c = 0; c < chunks; ++c) send(kLaserRangesId, {static_cast<double>(number), static_cast<double>(c), 1.0 + c, 2.0, 3.0});
  }
  std::vector<RawFrame> board_received() {
    std::vector<RawFrame> out;
    RawFrame f;
    while (board.receive(f) == ReceiveStatus::kFrame) out.push_back(f);
    return out;
  }
  bool read(SensorFrame& f) { return robot->sensors().read(f); }

  CanSettings settings;
  VirtualClock clock;
  CanSocket board;
  std::unique_ptr<CanRobot> robot;
  int reopened = 0;
};

TEST(CanRobot, BoardFramesBecomeTheSensorFrame) {
  Bench b;
  b.beat(1.5);
  b.scan(4, 7);
  SensorFrame f;
  EXPECT_TRUE(b.read(f));
  EXPECT_TRUE(f.pose.valid);
  EXPECT_NEAR(f.pose.pose.x, 1.5, 1e-9);
  EXPECT_NEAR(f.pose.pose.theta, 0.25, 1e-9);
  EXPECT_NEAR(f.odometry.distance, 12.5, 1e-9);
  EXPECT_NEAR(f.odometry.velocity, 0.8, 1e-9);
  EXPECT_NEAR(f.head.yaw, 0.3, 1e-9);
  EXPECT_TRUE(f.body.valid);
  EXPECT_NEAR(f.body.tilt.pitch, 0.02, 1e-9);
  EXPECT_NEAR(f.power.bus_volts, 24.0, 1e-9);
  EXPECT_FALSE(f.collided);
  ASSERT_EQ(f.laser.beam_count, 7);
  EXPECT_NEAR(f.laser.angle_increment, 0.01, 1e-9);
  EXPECT_NEAR(f.laser.range[0], 1.0, 1e-6);  // chunk 0, beam 0
  EXPECT_NEAR(f.laser.range[6], 3.0, 1e-6);  // chunk 2, beam 6: range0 of chunk 2
  EXPECT_TRUE(f.laser.valid[6]);
  EXPECT_TRUE(b.robot->health().board_alive);
  EXPECT_EQ(b.robot->health().malformed + b.robot->health().unknown_id, 0U);
}

TEST(CanRobot, CommandsGoOutWithAHeartbeatEveryTenth) {
  Bench b;
  for (int i = 0; i < 20; ++i) b.robot->actuators().write({{0.5, 1.25}, {0.2, -0.1}});
  int drives = 0, heads = 0, beats = 0;
  for (const RawFrame& f : b.board_received()) {
    const FrameSpec* spec = nullptr;
    Values v;
    ASSERT_TRUE(decode(f, spec, v).ok());
    if (f.id == kDriveId) {
      EXPECT_NEAR(v[0], 0.5, 1e-9);
      EXPECT_NEAR(v[1], 1.25, 1e-9);
      EXPECT_EQ(v[2], drives);  // the counter
      EXPECT_EQ(v[3], 1.0);
      ++drives;
    }
    heads += f.id == kHeadCommandId ? 1 : 0;
    beats += f.id == kControllerHeartbeatId ? 1 : 0;
  }
  EXPECT_EQ(drives, 20);
  EXPECT_EQ(heads, 20);
  EXPECT_EQ(beats, 2);
}

// The board echoes the last CTRL_DRIVE it applied in its heartbeat; the controller measures from
// sending that command to reading the echo.
TEST(CanRobot, TheRoundTripIsMeasuredFromTheBoardsEchoOfTheDriveCounter) {
  Bench b;
  SensorFrame f;
  for (int i = 0; i < 10; ++i) {
    b.robot->actuators().write({{0.1, 0.5}, {0.0, 0.0}});  // drive counter i
    b.clock.advance(std::chrono::milliseconds{i + 1});
    b.send(kBoardHeartbeatId, {static_cast<double>(i), 2, 0, static_cast<double>(i)});
    ASSERT_TRUE(b.read(f));
  }
  b.send(kBoardHeartbeatId, {10, 2, 0, 9});    // the same echo again: the board saw nothing new
  b.send(kBoardHeartbeatId, {11, 2, 0, 200});  // a counter never sent
  ASSERT_TRUE(b.read(f));
  const RoundTrip& rt = b.robot->health().round_trip;
  EXPECT_EQ(rt.samples, 10U);
  EXPECT_EQ(rt.p50_us, 5250U) << "the 5th of 1..10 ms, reported at its 250 us bin's upper edge";
  EXPECT_EQ(rt.p99_us, 10000U) << "the 10th, capped at the largest seen";
  EXPECT_EQ(rt.max_us, 10000U);
}

TEST(CanRobot, AStaleSensorIsInvalidInThatReading) {
  Bench b;
  b.beat();
  b.scan(1, 3);
  SensorFrame f;
  ASSERT_TRUE(b.read(f));
  b.clock.advance(60ms);  // past the 50 ms sensor timeout, inside the 300 ms heartbeat timeout
  b.send(kBoardHeartbeatId, {8, 2, 0, 0});
  EXPECT_TRUE(b.read(f)) << "the board answers: only the stale sensors are invalid";
  EXPECT_FALSE(f.pose.valid);
  EXPECT_FALSE(f.body.valid);
  EXPECT_EQ(b.robot->health().stale_readings, 1U);
  EXPECT_FALSE(b.robot->actuators().in_safe_state()) << "staleness is not a lost board";
}

TEST(CanRobot, AMissedBoardHeartbeatLatchesTheSafeState) {
  Bench b;
  b.beat();
  SensorFrame f;
  (void)b.read(f);
  (void)b.board_received();
  b.clock.advance(310ms);
  EXPECT_FALSE(b.read(f));
  EXPECT_TRUE(b.robot->board_lost());
  EXPECT_TRUE(b.robot->actuators().in_safe_state());
  EXPECT_EQ(b.robot->health().heartbeat_losses, 1U);
  bool safe_sent = false, stop_sent = false;
  for (const RawFrame& r : b.board_received()) {
    const FrameSpec* spec = nullptr;
    Values v;
    ASSERT_TRUE(decode(r, spec, v).ok());
    safe_sent = safe_sent || (r.id == kSafeStateId && v[0] == static_cast<double>(SafeReason::kBoardLost));
    stop_sent = stop_sent || (r.id == kDriveId && v[3] == 0.0 && v[1] == 0.0);
  }
  EXPECT_TRUE(safe_sent);
  EXPECT_TRUE(stop_sent);
  // Latched: a returning board does not make the controller drive again.
  b.beat();
  (void)b.read(f);
  EXPECT_FALSE(b.robot->board_lost());
  b.robot->actuators().write({{0.0, 1.0}, {}});
  for (const RawFrame& r : b.board_received()) EXPECT_NE(r.id, kDriveId) << "a drive command after the safe state";
}

TEST(CanRobot, BusOffAndErrorPassiveAreCountedAndABusOffReconnects) {
  Bench b;
  b.beat();
  ASSERT_TRUE(send_error_frame(b.board.fd(), BusState::kErrorPassive));
  SensorFrame f;
  (void)b.read(f);
  EXPECT_EQ(b.robot->health().error_passive, 1U);
  EXPECT_EQ(b.robot->health().bus, BusState::kErrorPassive);
  ASSERT_TRUE(send_error_frame(b.board.fd(), BusState::kBusOff));
  (void)b.read(f);
  EXPECT_EQ(b.robot->health().bus_off, 1U);
  EXPECT_EQ(b.reopened, 0);
  b.clock.advance(10ms);
  (void)b.read(f);  // the next read reopens
  EXPECT_EQ(b.reopened, 1);
  EXPECT_EQ(b.robot->health().reconnects, 1U);
  EXPECT_EQ(b.robot->health().bus, BusState::kActive);
  b.beat(2.5);
  (void)b.read(f);
  EXPECT_NEAR(f.pose.pose.x, 2.5, 1e-9) << "frames arrive on the new socket";
}

TEST(CanRobot, AFullTransmitQueueIsCountedAndNeverBlocks) {
  Bench b;
  // Nobody reads the board's end: the socketpair's buffer fills, then every send is refused.
  for (int i = 0; i < 5000 && b.robot->health().tx_full == 0; ++i) b.robot->actuators().write({{0.0, 0.5}, {}});
  EXPECT_GT(b.robot->health().tx_full, 0U);
  EXPECT_GT(b.robot->health().frames_sent, 0U);
}

TEST(CanRobot, MalformedFramesAndUnknownIdsAreCountedAndChangeNothing) {
  Bench b;
  b.beat(1.0);
  b.scan(1, 3);
  SensorFrame f;
  ASSERT_TRUE(b.read(f));
  const std::uint8_t fast[8] = {0, 0, 0, 0, 0x70, 0x17, 0, 0};  // odometry at 6 m/s: out of range
  ASSERT_TRUE(send_raw(b.board.fd(), kOdometryId, 8, fast));
  const std::uint8_t short_pose[5] = {1, 2, 3, 4, 5};
  ASSERT_TRUE(send_raw(b.board.fd(), kPoseId, 5, short_pose));
  ASSERT_TRUE(send_raw(b.board.fd(), 0x123, 8, fast));
  ASSERT_TRUE(send_raw(b.board.fd(), 0x80000123U, 8, fast));  // an extended frame
  (void)b.read(f);
  EXPECT_EQ(b.robot->health().malformed, 3U);
  EXPECT_EQ(b.robot->health().unknown_id, 1U);
  EXPECT_NEAR(f.odometry.velocity, 0.8, 1e-9) << "the last good value stands";
  EXPECT_NEAR(f.pose.pose.x, 1.0, 1e-9);
}

TEST(CanRobot, ACommandOutsideTheProtocolIsRefusedAndTheCarStopped) {
  Bench b;
  b.robot->actuators().write({{0.0, 9.0}, {}});  // 9 m/s: more than the board takes
  EXPECT_EQ(b.robot->health().refused_commands, 1U);
  bool stopped = false;
  for (const RawFrame& r : b.board_received()) {
    const FrameSpec* spec = nullptr;
    Values v;
    ASSERT_TRUE(decode(r, spec, v).ok());
    if (r.id == kDriveId) stopped = v[3] == 0.0 && v[1] == 0.0;
  }
  EXPECT_TRUE(stopped);
}

TEST(CanRobot, ASocketFailureIsCountedAndTheSocketReopened) {
  Bench b;
  b.board = CanSocket{};  // the board's end closes: the controller's recv sees the end
  SensorFrame f;
  (void)b.read(f);
  EXPECT_EQ(b.robot->health().socket_failures, 1U);
  b.clock.advance(10ms);
  (void)b.read(f);
  EXPECT_EQ(b.reopened, 1);
  b.beat(3.0);
  (void)b.read(f);
  EXPECT_NEAR(f.pose.pose.x, 3.0, 1e-9);
}

TEST(CanRobot, AnIncompleteScanIsCountedAndNotUsed) {
  Bench b;
  b.beat();
  b.send(kLaserHeaderId, {5, 9, -1.0, 0.01, 10.0});
  b.send(kLaserRangesId, {5, 0, 1.0, 1.0, 1.0});
  b.send(kLaserRangesId, {5, 2, 1.0, 1.0, 1.0});  // chunk 1 lost
  SensorFrame f;
  (void)b.read(f);
  EXPECT_EQ(b.robot->health().incomplete_scans, 1U);
  EXPECT_EQ(f.laser.beam_count, 0) << "no scan rather than a scan with holes";
}

}  // namespace
}  // namespace ringlet::hal::can
