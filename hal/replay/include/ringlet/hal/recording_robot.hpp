#pragma once
// A hal::Robot that records what the robot it wraps senses into a HAL log (robot_log.hpp) while
// passing everything through unchanged: every Sensors::read(), every BallSensor::read(), and every
// Camera::grab_latest() that hands out a frame with a new sequence number. Actuators and ground
// truth pass through unrecorded (a replay drives nothing; it has no truth).
//
// Real time: nothing on the cycle path allocates, locks or does I/O. A call copies its record into
// a slot preallocated at construction (camera slots hold max_camera_frame_bytes each) and hands it
// through a bounded single-producer single-consumer queue to a writer thread, which encodes and
// writes the file. When the queue is full:
//   RecordMode::kLossless    the call waits for the writer to free a slot. For lockstep
//                            simulation, where time is virtual and waiting changes nothing the
//                            controller does: the log is complete.
//   RecordMode::kDropOnFull  the record is dropped and counted, never waited for (the real clock).
//                            The log carries a gap record where records were lost, and a replay
//                            refuses a log with gaps unless told to accept them.
//
// Threads: the wrapped robot's sensors, ball sensor and camera must be called from one thread (the
// executive's, as the firmware does): that thread is the queue's single producer. stop() (or the
// destructor) is called once the run has stopped calling them.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "ringlet/hal/robot.hpp"
#include "ringlet/hal/robot_log.hpp"

namespace ringlet::hal {

enum class RecordMode : std::uint8_t { kLossless, kDropOnFull };

struct RecordingOptions {
  RecordMode mode = RecordMode::kLossless;
  Nanos period{10'000'000};  // the executive period, written into the header
  std::string note;          // free text for the header (cut at kMaxLogNoteBytes)
  std::size_t record_slots = 256;  // sensor and ball records in flight (~3.7 KiB each)
  std::size_t camera_slots = 4;    // camera frames in flight
  /// Bytes of the largest camera frame (stride * height), e.g.
  /// camera_frame_bytes(PixelFormat::kYuyv, 640, 480). Needed when the wrapped robot has a camera;
  /// a larger frame is not recorded (it counts as dropped, and status() names it).
  std::size_t max_camera_frame_bytes = 0;
};

/// How the recording is going (safe from any thread).
struct RecordingStatus {
  std::string error;              // "<path>: cannot write HAL log: <errno text>", or a frame too large
  std::uint64_t records_written = 0;
  std::uint64_t dropped = 0;      // records dropped so far (queue full, frame too large)
  [[nodiscard]] bool ok() const noexcept { return error.empty(); }
};

class RecordingRobot final : public Robot {
 public:
  /// Creates (truncates) the log, writes its header and starts the writer thread. Throws LogError
  /// ("<path>: cannot create HAL log: <errno text>") when the file cannot be created, and
  /// std::invalid_argument for options that cannot work (no slots; a camera but no frame size,
  /// or a frame size over kMaxLogCameraFrameBytes). `inner` must outlive this robot.
  RecordingRobot(Robot& inner, const std::filesystem::path& log, RecordingOptions options);
  ~RecordingRobot() override;
  RecordingRobot(const RecordingRobot&) = delete;
  RecordingRobot& operator=(const RecordingRobot&) = delete;

  [[nodiscard]] std::string_view backend_name() const noexcept override;  // the wrapped robot's
  Sensors& sensors() noexcept override;
  Actuators& actuators() noexcept override;
  Camera* camera() noexcept override;            // null iff the wrapped robot has none
  BallSensor* ball_sensor() noexcept override;   // null iff the wrapped robot has none
  [[nodiscard]] const GroundTruth* ground_truth() const noexcept override;
  [[nodiscard]] const BoardHealth* board_health() const noexcept override;  // the wrapped robot's

  /// Writes what is queued, a gap record for drops not yet marked, the end record; closes the
  /// file and joins the writer. Idempotent; the destructor calls it. Never throws.
  RecordingStatus stop() noexcept;
  [[nodiscard]] RecordingStatus status() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ringlet::hal
