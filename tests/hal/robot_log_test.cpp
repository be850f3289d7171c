// The HAL log format: every record kind round-trips through the encoders and the reader, and a
// damaged log (wrong magic, bad version, impossible sizes, bad values, truncation at any byte) is
// refused with "<path>: <what> at byte N" or read as a shorter log, never crashes.
#include "ringlet/hal/robot_log.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "fake_robot.hpp"
#include "log_test_support.hpp"
#include "ringlet/hal/replay_robot.hpp"
#include "ringlet/hal/robot_log_reader.hpp"

namespace {

using namespace ringlet::hal;
using namespace ringlet::hal::test;

constexpr Nanos kPeriod{10'000'000};

CameraRecord yuyv_frame(std::uint64_t reads, std::vector<std::uint8_t>& pixels) {
  CameraRecord c{reads, Nanos{123'456'789}, 7, PixelFormat::kYuyv, 640, 480, 640 * 2};
  pixels.resize(c.pixel_bytes());
  for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = static_cast<std::uint8_t>(i * 13 + 5);
  return c;
}

/// A complete log with one record of every kind: sensor 0 (721 beams), ball, camera, a gap of one
/// dropped sensor record, sensor 2 (3 beams), end.
std::vector<std::uint8_t> every_kind(std::vector<std::uint8_t>& pixels) {
  std::vector<std::uint8_t> out;
  append_header(out, LogHeader{kRobotLogVersion, kPeriod, "robot nao-3, spl_field.toml"});
  append_record(out, SensorRecord{0, true, scripted_frame(0, 721)});
  append_record(out, BallRecord{1, true, BallSighting{Nanos{5}, true, RobotPoint{1.25, -0.5}}});
  const CameraRecord cam = yuyv_frame(1, pixels);
  append_record(out, cam, pixels.data());
  append_record(out, GapRecord{2, DropCounts{1, 0, 0}});
  append_record(out, SensorRecord{2, false, scripted_frame(2, 3)});
  append_record(out, EndRecord{3, 1});
  return out;
}

TEST(RobotLog, EveryRecordKindRoundTrips) {
  std::vector<std::uint8_t> pixels;
  const auto bytes = every_kind(pixels);
  const auto path = log_dir() / "every_kind.rlog";
  write_bytes(path, bytes, bytes.size());

  RobotLogReader reader(path);
  EXPECT_EQ(reader.header().version, kRobotLogVersion);
  EXPECT_EQ(reader.header().period, kPeriod);
  EXPECT_EQ(reader.header().note, "robot nao-3, spl_field.toml");
  LogRecord rec;
  std::vector<std::uint8_t> got_pixels;

  ASSERT_TRUE(reader.next(rec, &got_pixels));
  ASSERT_EQ(rec.kind, RecordKind::kSensor);
  EXPECT_EQ(rec.sensor.index, 0u);
  EXPECT_TRUE(rec.sensor.ok);
  EXPECT_EQ(rec.sensor.frame.laser.beam_count, 721);
  expect_same_frame(rec.sensor.frame, scripted_frame(0, 721), 0);

  ASSERT_TRUE(reader.next(rec, &got_pixels));
  ASSERT_EQ(rec.kind, RecordKind::kBall);
  EXPECT_EQ(rec.ball.reads, 1u);
  EXPECT_TRUE(rec.ball.ok);
  EXPECT_EQ(rec.ball.sighting.stamp, Nanos{5});
  EXPECT_TRUE(rec.ball.sighting.seen);
  EXPECT_EQ(rec.ball.sighting.at.x, 1.25);
  EXPECT_EQ(rec.ball.sighting.at.y, -0.5);

  ASSERT_TRUE(reader.next(rec, &got_pixels));
  ASSERT_EQ(rec.kind, RecordKind::kCamera);
  EXPECT_EQ(rec.camera.reads, 1u);
  EXPECT_EQ(rec.camera.capture_time, Nanos{123'456'789});
  EXPECT_EQ(rec.camera.sequence, 7u);
  EXPECT_EQ(rec.camera.format, PixelFormat::kYuyv);
  EXPECT_EQ(rec.camera.width, 640u);
  EXPECT_EQ(rec.camera.height, 480u);
  EXPECT_EQ(rec.camera.stride, 1280u);
  EXPECT_EQ(got_pixels, pixels);

  ASSERT_TRUE(reader.next(rec, &got_pixels));
  ASSERT_EQ(rec.kind, RecordKind::kGap);
  EXPECT_EQ(rec.gap.reads, 2u);
  EXPECT_EQ(rec.gap.dropped.sensor, 1u);

  ASSERT_TRUE(reader.next(rec, &got_pixels));
  ASSERT_EQ(rec.kind, RecordKind::kSensor);
  EXPECT_EQ(rec.sensor.index, 2u);
  EXPECT_FALSE(rec.sensor.ok);
  expect_same_frame(rec.sensor.frame, scripted_frame(2, 3), 2);

  ASSERT_TRUE(reader.next(rec, &got_pixels));
  ASSERT_EQ(rec.kind, RecordKind::kEnd);
  EXPECT_EQ(rec.end.sensor_reads, 3u);
  EXPECT_EQ(rec.end.dropped, 1u);
  EXPECT_FALSE(reader.next(rec, &got_pixels));
  EXPECT_TRUE(reader.saw_end());

  const RobotLogSummary s = scan_robot_log(path);
  EXPECT_EQ(s.sensor_records, 2u);
  EXPECT_EQ(s.ball_records, 1u);
  EXPECT_EQ(s.camera_records, 1u);
  EXPECT_EQ(s.gap_records, 1u);
  EXPECT_EQ(s.dropped_sensor, 1u);
  EXPECT_EQ(s.first_gap_reads, 1u);
  EXPECT_EQ(s.sensor_reads, 3u);
  EXPECT_EQ(s.max_camera_frame_bytes, 640u * 480u * 2u);
  EXPECT_TRUE(s.complete);
  EXPECT_EQ(s.file_bytes, bytes.size());
}

TEST(RobotLog, BeamsPastTheCountAreNotLoggedAndReadBackAsZero) {
  SensorFrame f = scripted_frame(0, 2);
  f.laser.range[5] = 9.0F;  // garbage past beam_count
  f.laser.valid[5] = true;
  std::vector<std::uint8_t> out;
  append_header(out, LogHeader{kRobotLogVersion, kPeriod, ""});
  append_record(out, SensorRecord{0, true, f});
  EXPECT_EQ(out.size(), 24 + kRecordHeaderBytes + kSensorFixedBytes + 2 * kBytesPerBeam);
  const auto path = log_dir() / "beams.rlog";
  write_bytes(path, out, out.size());
  RobotLogReader reader(path);
  LogRecord rec;
  rec.sensor.frame.laser.range[5] = 1.0F;  // the reader must clear what the record does not hold
  rec.sensor.frame.laser.valid[5] = true;
  ASSERT_TRUE(reader.next(rec, nullptr));
  EXPECT_EQ(rec.sensor.frame.laser.range[5], 0.0F);
  EXPECT_FALSE(rec.sensor.frame.laser.valid[5]);
}

TEST(RobotLog, TheBytesAreLittleEndianWhateverTheHost) {
  std::vector<std::uint8_t> out;
  append_header(out, LogHeader{kRobotLogVersion, Nanos{0x0102030405060708}, "n"});
  const std::vector<std::uint8_t> expected{'R', 'L', 'H', 'A', 'L', 'L', 'O', 'G', 2, 0, 0, 0,
                                           8,   7,   6,   5,   4,   3,   2,   1,   1, 0, 0, 0, 'n'};
  EXPECT_EQ(out, expected);
}

// ---- damaged logs -------------------------------------------------------------------------------

struct Damage {
  const char* name;
  std::function<void(std::vector<std::uint8_t>&)> damage;
  const char* message;  // expected after "<path>: "
};

void put_u32(std::vector<std::uint8_t>& b, std::size_t at, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) b[at + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(v >> (8 * i));
}

// Offsets in every_kind(): header 24 + 27 note bytes = 51; sensor 0 record at 51, its payload at 56.
constexpr std::size_t kFirstRecord = 51;
constexpr std::size_t kSensorPayload = kFirstRecord + kRecordHeaderBytes;
constexpr std::size_t kBallRecord = kSensorPayload + kSensorFixedBytes + 721 * kBytesPerBeam;
constexpr std::size_t kCameraRecord = kBallRecord + kRecordHeaderBytes + kBallPayloadBytes;

TEST(RobotLog, DamagedLogsAreRefusedNamingWhatAndWhere) {
  const std::vector<Damage> cases{
      {"magic", [](auto& b) { b[0] = 'X'; }, "wrong magic (not a Ringlet HAL log) at byte 0"},
      {"version", [](auto& b) { put_u32(b, 8, 7); }, "unsupported version 7 (this build reads version 2) at byte 8"},
      {"period", [](auto& b) { for (int i = 12; i < 20; ++i) b[static_cast<std::size_t>(i)] = 0; },
       "period of 0 ns is not positive at byte 12"},
      {"note", [](auto& b) { put_u32(b, 20, 5000); }, "note of 5000 bytes is longer than the limit of 4096 at byte 20"},
      {"kind", [](auto& b) { b[kFirstRecord] = 9; }, "unknown record kind 9 at byte 51"},
      {"sensor size", [](auto& b) { put_u32(b, kFirstRecord + 1, 100); },
       "sensor record of 100 bytes is not 174 + 5 per beam for 0 to 721 beams at byte 51"},
      {"beam count", [](auto& b) { b[kSensorPayload + 147] = 0xD2; },  // 722 = 0x2D2
       "laser beam_count 722 exceeds 721 at byte 203"},
      {"beam count vs size", [](auto& b) { b[kSensorPayload + 147] = 0xD0; },  // 720 beams in a 721-beam record
       "sensor record of 3779 bytes does not match its 720 beams (3774 expected) at byte 51"},
      {"bad bool", [](auto& b) { b[kSensorPayload + 8] = 2; }, "sensor record: ok is 2, not 0 or 1 at byte 64"},
      {"index", [](auto& b) { b[kSensorPayload] = 4; }, "sensor record index 4, expected 0 at byte 51"},
      // The inertial unit's valid flag: index 8, ok 1, stamp 8, pose 33, odometry 32, head 16, then
      // body stamp 8, pitch 8, roll 8.
      {"body valid", [](auto& b) { b[kSensorPayload + 122] = 3; }, "sensor record: body.valid is 3, not 0 or 1 at byte 178"},
      {"version 1", [](auto& b) { put_u32(b, 8, 1); },
       "unsupported version 1 (this build reads version 2; version 1 logs have no torso tilt, record the run again) "
       "at byte 8"},
      {"ball tag", [](auto& b) { b[kBallRecord + kRecordHeaderBytes] = 0; },
       "ball record tagged with read 0, expected 1 at byte"},
      {"ball size", [](auto& b) { put_u32(b, kBallRecord + 1, 35); }, "ball record of 35 bytes, expected 34 at byte"},
      {"camera too large", [](auto& b) { put_u32(b, kCameraRecord + 1, 0xFFFFFFFF); },
       "camera record of 4294967295 bytes is larger than the largest frame (50331648 bytes) at byte"},
      {"camera pixels", [](auto& b) {
         put_u32(b, kCameraRecord + kRecordHeaderBytes + 25, 5000);  // width
         put_u32(b, kCameraRecord + kRecordHeaderBytes + 29, 5000);  // height
       },
       "camera frame 5000x5000 is empty or exceeds 16777216 pixels at byte"},
      {"camera format", [](auto& b) { b[kCameraRecord + kRecordHeaderBytes + 24] = 3; },
       "camera record: unknown pixel format 3 at byte"},
      {"camera stride", [](auto& b) { put_u32(b, kCameraRecord + kRecordHeaderBytes + 33, 100); },
       "camera frame stride 100 is less than a row (1280 bytes) at byte"},
      {"data after end", [](auto& b) { b.push_back(1); }, "data after the end record at byte"},
      {"truncated", [](auto& b) { b.erase(b.end() - 3, b.end()); }, "truncated end record (16 bytes announced, 13 left) at byte"},
  };
  std::vector<std::uint8_t> pixels;
  for (const Damage& c : cases) {
    SCOPED_TRACE(c.name);
    auto bytes = every_kind(pixels);
    c.damage(bytes);
    const auto path = log_dir() / "damaged.rlog";
    write_bytes(path, bytes, bytes.size());
    try {
      (void)scan_robot_log(path);
      ADD_FAILURE() << "accepted";
    } catch (const LogError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(path.string() + ": " + c.message, 0), 0u) << e.what();
    }
  }
}

TEST(RobotLog, NonRegularFilesAreRefused) {
  try {
    RobotLogReader reader(log_dir());
    ADD_FAILURE() << "accepted a directory";
  } catch (const LogError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot read HAL log: not a regular file (a directory)"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(RobotLogReader("/nonexistent/run.rlog"), LogError);
}

TEST(RobotLog, ALogCutAtAnyByteIsRefusedOrReadAsAShorterLog) {
  std::vector<std::uint8_t> out;
  append_header(out, LogHeader{kRobotLogVersion, kPeriod, "cut"});
  std::vector<std::uint8_t> pixels(4 * 2 * 2);
  for (std::uint64_t i = 0; i < 3; ++i) {
    append_record(out, SensorRecord{i, true, scripted_frame(i, 4)});
    append_record(out, BallRecord{i + 1, true, BallSighting{}});
    append_record(out, CameraRecord{i + 1, Nanos{1}, i, PixelFormat::kYuyv, 4, 2, 8}, pixels.data());
  }
  append_record(out, EndRecord{3, 0});
  const auto path = log_dir() / "cut.rlog";
  std::size_t refused = 0;
  std::size_t shorter = 0;
  for (std::size_t n = 0; n < out.size(); ++n) {
    write_bytes(path, out, n);
    try {
      const RobotLogSummary s = scan_robot_log(path);
      EXPECT_FALSE(s.complete) << n;
      EXPECT_LE(s.sensor_records + s.ball_records + s.camera_records, 9u) << n;
      ++shorter;
      // The replay backend takes it too, and ends where the log ends.
      ReplayRobot replay(path);
      SensorFrame f;
      for (std::uint64_t i = 0; i < s.sensor_records; ++i) EXPECT_TRUE(replay.sensors().read(f)) << n;
      EXPECT_FALSE(replay.end_of_log());
      EXPECT_FALSE(replay.sensors().read(f)) << n;
      EXPECT_TRUE(replay.end_of_log()) << n;
    } catch (const LogError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(path.string() + ": ", 0), 0u) << e.what();
      EXPECT_NE(std::string(e.what()).find(" at byte "), std::string::npos) << e.what();
      ++refused;
      EXPECT_THROW(ReplayRobot{path}, LogError) << n;
    }
    // Tolerating a torn tail, only a cut header is refused.
    if (n >= 27) {
      EXPECT_NO_THROW((void)scan_robot_log(path, LogReaderOptions{true})) << n;
    }
  }
  EXPECT_EQ(shorter, 10u);  // cut exactly between records (after the header and after each of the 9)
  EXPECT_EQ(refused + shorter, out.size());
}

}  // namespace
