#pragma once
// The firmware's configuration file (TOML, documented in firmware/README.md): which backend and
// its own section (read by the backend factory), the mission, the executive and its task table. Loading is
// all-or-nothing: any problem is a ConfigError "file:line:col: key: message" and no config exists.
// Unknown keys are errors too, so a typo never silently falls back to a default.
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "ringlet/behaviour/move_to_waypoint.hpp"
#include "ringlet/behaviour/plan_execute.hpp"
#include "ringlet/behaviour/reactive/voting.hpp"
#include "ringlet/executive/realtime.hpp"
#include "ringlet/executive/task_table.hpp"
#include "ringlet/firmware/lossy_link.hpp"
#include "ringlet/hal/camera.hpp"
#include "ringlet/hal/camera_geometry.hpp"
#include "ringlet/localization/field_model.hpp"
#include "ringlet/localization/particle_filter.hpp"
#include "ringlet/planning/cost_model.hpp"
#include "ringlet/planning/knn_regressor.hpp"
#include "ringlet/planning/learned_cost_model.hpp"
#include "ringlet/planning/occupancy_grid.hpp"
#include "ringlet/pddl/problem_edit.hpp"

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

/// The head camera ([camera]): the robot's own ("robot": the simulator renders it, a replay plays
/// it back) or read through OpenCV ("opencv": a V4L2 device, a video file or an image folder). It
/// is opened when the task table runs the vision task, and delivers a frame every time vision
/// runs (the vision row's `every`).
struct CameraSettings {
  std::string backend = "robot";
  std::string source;  // opencv: "/dev/video0", a video file or a folder of images
  double hfov_deg = 57.0;  // the NAO's head camera
  double vfov_deg = 44.0;
  hal::CameraIntrinsics intrinsics = hal::CameraIntrinsics::from_fov(640, 480, hfov_deg, vfov_deg);
  hal::CameraMount mount{};
  hal::PixelFormat format = hal::PixelFormat::kYuyv;
};

/// How the mission drives ([mission] drive): "waypoints" — the Mission machine steers straight at
/// each goal (move_to_waypoint, [follower]); "navigate" — the Navigate machine follows the
/// planner's regions (D* Lite, [planner]) with the arbiter's arcs (the reactive layer, [reactive]).
/// "pddl" — the PlanExecute machine asks the PDDL planner service (the pddl task, [pddl]) for
/// actions one by one and drives each to its place with move_to_waypoint ([follower]).
enum class DriveMode { kWaypoints, kNavigate, kPddl };

/// The mission ([mission]): waypoints in the world frame, visited in order.
struct MissionSettings {
  static constexpr std::size_t kMaxGoals = 32;  // what wb::MissionGoals holds
  DriveMode drive = DriveMode::kWaypoints;
  std::vector<behaviour::Waypoint> goals;
  double goal_tolerance = 0.3;  // m: a goal counts as reached this close
  double timeout_s = 300.0;     // schedule time before giving up
  bool ball_tracking = true;    // the BallTracker machine in the schedule (false: no head camera)
};

enum class CostModelKind { kBinary, kKnn };

/// The deliberative layer ([planner], Powers & Balch §III-B, §III-C): the occupancy grid and its
/// regions, the cost model (the binary baseline or the learned kNN one), the work one activation
/// of the planner task may do, and the experiences it loads, records and learns from.
struct PlannerSettings {
  planning::MapConfig map{};
  planning::BinaryCostModel::Params cost{};
  int pops_per_slice = 2000;  // D* Lite queue pops per activation (the deterministic slice)
  CostModelKind cost_model = CostModelKind::kBinary;
  planning::KnnParams knn{};            // k, distance_weighted (prior_speed: top_speed)
  int wall_occupied = 3;                // the learned model's wall rule (learned_cost_model.hpp)
  std::filesystem::path experiences;    // loaded at start (empty: none)
  std::filesystem::path prior_map;      // a MovingAI .map of what is known before the run (empty: nothing)
  std::filesystem::path record;         // this mission's experiences, written at its end (empty: none)
  int capacity = 10000;                 // experiences this mission may record
  bool learn_online = false;            // recorded experiences join the model during the mission
  int publish_every = 100;              // planner activations between rebuild requests (online)

  /// Whether the planner task records experiences at all.
  [[nodiscard]] bool records() const noexcept { return !record.empty() || learn_online; }
};

/// The PDDL planner service ([pddl], issue 15; planning/pddl/README.md) and what the
/// PlanExecute machine asks it for. Only a configuration whose table runs the pddl task reads
/// the files; the arenas and the planners' arrays are sized here at start-up.
struct PddlSettings {
  std::filesystem::path domain;    // the domain file (required with the pddl task)
  std::filesystem::path problems;  // the folder LOAD_PDDL's names are looked up in (default: the domain's)
  std::vector<pddl::Place> places;  // place objects and where they are (world frame, m)
  double obstacle_radius = 0.6;     // m: IS_OBSTACLE_KNOWN blocks the connections passing this close
  int arena_kib = 4096;             // each of the two grounding arenas
  int max_facts = 4096;
  int max_operators = 65536;
  int max_nodes = 50000;            // search nodes of each planner
  int lama_restarts = 0;            // weighted A* restarts after LAMA's first plan (0-4)
  int units_per_slice = 200;        // planner expansions per activation (deterministic)
  LossyLinkSettings link{};         // the seeded lossy channel between machine and service (tests)
  behaviour::PlanExecuteParams machine{};  // what the PlanExecute machine asks for, its obstacle test
};

/// One backend's own section ([sim], ...), read and used by the backend factory only.
class BackendSettings {
 public:
  virtual ~BackendSettings() = default;
  /// What the run was made of, for the report: e.g. "courtyard.world".
  [[nodiscard]] virtual std::string source_name() const = 0;
  /// The seed of the backend's randomness (none: the backend has none, e.g. a replay).
  [[nodiscard]] virtual std::optional<std::uint64_t> seed() const = 0;
};

/// Field-line and ball detection ([vision]).
struct VisionSettings {
  std::filesystem::path lut;  // colour table (ringlet-vision-calibrate); empty: default thresholds
  std::uint64_t seed = 1;     // RANSAC's sampling
  int max_trials = 30;        // Mi-Pal's MAX_TRIALS
  int skip = 10;              // Mi-Pal's RANSAC_SKIP
  std::string colour;         // "adaptive" (field colour from each frame, the table as fallback) or "table";
                              // default: "table" when lut is given, else "adaptive"
  std::string ball = "orange";  // "orange" (colour blobs) or "bw" (the SPL's black-and-white ball, HOG/SVM verified)
  std::filesystem::path ball_model;   // HOG/SVM model (ringlet-train-hog) verifying bw ball candidates; empty: none
  std::filesystem::path robot_model;  // HOG/SVM model verifying robot candidates; empty: none (unverified obstacles)
  bool robots = true;                 // the robot stage runs (RobotDetections posted)
};

/// Self-localization ([field], [localization]; the localization task, localization/README.md):
/// the known field, the filter's parameters and what the robot knows when it starts.
struct LocalizationSettings {
  localization::FieldDimensions field{};
  localization::FilterParams filter{};
  std::optional<hal::Pose2> start;  // a known start pose (a kick-off position); none: unknown
  double start_sigma_xy = 0.1;      // m, how well it is known
  double start_sigma_theta = 0.05;  // rad
  double side = 0.0;                // the side prior: -1 west half (x < 0), +1 east, 0 none
};

/// Remote monitoring ([remote]): the whiteboard published over Cyclone DDS by the bridge
/// (remote/README.md). Off by default.
struct RemoteSettings {
  bool enabled = false;
  int robot = 0;                        // the robot's id (e.g. its player number), 0-65535
  int domain = 0;                       // DDS domain id, 0-232
  std::string partition = "ringlet";    // e.g. the team's name (1-256 characters)
  std::filesystem::path cyclone_config;  // Cyclone DDS XML file; empty: loopback only
  int poll_ms = 2;                      // the bridge thread's period (real clock)
  int wait_for_monitors = 0;            // start the run once this many monitors listen ...
  double wait_timeout_s = 10.0;         // ... or after this long (then run anyway, with a warning)
  std::map<std::string, double, std::less<>> max_rate_hz;  // type name -> most samples per second
  std::vector<std::string> unpublished;                    // type names kept off the network
  std::vector<std::string> accept;  // types a monitor may write (remote writes); empty: none
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
  std::shared_ptr<const BackendSettings> backend_settings;  // its section, read by the factory
  std::optional<std::uint64_t> seed_override;  // --seed: replaces the backend's seed
  std::filesystem::path record_log;      // --record: the robot's HAL inputs go to this log
  std::filesystem::path whiteboard_log;  // --wb-log: every whiteboard message goes to this log
  MissionSettings mission{};
  behaviour::MoveToWaypointParams follower{};
  ClockMode clock = ClockMode::kLockstep;
  executive::ExecutiveConfig executive{};
  executive::RealtimeSettings realtime{};
  std::vector<executive::TaskSpec> tasks;
  SafetyParams safety{};
  PlannerSettings planner{};
  PddlSettings pddl{};
  behaviour::reactive::ReactiveParams reactive{};
  CameraSettings camera{};
  VisionSettings vision{};
  RemoteSettings remote{};
  LocalizationSettings localization{};
  int trajectory_every = 10;        // telemetry.trajectory_every: frames between samples

  /// The row of the task table named `name`, or null when that task does not run.
  [[nodiscard]] const executive::TaskSpec* task(std::string_view name) const noexcept;
  /// The seed the run uses: --seed, else the backend's (0 when it has none).
  [[nodiscard]] std::uint64_t seed() const noexcept;
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
