// The sense task posts the link to the board (wb::BoardHealth) once a second when the backend has
// a board, and never when it has none (the simulator).
#include <gtest/gtest.h>

#include "ringlet/firmware/tasks/sense_task.hpp"

namespace ringlet::firmware {
namespace {

struct StillSensors final : hal::Sensors {
  bool read(hal::SensorFrame& out) noexcept override {
    out.pose.valid = true;
    return true;
  }
};

executive::TaskContext frame(std::uint64_t n) {
  executive::TaskContext ctx;
  ctx.frame = n;
  ctx.period = hal::Nanos{10'000'000};
  return ctx;
}

TEST(SenseTask, PostsTheBoardsHealthOnceASecond) {
  StillSensors sensors;
  wb::Whiteboard board;
  hal::BoardHealth health;
  health.frames_received = 1234;
  health.heartbeat_losses = 1;
  health.bus = hal::BusState::kErrorPassive;
  health.board_alive = true;
  SenseTask task(sensors, board, &health);
  for (std::uint64_t f = 0; f < 250; ++f) task.run(frame(f));
  EXPECT_EQ(board.generation<wb::BoardHealth>(), 3U) << "frames 0, 100 and 200";
  const wb::BoardHealth h = board.get<wb::BoardHealth>();
  EXPECT_EQ(h.frames_received, 1234U);
  EXPECT_EQ(h.heartbeat_losses, 1U);
  EXPECT_EQ(h.bus, 1);
  EXPECT_TRUE(h.board_alive);
}

TEST(SenseTask, PostsNoBoardHealthWithoutABoard) {
  StillSensors sensors;
  wb::Whiteboard board;
  SenseTask task(sensors, board);
  for (std::uint64_t f = 0; f < 250; ++f) task.run(frame(f));
  EXPECT_EQ(board.generation<wb::BoardHealth>(), 0U);
  EXPECT_EQ(board.generation<wb::Pose>(), 250U);
}

}  // namespace
}  // namespace ringlet::firmware
