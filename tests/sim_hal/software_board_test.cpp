// The software board (sim_hal/software_board.hpp) and the CAN backend (hal/can/can_robot.hpp)
// closing the loop over a socketpair that carries struct can_frame: the controller's commands
// drive the simulated car, the car's sensors come back through the protocol, and each side's
// watchdog acts when the other goes quiet.
#include <gtest/gtest.h>
#include <sys/socket.h>

#include <algorithm>
#include <memory>

#include "ringlet/hal/can/can_robot.hpp"
#include "ringlet/hal/virtual_clock.hpp"
#include "ringlet/sim_hal/software_board.hpp"
#include "ringlet/sim_hal/world.hpp"

namespace ringlet::sim_hal {
namespace {

using namespace std::chrono_literals;
using hal::can::BoardState;
using hal::can::CanRobot;
using hal::can::CanSocket;

constexpr hal::Nanos kPeriod{10'000'000};

struct Loop {
  Loop() : clock(hal::Nanos{1'000'000'000}) {
    int sv[2];
    EXPECT_EQ(::socketpair(AF_UNIX, SOCK_SEQPACKET, 0, sv), 0);
    SimConfig sim;
    sim.laser_beams = 181;
    car = std::make_unique<SimRobot>(load_world(RINGLET_SIM_WORLDS_DIR "/courtyard.world"), sim);
    board = std::make_unique<SoftwareBoard>(*car, CanSocket::adopt(sv[1]));
    controller = std::make_unique<CanRobot>(hal::can::CanSettings{}, CanSocket::adopt(sv[0]), clock, nullptr);
  }
  // One frame: the board's period, then the controller's sense and (when driving) actuate.
  hal::SensorFrame frame(bool command, hal::ActuatorCommand cmd = {{0.0, 0.5}, {}}) {
    board->step(clock.now());
    hal::SensorFrame f;
    (void)controller->sensors().read(f);
    if (command) controller->actuators().write(cmd);
    clock.advance(kPeriod);
    return f;
  }
  hal::VirtualClock clock;
  std::unique_ptr<SimRobot> car;
  std::unique_ptr<SoftwareBoard> board;
  std::unique_ptr<CanRobot> controller;
};

// A scan leaves the board over the scan's period, not in one burst: the header in the step that
// takes the scan, then 7 of its 61 range frames per step, every chunk once and in order.
TEST(SoftwareBoard, ALaserScanIsSpreadOverItsPeriod) {
  int sv[2];
  ASSERT_EQ(::socketpair(AF_UNIX, SOCK_SEQPACKET, 0, sv), 0);
  SimConfig sim;
  sim.laser_beams = 181;
  SimRobot car(load_world(RINGLET_SIM_WORLDS_DIR "/courtyard.world"), sim);
  SoftwareBoard board(car, CanSocket::adopt(sv[1]));
  CanSocket controller = CanSocket::adopt(sv[0]);
  hal::VirtualClock clock(hal::Nanos{1'000'000'000});
  int headers = 0, next_chunk = 0, most_in_a_step = 0;
  for (int step = 0; step < 10; ++step) {
    board.step(clock.now());
    clock.advance(kPeriod);
    int ranges = 0;
    hal::can::RawFrame f;
    while (controller.receive(f) == hal::can::ReceiveStatus::kFrame) {
      if (f.id == hal::can::kLaserHeaderId) ++headers;
      if (f.id != hal::can::kLaserRangesId) continue;
      ++ranges;
      EXPECT_EQ(f.data[1], next_chunk) << "chunks in order, each once";
      ++next_chunk;
    }
    most_in_a_step = std::max(most_in_a_step, ranges);
  }
  EXPECT_EQ(headers, 1);
  EXPECT_EQ(next_chunk, 61) << "the whole scan within its period";
  EXPECT_EQ(most_in_a_step, 7);
}

TEST(SoftwareBoard, TheControllerDrivesTheSimulatedCarThroughTheProtocol) {
  Loop loop;
  hal::SensorFrame f;
  for (int i = 0; i < 300; ++i) f = loop.frame(true);  // 3 s at 0.5 m/s
  EXPECT_TRUE(f.pose.valid);
  EXPECT_GT(f.odometry.distance, 1.0) << "the car drove on the controller's commands";
  EXPECT_NEAR(f.odometry.velocity, 0.5, 0.05);
  EXPECT_NEAR(loop.car->distance_travelled(), f.odometry.distance, 0.01);
  EXPECT_EQ(f.laser.beam_count, 181) << "the chunked laser scan came through whole";
  const auto& h = loop.controller->health();
  EXPECT_TRUE(h.board_alive);
  EXPECT_EQ(h.malformed + h.unknown_id + h.incomplete_scans + h.tx_full + h.refused_commands, 0U);
  EXPECT_EQ(loop.board->counts().refused, 0U);
  EXPECT_EQ(loop.board->state(), BoardState::kDriving);
}

TEST(SoftwareBoard, ItsWatchdogStopsTheCarWhenCommandsStop) {
  Loop loop;
  for (int i = 0; i < 100; ++i) (void)loop.frame(true);
  hal::SensorFrame f;
  for (int i = 0; i < 100; ++i) f = loop.frame(false);  // the controller stops commanding (killed)
  EXPECT_EQ(loop.board->counts().watchdog_stops, 1U);
  EXPECT_EQ(loop.board->state(), BoardState::kWatchdogStop);
  EXPECT_NEAR(f.odometry.velocity, 0.0, 0.05) << "the board stopped the car on its own";
  EXPECT_EQ(loop.controller->health().board_faults, 1U);
  EXPECT_EQ(loop.controller->health().last_fault, static_cast<std::uint16_t>(hal::can::BoardFault::kCommandTimeout));
  // Commands return: the car drives again.
  for (int i = 0; i < 100; ++i) f = loop.frame(true);
  EXPECT_EQ(loop.board->state(), BoardState::kDriving);
  EXPECT_GT(f.odometry.velocity, 0.3);
}

TEST(SoftwareBoard, ALostBoardPutsTheControllerInTheSafeState) {
  Loop loop;
  for (int i = 0; i < 50; ++i) (void)loop.frame(true);
  loop.board.reset();  // the board process dies: no heartbeat, no sensors
  for (int i = 0; i < 40; ++i) {
    hal::SensorFrame f;
    (void)loop.controller->sensors().read(f);
    loop.clock.advance(kPeriod);
  }
  EXPECT_TRUE(loop.controller->board_lost());
  EXPECT_TRUE(loop.controller->actuators().in_safe_state()) << "within heartbeat_timeout (300 ms) of the last beat";
}

TEST(SoftwareBoard, TheSafeStateLatchesTheBoardsCarStopped) {
  Loop loop;
  for (int i = 0; i < 50; ++i) (void)loop.frame(true);
  loop.controller->actuators().enter_safe_state();
  hal::SensorFrame f;
  for (int i = 0; i < 50; ++i) f = loop.frame(true);
  EXPECT_EQ(loop.board->state(), BoardState::kSafe);
  EXPECT_NEAR(f.odometry.velocity, 0.0, 0.05);
}

}  // namespace
}  // namespace ringlet::sim_hal
