#pragma once
// The HAL log: what a run's robot sensed (sensor frames, ball sightings, camera frames), in the
// order the firmware read it, so that a replay can feed the same inputs through the same firmware.
// The byte layout is in hal/replay/README.md; this header has its constants, the records as C++
// structs and the encoders (one record -> bytes). The reader is robot_log_reader.hpp.
//
// Every value is written field by field, little-endian whatever the host (integers at their width,
// doubles and floats as their IEEE-754 bits, bools as one byte 0/1): the same run gives the same
// bytes on x86-64 and aarch64, and no struct padding ever reaches the file.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "ringlet/hal/ball_sensor.hpp"
#include "ringlet/hal/camera.hpp"
#include "ringlet/hal/image_header.hpp"
#include "ringlet/hal/sensors.hpp"
#include "ringlet/hal/time.hpp"

namespace ringlet::hal {

/// A HAL log that cannot be read or written: "<path>: <what is wrong> at byte N".
class LogError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

inline constexpr std::string_view kRobotLogMagic{"RLHALLOG", 8};
/// Version 2 added the inertial unit (the torso's tilt) to the sensor record; a version 1 log
/// cannot be replayed (vision would see an upright torso the robot may not have had).
inline constexpr std::uint32_t kRobotLogVersion = 2;
inline constexpr std::size_t kMaxLogNoteBytes = 4096;
/// The largest camera frame a log may hold: kMaxImagePixels at 3 bytes per pixel (48 MiB).
inline constexpr std::size_t kMaxLogCameraFrameBytes = kMaxImagePixels * 3;

enum class RecordKind : std::uint8_t {
  kSensor = 1,  // one Sensors::read()
  kBall = 2,    // one BallSensor::read()
  kCamera = 3,  // one Camera::grab_latest() that returned a frame with a new sequence number
  kGap = 4,     // records the recorder dropped (queue full) just before the next record
  kEnd = 5,     // written by a clean stop: the log is complete
};
[[nodiscard]] const char* to_string(RecordKind kind) noexcept;

// Byte sizes of the payloads (after the 5-byte record header: u8 kind, u32 payload size).
inline constexpr std::size_t kRecordHeaderBytes = 5;
inline constexpr std::size_t kSensorFixedBytes = 174;  // + 5 per beam (f32 range, u8 valid)
inline constexpr std::size_t kBytesPerBeam = 5;
inline constexpr std::size_t kBallPayloadBytes = 34;
inline constexpr std::size_t kCameraFixedBytes = 37;  // + stride * height pixel bytes
inline constexpr std::size_t kGapPayloadBytes = 20;
inline constexpr std::size_t kEndPayloadBytes = 16;
inline constexpr std::size_t kMaxSensorRecordBytes =
    kRecordHeaderBytes + kSensorFixedBytes + kBytesPerBeam * LaserScan::kMaxBeams;

/// Bytes per pixel of a camera format (YUYV: 2, BGR: 3, gray: 1); 0 for an unknown value.
[[nodiscard]] constexpr std::size_t bytes_per_pixel(PixelFormat f) noexcept {
  switch (f) {
    case PixelFormat::kYuyv: return 2;
    case PixelFormat::kBgr8: return 3;
    case PixelFormat::kGray8: return 1;
  }
  return 0;
}
/// Bytes of a tightly packed frame (stride = width * bytes per pixel): what RecordingOptions'
/// max_camera_frame_bytes needs for a camera of that mode.
[[nodiscard]] constexpr std::size_t camera_frame_bytes(PixelFormat f, std::size_t width, std::size_t height) noexcept {
  return width * height * bytes_per_pixel(f);
}

struct LogHeader {
  std::uint32_t version = kRobotLogVersion;
  Nanos period{0};   // the executive period of the recorded run
  std::string note;  // free text (at most kMaxLogNoteBytes): configuration, robot, date...
};

/// Records dropped by a recorder whose queue was full (RecordMode::kDropOnFull).
struct DropCounts {
  std::uint32_t sensor = 0;
  std::uint32_t ball = 0;
  std::uint32_t camera = 0;
  [[nodiscard]] bool any() const noexcept { return sensor + ball + camera > 0; }
  [[nodiscard]] std::uint64_t total() const noexcept {
    return std::uint64_t{sensor} + std::uint64_t{ball} + std::uint64_t{camera};
  }
};

struct SensorRecord {
  std::uint64_t index = 0;  // 0 for the run's first Sensors::read(), then 1, 2, ...
  bool ok = false;          // what read() returned
  SensorFrame frame{};      // beams past laser.beam_count are not logged (they read back as 0/false)
};

/// `reads` in the following records: how many Sensors::read() calls the run had made before the
/// call was recorded (the record "follows" sensor record reads - 1).
struct BallRecord {
  std::uint64_t reads = 0;
  bool ok = false;
  BallSighting sighting{};
};

struct CameraRecord {
  std::uint64_t reads = 0;
  Nanos capture_time{0};
  std::uint64_t sequence = 0;
  PixelFormat format = PixelFormat::kYuyv;
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::uint32_t stride = 0;  // bytes per row; the pixels are stride * height bytes
  [[nodiscard]] std::size_t pixel_bytes() const noexcept { return std::size_t{stride} * height; }
};

struct GapRecord {
  std::uint64_t reads = 0;  // of the record that follows the gap
  DropCounts dropped{};
};

struct EndRecord {
  std::uint64_t sensor_reads = 0;  // Sensors::read() calls in the whole run (dropped ones too)
  std::uint64_t dropped = 0;       // records dropped in the whole run (the gaps' sum)
};

// ---- encoders: append one header or record to `out` (the writer thread's buffer) --------------

void append_header(std::vector<std::uint8_t>& out, const LogHeader& header);
void append_record(std::vector<std::uint8_t>& out, const SensorRecord& r);
void append_record(std::vector<std::uint8_t>& out, const BallRecord& r);
/// `pixels` must hold r.pixel_bytes() bytes.
void append_record(std::vector<std::uint8_t>& out, const CameraRecord& r, const std::uint8_t* pixels);
void append_record(std::vector<std::uint8_t>& out, const GapRecord& r);
void append_record(std::vector<std::uint8_t>& out, const EndRecord& r);

}  // namespace ringlet::hal
