#pragma once
// Small helpers shared by the sim tests: worlds built in code, and a frame hash for determinism.
#include <bit>
#include <cstdint>

#include "ringlet/hal/sensors.hpp"
#include "ringlet/sim_hal/world.hpp"

namespace ringlet::sim_hal::test {

/// An empty walled rectangle from (0, 0) to (width, height), robot at `start`.
inline World box_world(double width, double height, hal::Pose2 start) {
  World world;
  world.name = "box";
  world.min = {0.0, 0.0};
  world.max = {width, height};
  world.start = start;
  return world;
}

/// FNV-1a over raw bytes: any bit of difference in a reading changes the hash.
class Fnv1a {
 public:
  void bytes(const void* data, std::size_t size) noexcept {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) {
      hash_ ^= p[i];
      hash_ *= 0x100000001b3ULL;
    }
  }
  void value(double v) noexcept {
    const auto bits = std::bit_cast<std::uint64_t>(v);
    bytes(&bits, sizeof bits);
  }
  void value(float v) noexcept {
    const auto bits = std::bit_cast<std::uint32_t>(v);
    bytes(&bits, sizeof bits);
  }
  void value(bool v) noexcept {
    const unsigned char byte = v ? 1 : 0;
    bytes(&byte, 1);
  }
  void value(std::int64_t v) noexcept { bytes(&v, sizeof v); }

  /// Everything a controller could see in a frame.
  void frame(const hal::SensorFrame& f) noexcept {
    value(static_cast<std::int64_t>(f.stamp.count()));
    value(f.pose.pose.x);
    value(f.pose.pose.y);
    value(f.pose.pose.theta);
    value(f.odometry.distance);
    value(f.odometry.velocity);
    value(f.odometry.curvature);
    value(f.head.yaw);
    value(f.head.pitch);
    value(f.power.battery_volts);
    value(f.power.bus_volts);
    for (std::size_t i = 0; i < f.laser.beam_count; ++i) {
      value(f.laser.range[i]);
      value(f.laser.valid[i]);
    }
    value(f.collided);
  }

  [[nodiscard]] std::uint64_t result() const noexcept { return hash_; }

 private:
  std::uint64_t hash_ = 0xcbf29ce484222325ULL;
};

}  // namespace ringlet::sim_hal::test
