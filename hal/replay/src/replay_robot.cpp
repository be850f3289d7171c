#include "ringlet/hal/replay_robot.hpp"

#include <exception>
#include <utility>
#include <vector>

namespace ringlet::hal {

void ReplayActuators::write(const ActuatorCommand& cmd) noexcept {
  if (in_safe_state()) return;
  last_ = cmd;
  ++count_;
}

struct ReplayRobot::Impl {
  class ReplaySensors final : public Sensors {
   public:
    explicit ReplaySensors(Impl& impl) : owner_(impl) {}
    bool read(SensorFrame& out) noexcept override { return owner_.read(out); }
    [[nodiscard]] bool exhausted() const noexcept override { return owner_.end; }

   private:
    Impl& owner_;
  };
  class ReplayCamera final : public Camera {
   public:
    explicit ReplayCamera(Impl& impl) : owner_(impl) {}
    bool grab_latest(FrameView& out) noexcept override { return owner_.grab(out); }

   private:
    Impl& owner_;
  };
  class ReplayBall final : public BallSensor {
   public:
    explicit ReplayBall(Impl& impl) : owner_(impl) {}
    bool read(BallSighting& out) noexcept override { return owner_.read_ball(out); }

   private:
    Impl& owner_;
  };

  explicit Impl(const std::filesystem::path& log, ReplayOptions options)
      : summary(scan_robot_log(log, LogReaderOptions{options.tolerate_torn_tail})),
        reader(log, LogReaderOptions{options.tolerate_torn_tail}) {
    if (summary.gap_records > 0 && !options.allow_gaps) {
      throw LogError(log.string() + ": the recorder dropped " + std::to_string(summary.dropped()) + " records (" +
                     std::to_string(summary.dropped_sensor) + " sensor, " + std::to_string(summary.dropped_ball) +
                     " ball, " + std::to_string(summary.dropped_camera) + " camera), the first after read " +
                     std::to_string(summary.first_gap_reads) +
                     ", so a replay would not see what the run saw (allow gaps to replay it anyway) at byte " +
                     std::to_string(summary.first_gap_offset));
    }
    staged_pixels.reserve(summary.max_camera_frame_bytes);
    shown_pixels.reserve(summary.max_camera_frame_bytes);
    advance();
  }

  RobotLogSummary summary;
  RobotLogReader reader;
  LogRecord record;
  SensorRecord pending;
  bool have_pending = false;
  bool end = false;
  std::uint64_t reads = 0;
  std::string error;

  std::vector<std::uint8_t> staged_pixels;  // the newest frame read, not yet handed out
  std::vector<std::uint8_t> shown_pixels;   // the frame the last grab handed out
  CameraRecord staged_frame;
  CameraRecord shown_frame;
  bool staged = false;
  bool shown = false;

  BallRecord ball;
  bool have_ball = false;

  ReplaySensors sensors{*this};
  ReplayCamera camera{*this};
  ReplayBall ball_sensor{*this};

  /// Reads up to and including the next sensor record, which waits in `pending`; the camera and
  /// ball records before it are the ones the recorded run read after its last sensor read.
  void advance() noexcept {
    have_pending = false;
    try {
      while (reader.next(record, &staged_pixels)) {
        switch (record.kind) {
          case RecordKind::kSensor:
            pending = record.sensor;
            have_pending = true;
            return;
          case RecordKind::kCamera:
            staged_frame = record.camera;
            staged = true;
            break;
          case RecordKind::kBall:
            ball = record.ball;
            have_ball = true;
            break;
          case RecordKind::kGap:
          case RecordKind::kEnd: break;
        }
      }
    } catch (const std::exception& e) {
      staged = false;  // its pixels may be half overwritten
      try {
        error = e.what();
      } catch (...) {
        error.clear();
      }
      if (error.empty()) error = "HAL log: read error";
    }
  }

  bool read(SensorFrame& out) noexcept {
    if (!have_pending) {
      end = true;
      return false;
    }
    out = pending.frame;
    const bool ok = pending.ok;
    reads = pending.index + 1;
    advance();
    return ok;
  }

  bool grab(FrameView& out) noexcept {
    if (staged) {
      std::swap(staged_pixels, shown_pixels);
      shown_frame = staged_frame;
      staged = false;
      shown = true;
    }
    if (!shown) return false;
    out.capture_time = shown_frame.capture_time;
    out.sequence = shown_frame.sequence;
    out.format = shown_frame.format;
    out.width = static_cast<int>(shown_frame.width);
    out.height = static_cast<int>(shown_frame.height);
    out.stride = static_cast<int>(shown_frame.stride);
    out.data = shown_pixels.data();
    return true;
  }

  bool read_ball(BallSighting& out) noexcept {
    if (!have_ball) {
      out = BallSighting{};
      return false;
    }
    out = ball.sighting;
    return ball.ok;
  }
};

ReplayRobot::ReplayRobot(const std::filesystem::path& log, ReplayOptions options)
    : impl_(std::make_unique<Impl>(log, options)) {}

ReplayRobot::~ReplayRobot() = default;

Sensors& ReplayRobot::sensors() noexcept { return impl_->sensors; }
Camera* ReplayRobot::camera() noexcept { return impl_->summary.camera_records > 0 ? &impl_->camera : nullptr; }
BallSensor* ReplayRobot::ball_sensor() noexcept {
  return impl_->summary.ball_records > 0 ? &impl_->ball_sensor : nullptr;
}
Nanos ReplayRobot::period() const noexcept { return impl_->summary.header.period; }
const RobotLogSummary& ReplayRobot::summary() const noexcept { return impl_->summary; }
bool ReplayRobot::end_of_log() const noexcept { return impl_->end; }
std::uint64_t ReplayRobot::reads() const noexcept { return impl_->reads; }
const std::string& ReplayRobot::error() const noexcept { return impl_->error; }

}  // namespace ringlet::hal
