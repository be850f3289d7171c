#pragma once
// The firmware's configuration file (TOML, documented in firmware/README.md): which backend,
// which world, the simulator, the mission, the executive and its task table. Loading is
// all-or-nothing: any problem is a ConfigError "file:line:col: key: message" and no config exists.
// Unknown keys are errors too, so a typo never silently falls back to a default.
#include <filesystem>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "ringlet/behaviour/move_to_waypoint.hpp"
#include "ringlet/executive/realtime.hpp"
#include "ringlet/executive/task_table.hpp"
#include "ringlet/hal/camera_geometry.hpp"
#include "ringlet/sim_hal/sim_robot.hpp"

namespace ringlet::firmware {

class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class ClockMode { kLockstep, kRealtime };

/// The Safety machine's thresholds ([safety]). Stopping from max_speed takes
/// max_speed² / (2 · max_acceleration) plus one period; stop_range_m must cover that plus the
/// robot's radius, or the robot touches what it stopped for.
struct SafetyParams {
  double stop_range = 0.9;     // m
  double release_range = 1.2;  // m
  long hold_ms = 300;          // ms clear before driving on
};

/// The head camera ([camera]): rendered by the simulator ("sim") or read through OpenCV
/// ("opencv": a V4L2 device, a video file or an image folder).
struct CameraSettings {
  bool enabled = false;
  std::string backend = "sim";
  std::string source;  // opencv: "/dev/video0", a video file or a folder of images
  hal::CameraIntrinsics intrinsics = hal::CameraIntrinsics::nao();
  hal::CameraMount mount{};
  hal::PixelFormat format = hal::PixelFormat::kYuyv;
  int every_frames = 3;  // sim: a frame every 3rd period (30 fps at 100 Hz)
};

/// Field-line and ball detection ([vision]).
struct VisionSettings {
  std::filesystem::path lut;  // colour table (ringlet-vision-calibrate); empty: default thresholds
  std::uint64_t seed = 1;     // RANSAC's sampling
  int max_trials = 30;        // Mi-Pal's MAX_TRIALS
  int skip = 10;              // Mi-Pal's RANSAC_SKIP
};

/// Where each key of the file was written, so that problems found after parsing (binding the
/// tasks, the world's start pose, the backend, the camera) still name "file:line:col".
struct ConfigPositions {
  std::string file;  // the configuration file
  // "robot.backend", "executive.tasks[2]", "executive.tasks[2].name" -> "file:line:col"
  std::map<std::string, std::string, std::less<>> keys;

  /// "file:line:col" of `key`; for a key the file does not contain (a default), that of the
  /// nearest enclosing table or array that it does contain; else just the file.
  [[nodiscard]] std::string at(std::string_view key) const;
};

/// Longest run the firmware accepts (--duration, mission.timeout_s): one day of schedule time.
inline constexpr double kMaxRunSeconds = 86400.0;
/// Most trajectory samples a run may record (24 MB of poses, sized at start-up): a run whose
/// length / (period · telemetry.trajectory_every) exceeds it is refused at start.
inline constexpr std::uint64_t kMaxTrajectorySamples = 1'000'000;

struct FirmwareConfig {
  std::filesystem::path source;     // the file it came from
  ConfigPositions positions;        // where each key was written in it
  std::string backend = "sim";      // robot.backend
  std::filesystem::path world;      // sim.world, resolved relative to the config file
  sim_hal::SimConfig sim{};             // sim.* (its period and seed come from executive/sim)
  behaviour::MoveToWaypointParams follower{};
  double goal_tolerance = 0.3;      // mission.goal_tolerance_m
  double timeout_s = 300.0;         // mission.timeout_s: schedule time before giving up
  ClockMode clock = ClockMode::kLockstep;
  executive::ExecutiveConfig executive{};
  executive::RealtimeSettings realtime{};
  std::vector<executive::TaskSpec> tasks;
  SafetyParams safety{};
  CameraSettings camera{};
  VisionSettings vision{};
  int trajectory_every = 10;        // telemetry.trajectory_every: frames between samples
};

/// Reads the file with hal::read_file (regular files up to hal::kMaxTextFileBytes only) and parses it.
[[nodiscard]] FirmwareConfig load_config(const std::filesystem::path& path);
/// Parses config text; `source` names it in messages, relative paths resolve against `base_dir`.
[[nodiscard]] FirmwareConfig parse_config(std::string_view text, const std::string& source,
                                          const std::filesystem::path& base_dir);

/// Trajectory samples a run of `seconds` records with this configuration (the buffer's size).
[[nodiscard]] std::uint64_t trajectory_samples(const FirmwareConfig& config, double seconds) noexcept;
/// Empty when a run of `seconds` fits the limits (finite, 0 < seconds <= kMaxRunSeconds, at most
/// kMaxTrajectorySamples samples), else why not — a sentence to put after the flag or key.
[[nodiscard]] std::string run_length_problem(const FirmwareConfig& config, double seconds);

}  // namespace ringlet::firmware
