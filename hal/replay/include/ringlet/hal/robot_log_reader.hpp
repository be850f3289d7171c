#pragma once
// Reads a HAL log (robot_log.hpp, hal/replay/README.md) record by record with bounded memory: one
// buffered file, a fixed buffer for the small records, and the caller's pixel buffer for camera
// frames. Everything is checked before it is used: the magic, the version, every record's kind and
// size (against the largest the kind can have and against what is left of the file, before
// anything is read or allocated for it), bools that must be 0 or 1, laser beam counts, camera
// sizes and formats, and the order of the records (sensor indices count up, each other record is
// tagged with the reads before it, gaps add up, nothing follows the end record). A bad log throws
// LogError("<path>: <what is wrong> at byte N"); nothing in it can crash the reader.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

#include "ringlet/hal/robot_log.hpp"

namespace ringlet::hal {

struct LogReaderOptions {
  /// A log whose last record was cut off (the recorder died mid-write: power loss, SIGKILL) is
  /// read up to its last whole record instead of refused; the cut bytes are counted.
  bool tolerate_torn_tail = false;
};

/// One record; `kind` says which member holds it.
struct LogRecord {
  RecordKind kind = RecordKind::kSensor;
  std::uint64_t offset = 0;  // where the record starts in the file
  SensorRecord sensor{};
  BallRecord ball{};
  CameraRecord camera{};
  GapRecord gap{};
  EndRecord end{};
};

class RobotLogReader {
 public:
  /// Opens the log (a regular file only) and reads its header. Throws LogError.
  explicit RobotLogReader(const std::filesystem::path& path, LogReaderOptions options = {});
  ~RobotLogReader();
  RobotLogReader(const RobotLogReader&) = delete;
  RobotLogReader& operator=(const RobotLogReader&) = delete;

  [[nodiscard]] const LogHeader& header() const noexcept;
  [[nodiscard]] const std::filesystem::path& path() const noexcept;
  /// Reads the next record into `out`; false at the end of the file (or at a tolerated torn tail).
  /// A camera record's pixels go to *pixels (resized to the frame's bytes: a vector reserved for
  /// the largest frame never reallocates), or are skipped when pixels is null. Throws LogError.
  bool next(LogRecord& out, std::vector<std::uint8_t>* pixels);
  /// Sensors::read() calls the run had made at the current position (the tag of the next ball or
  /// camera record).
  [[nodiscard]] std::uint64_t reads() const noexcept;
  [[nodiscard]] bool saw_end() const noexcept;
  /// Bytes of a cut-off last record that were ignored (tolerate_torn_tail), else 0.
  [[nodiscard]] std::uint64_t torn_tail_bytes() const noexcept;
  [[nodiscard]] std::uint64_t file_bytes() const noexcept;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// What a whole log holds, found by reading it once (camera pixels are skipped, not read).
struct RobotLogSummary {
  LogHeader header;
  std::uint64_t file_bytes = 0;
  std::uint64_t sensor_records = 0;
  std::uint64_t ball_records = 0;
  std::uint64_t camera_records = 0;
  std::uint64_t gap_records = 0;
  std::uint64_t sensor_reads = 0;       // reads the run made (recorded or dropped)
  std::uint64_t dropped_sensor = 0;     // summed over the gap records
  std::uint64_t dropped_ball = 0;
  std::uint64_t dropped_camera = 0;
  std::uint64_t first_gap_reads = 0;    // reads before the first gap (when gap_records > 0)
  std::uint64_t first_gap_offset = 0;   // where the first gap record starts
  std::size_t max_camera_frame_bytes = 0;
  bool complete = false;                // an end record closes the log
  std::uint64_t torn_tail_bytes = 0;
  [[nodiscard]] std::uint64_t dropped() const noexcept { return dropped_sensor + dropped_ball + dropped_camera; }
};

/// Reads and checks the whole log. Throws LogError.
[[nodiscard]] RobotLogSummary scan_robot_log(const std::filesystem::path& path, LogReaderOptions options = {});

}  // namespace ringlet::hal
