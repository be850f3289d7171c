// The link to the board (hal::BoardHealth, backend can): the sense task posts it (wb::BoardHealth)
// once a second when the backend has a board and never when it has none, and the report carries it.
#include <gtest/gtest.h>

#include <sstream>

#include "ringlet/firmware/mission_report.hpp"
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

namespace ringlet::firmware {
namespace {

// The report carries the link to the board at the end of the run (backend can), in text and JSON.
TEST(MissionReport, CarriesTheBoardsHealth) {
  MissionSummary s;
  EXPECT_TRUE(summary_json(s)["board"].is_null()) << "no board: null";
  hal::BoardHealth b;
  b.board_alive = true;
  b.frames_received = 500;
  b.heartbeat_losses = 2;
  b.bus = hal::BusState::kBusOff;
  s.board = b;
  const nlohmann::json j = summary_json(s)["board"];
  EXPECT_EQ(j["frames_received"], 500);
  EXPECT_EQ(j["heartbeat_losses"], 2);
  EXPECT_EQ(j["bus"], "bus-off");
  EXPECT_EQ(j["alive"], true);
  std::ostringstream text;
  print_summary(text, s);
  EXPECT_NE(text.str().find("  board: alive, 500 frames in, 0 out, 0 malformed, 0 unknown, 0 stale readings, 2 heartbeats lost"),
            std::string::npos)
      << text.str();
}

}  // namespace
}  // namespace ringlet::firmware
