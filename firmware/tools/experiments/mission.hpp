#pragma once
// One lockstep mission of the experiments: a shipped configuration with the goals, the seed, the
// time limit and the planner's cost model replaced, run in-process exactly as the binary runs it
// (FirmwareStack + run_mission), and what the experiments need from it: per-goal times, the
// experiences recorded, the trajectory and the planner's plans.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "ringlet/behaviour/move_to_waypoint.hpp"
#include "ringlet/firmware/mission_report.hpp"
#include "ringlet/hal/geometry.hpp"
#include "ringlet/hal/ground_truth.hpp"
#include "ringlet/planning/experience.hpp"

namespace ringlet::experiments {

struct MissionSpec {
  std::filesystem::path config;                // a shipped configuration (pb_training.toml, ...)
  std::vector<behaviour::Waypoint> goals;      // empty: the configuration's
  std::uint64_t seed = 42;                     // the simulator's seed (--seed of the binary)
  double timeout_s = 300.0;                    // schedule time before the mission counts as failed ...
  double timeout_cap_s = 86400.0;              // ... at most this (--mission-timeout: the smallest runs)
  bool learned = false;                        // cost_model = "knn" (else the binary baseline)
  int k = 5;
  std::filesystem::path experiences;           // the kNN model's training file (empty: none)
  bool learn_online = false;
  int publish_every = 100;
  std::filesystem::path record;                // where this mission's experiences go (empty: nowhere)
  std::filesystem::path prior_map;             // [planner] prior_map: what the planner knows before it drives (empty: nothing)
  /// Where the robot starts instead of the world's start (x, y, heading in degrees as the world
  /// file writes it: 0 = +y, 90 = +x). The mission then runs on copies of the configuration and
  /// the world, written to `work_dir` as `tag`.toml and `tag`.world.
  struct Start {
    double x = 0, y = 0, heading_deg = 0;
  };
  std::optional<Start> start;
  std::filesystem::path work_dir;
  std::string tag;
};

/// The heading (degrees, the world file's convention) of travel from (ax, ay) to (bx, by), in
/// whole degrees so that it prints exactly.
[[nodiscard]] double heading_deg(double ax, double ay, double bx, double by);

struct MissionResult {
  firmware::MissionSummary summary;
  std::vector<double> goal_seconds;            // per goal: time since the previous goal (or the start); -1: missed
  std::vector<planning::Experience> experiences;  // recorded in this mission
  std::vector<hal::Pose2> trajectory;
  std::vector<hal::WorldPoint> first_plan;     // the planner's first plan to the first goal
  std::vector<hal::WorldPoint> goals;          // the goals flown, world frame
};

/// Why a mission missed its goal: the planner gave up (Navigate ended in Unreachable: no way
/// through the cells the laser had marked), the robot was boxed in (it moved less than 1 m, net,
/// over the last quarter of its recorded trajectory), or it was still under way at the time limit.
enum class Miss { kNone, kUnreachable, kBoxedIn, kOutOfTime };
struct MissReport {
  Miss kind = Miss::kNone;
  std::size_t goal = 0;        // the goal it was driving to (0-based)
  double to_goal_m = 0;        // from where it ended
  double moved_m = 0;          // net, over the last quarter of its run
};
[[nodiscard]] MissReport why_missed(const MissionResult& r);
[[nodiscard]] const char* describe(Miss kind);

/// Runs `spec` to the end (all goals, or the timeout). Throws firmware::ConfigError on a bad
/// configuration or experience file, std::runtime_error when the recorded experiences could not
/// be written.
[[nodiscard]] MissionResult run_mission(const MissionSpec& spec);

}  // namespace ringlet::experiments
