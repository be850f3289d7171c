#pragma once
// Shared by the HAL log tests: a temporary folder, file helpers, field-by-field frame comparison.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "ringlet/hal/sensors.hpp"
#include "temp_dir.hpp"

namespace ringlet::hal::test {

// One folder per test process, removed when it exits.
inline std::filesystem::path log_dir() {
  static const ringlet::test::TempDir dir("ringlet_hal_log");
  return dir.path();
}

inline std::vector<std::uint8_t> file_bytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void write_bytes(const std::filesystem::path& p, const std::vector<std::uint8_t>& bytes, std::size_t n) {
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(n));
}

inline void expect_same_frame(const SensorFrame& a, const SensorFrame& b, std::uint64_t read) {
  SCOPED_TRACE("read " + std::to_string(read));
  EXPECT_EQ(a.stamp, b.stamp);
  EXPECT_EQ(a.pose.stamp, b.pose.stamp);
  EXPECT_EQ(a.pose.pose.x, b.pose.pose.x);
  EXPECT_EQ(a.pose.pose.y, b.pose.pose.y);
  EXPECT_EQ(a.pose.pose.theta, b.pose.pose.theta);
  EXPECT_EQ(a.pose.valid, b.pose.valid);
  EXPECT_EQ(a.odometry.stamp, b.odometry.stamp);
  EXPECT_EQ(a.odometry.distance, b.odometry.distance);
  EXPECT_EQ(a.odometry.velocity, b.odometry.velocity);
  EXPECT_EQ(a.odometry.curvature, b.odometry.curvature);
  EXPECT_EQ(a.head.yaw, b.head.yaw);
  EXPECT_EQ(a.head.pitch, b.head.pitch);
  EXPECT_EQ(a.body.stamp, b.body.stamp);
  EXPECT_EQ(a.body.tilt.pitch, b.body.tilt.pitch);
  EXPECT_EQ(a.body.tilt.roll, b.body.tilt.roll);
  EXPECT_EQ(a.body.valid, b.body.valid);
  EXPECT_EQ(a.power.battery_volts, b.power.battery_volts);
  EXPECT_EQ(a.power.bus_volts, b.power.bus_volts);
  EXPECT_EQ(a.laser.stamp, b.laser.stamp);
  EXPECT_EQ(a.laser.beam_count, b.laser.beam_count);
  EXPECT_EQ(a.laser.angle_min, b.laser.angle_min);
  EXPECT_EQ(a.laser.angle_increment, b.laser.angle_increment);
  EXPECT_EQ(a.laser.max_range, b.laser.max_range);
  EXPECT_EQ(a.laser.range, b.laser.range);
  EXPECT_EQ(a.laser.valid, b.laser.valid);
  EXPECT_EQ(a.collided, b.collided);
}

}  // namespace ringlet::hal::test
