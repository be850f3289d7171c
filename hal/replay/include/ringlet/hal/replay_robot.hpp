#pragma once
// The replay backend ("replay"): a hal::Robot that feeds a HAL log (recorded by RecordingRobot)
// back through the firmware, so a robot's run can be re-run on a desktop. It has no ground truth.
//
//   Sensors::read()          the next sensor record (its frame and its return value); after the
//                            last one: returns false and end_of_log() becomes true.
//   BallSensor               present iff the log has ball records; read() hands out the newest
//                            ball record the recorded run had read by now (tag <= reads).
//   Camera                   present iff the log has camera records; grab_latest() hands out the
//                            newest recorded frame whose tag <= the reads so far: what the
//                            recorded run's vision saw, at the same read.
//   Actuators                accept commands (the last one and a count are kept), honour the
//                            latched safe state, drive nothing.
//
// Opening checks the whole log once (scan_robot_log: headers and small records are read, camera
// pixels skipped), so a bad log is refused with LogError before the run starts, and the camera
// buffers are sized for the largest frame. A log with gaps (records the recorder dropped) is
// refused unless ReplayOptions::allow_gaps.
//
// Lockstep only: the replay reads the file on the caller's thread, inside Sensors::read() (plain
// buffered reads, at most the records up to the next sensor record). That blocks on the disk,
// which is harmless in lockstep (time is virtual, so waiting changes nothing the controller does)
// and would be wrong on the real clock; the firmware must refuse `--realtime` with this backend.
// Memory is bounded: one file buffer, two camera frames, one record.
//
// Threads: like the other backends' sensors, read(), ball reads and grabs come from one thread.
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "ringlet/hal/robot.hpp"
#include "ringlet/hal/robot_log_reader.hpp"

namespace ringlet::hal {

struct ReplayOptions {
  bool allow_gaps = false;          // replay a log the recorder dropped records from
  bool tolerate_torn_tail = false;  // replay a log whose last record was cut off (a crash)
};

class ReplayActuators final : public Actuators {
 public:
  void write(const ActuatorCommand& cmd) noexcept override;
  void enter_safe_state() noexcept override { safe_.store(true, std::memory_order_relaxed); }
  [[nodiscard]] bool in_safe_state() const noexcept override { return safe_.load(std::memory_order_relaxed); }
  /// The last command accepted (not the ones ignored in the safe state), and how many there were.
  [[nodiscard]] const ActuatorCommand& last_command() const noexcept { return last_; }
  [[nodiscard]] std::uint64_t commands() const noexcept { return count_; }

 private:
  std::atomic<bool> safe_{false};
  ActuatorCommand last_{};
  std::uint64_t count_ = 0;
};

class ReplayRobot final : public Robot {
 public:
  /// Opens and checks the log. Throws LogError ("<path>: <what is wrong> at byte N"), including
  /// for gaps when they are not allowed.
  explicit ReplayRobot(const std::filesystem::path& log, ReplayOptions options = {});
  ~ReplayRobot() override;
  ReplayRobot(const ReplayRobot&) = delete;
  ReplayRobot& operator=(const ReplayRobot&) = delete;

  [[nodiscard]] std::string_view backend_name() const noexcept override { return "replay"; }
  Sensors& sensors() noexcept override;
  Actuators& actuators() noexcept override { return actuators_; }
  Camera* camera() noexcept override;
  BallSensor* ball_sensor() noexcept override;
  // ground_truth(): null (the default).

  /// The recorded run's executive period: the firmware refuses a configuration that differs.
  [[nodiscard]] Nanos period() const noexcept;
  [[nodiscard]] const RobotLogSummary& summary() const noexcept;
  /// True once Sensors::read() found no more sensor records (the firmware then ends the run).
  [[nodiscard]] bool end_of_log() const noexcept;
  /// Sensor records handed out so far.
  [[nodiscard]] std::uint64_t reads() const noexcept;
  /// A read error met during the replay (the file changed or vanished after it was checked);
  /// empty if none. The replay then ends (end_of_log()).
  [[nodiscard]] const std::string& error() const noexcept;
  [[nodiscard]] const ReplayActuators& replay_actuators() const noexcept { return actuators_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  ReplayActuators actuators_;
};

}  // namespace ringlet::hal
