#pragma once
// A small scripted hal::Robot for the HAL log tests: every input is a pure function of how many
// reads were made, so a recording and its replay can be checked field by field.
#include <atomic>
#include <cstdint>
#include <cstring>
#include <vector>

#include "ringlet/hal/robot.hpp"

namespace ringlet::hal::test {

/// The sensor frame of read i: every field differs per read; `beams` valid-or-not beams.
inline SensorFrame scripted_frame(std::uint64_t i, std::uint16_t beams) {
  SensorFrame f;
  const double d = static_cast<double>(i);
  f.stamp = Nanos{static_cast<std::int64_t>(i) * 10'000'000};
  f.pose = PoseMeasurement{f.stamp, Pose2{0.1 * d, -0.05 * d, 0.001 * d - 1.0}, i % 7 != 3};
  f.odometry = WheelOdometry{f.stamp, 0.01 * d, 0.5 + 0.001 * d, -0.25 + 1e-4 * d};
  f.head = HeadJoints{0.2 - 0.003 * d, 0.1 + 0.002 * d};
  f.body = InertialState{f.stamp - Nanos{500}, BodyTilt{0.05 - 0.001 * d, -0.02 + 0.0005 * d}, i % 5 != 4};
  f.power = PowerState{12.6 - 1e-4 * d, 5.0 + 1e-5 * d};
  f.laser.stamp = f.stamp - Nanos{1000};
  f.laser.beam_count = beams;
  f.laser.angle_min = -1.5707963267948966;
  f.laser.angle_increment = 3.141592653589793 / 720.0;
  f.laser.max_range = 5.5;
  for (std::size_t b = 0; b < beams; ++b) {
    f.laser.valid[b] = (b + i) % 5 != 0;
    f.laser.range[b] = f.laser.valid[b] ? 0.25F + 0.01F * static_cast<float>((b * 7 + i) % 500) : 0.0F;
  }
  f.collided = i % 11 == 10;
  return f;
}

class FakeSensors final : public Sensors {
 public:
  explicit FakeSensors(std::uint16_t beams) : beams_(beams) {}
  bool read(SensorFrame& out) noexcept override {
    out = scripted_frame(reads_, beams_);
    const bool ok = reads_ % 13 != 12;  // now and then the hardware "could not be read"
    ++reads_;
    return ok;
  }
  [[nodiscard]] std::uint64_t reads() const noexcept { return reads_; }

 private:
  std::uint16_t beams_;
  std::uint64_t reads_ = 0;
};

/// A YUYV camera whose frame n (sequence n) is new every `every` reads, from the first read on;
/// its pixels depend on n. Rows are padded (stride > width * 2), like some V4L2 drivers.
class FakeCamera final : public Camera {
 public:
  FakeCamera(const FakeSensors& sensors, int width, int height, std::uint64_t every)
      : sensors_(sensors), width_(width), height_(height), stride_(width * 2 + 8), every_(every),
        pixels_(static_cast<std::size_t>(stride_) * static_cast<std::size_t>(height)) {}
  bool grab_latest(FrameView& out) noexcept override {
    if (sensors_.reads() == 0) return false;
    const std::uint64_t seq = (sensors_.reads() - 1) / every_;
    for (std::size_t k = 0; k < pixels_.size(); ++k) pixels_[k] = static_cast<std::uint8_t>(k * 31 + seq * 17);
    out = FrameView{Nanos{static_cast<std::int64_t>(seq) * 33'000'000}, seq, PixelFormat::kYuyv, width_, height_,
                    stride_, pixels_.data()};
    return true;
  }
  [[nodiscard]] std::size_t frame_bytes() const noexcept { return pixels_.size(); }

 private:
  const FakeSensors& sensors_;
  int width_;
  int height_;
  int stride_;
  std::uint64_t every_;
  std::vector<std::uint8_t> pixels_;
};

class FakeBall final : public BallSensor {
 public:
  explicit FakeBall(const FakeSensors& sensors) : sensors_(sensors) {}
  bool read(BallSighting& out) noexcept override {
    const std::uint64_t r = sensors_.reads();
    out = BallSighting{Nanos{static_cast<std::int64_t>(r) * 10'000'000}, r % 4 != 0,
                       RobotPoint{1.0 + 0.01 * static_cast<double>(r), -0.5}};
    return r % 9 != 8;
  }

 private:
  const FakeSensors& sensors_;
};

class FakeActuators final : public Actuators {
 public:
  void write(const ActuatorCommand& /*cmd*/) noexcept override { ++writes; }
  void enter_safe_state() noexcept override { safe_.store(true); }
  [[nodiscard]] bool in_safe_state() const noexcept override { return safe_.load(); }
  std::uint64_t writes = 0;

 private:
  std::atomic<bool> safe_{false};
};

struct FakeRobotSetup {
  std::uint16_t beams = 721;
  bool camera = true;
  bool ball = true;
  int width = 64;
  int height = 48;
  std::uint64_t frame_every = 3;
};

class FakeRobot final : public Robot {
 public:
  explicit FakeRobot(FakeRobotSetup s = {})
      : sensors_(s.beams), camera_(sensors_, s.width, s.height, s.frame_every), ball_(sensors_),
        has_camera_(s.camera), has_ball_(s.ball) {}
  [[nodiscard]] std::string_view backend_name() const noexcept override { return "fake"; }
  Sensors& sensors() noexcept override { return sensors_; }
  Actuators& actuators() noexcept override { return actuators_; }
  Camera* camera() noexcept override { return has_camera_ ? &camera_ : nullptr; }
  BallSensor* ball_sensor() noexcept override { return has_ball_ ? &ball_ : nullptr; }
  [[nodiscard]] std::size_t frame_bytes() const noexcept { return camera_.frame_bytes(); }
  FakeActuators& fake_actuators() noexcept { return actuators_; }

 private:
  FakeSensors sensors_;
  FakeCamera camera_;
  FakeBall ball_;
  FakeActuators actuators_;
  bool has_camera_;
  bool has_ball_;
};

}  // namespace ringlet::hal::test
