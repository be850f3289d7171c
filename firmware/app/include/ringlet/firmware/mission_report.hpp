#pragma once
// What a run achieved, for people (summary on the terminal, SVG picture) and for tools (JSON).
#include <cstdint>
#include <filesystem>
#include <ostream>
#include <string>
#include <optional>

#include "ringlet/hal/board_health.hpp"
#include <vector>

#include <nlohmann/json.hpp>

#include "ringlet/firmware/mission_runner.hpp"
#include "ringlet/firmware/stack.hpp"

namespace ringlet::firmware {

/// One LLFSM at the end of the run.
struct MachineSummary {
  std::string name;
  std::string state;
  std::uint64_t ringlets = 0;
  bool suspended = false;
};

/// What ground truth says about the run (backends that have it: the simulator).
struct TruthSummary {
  double distance_m = 0;        // really driven
  std::uint64_t collisions = 0; // contact events
  HeadTracking head{};          // measured head yaw against the true ball
  LocalizationScore localization{};  // the localization against the true pose (not in the run hash)
};

/// What the bridge published ([remote] enabled): host-dependent counts, never in the run hash.
struct RemoteSummary {
  int robot = 0;
  int domain = 0;
  std::string partition;
  remote::TypeCounts totals{};
  remote::TypeCounts fsm_status{};
  std::uint64_t unacknowledged_frames = 0;  // lockstep frames the monitors did not acknowledge in time
  remote::RequestCounts requests{};         // remote writes: accepted, unauthorized, malformed, dropped
  double cpu_ms = 0.0;                      // the bridge's CPU time (its thread, or the lockstep observer)
  std::uint64_t pumps = 0;                  // its passes over the whiteboard
};

struct MissionSummary {
  std::string backend;
  std::string world;
  std::optional<std::uint64_t> seed;  // none: the backend has no randomness (a replay)
  std::size_t goals_reached = 0;
  std::size_t goal_count = 0;
  bool complete = false;
  double mission_seconds = 0;   // schedule time until the run ended
  double wall_seconds = 0;
  double distance_m = 0;        // from wheel odometry
  std::uint64_t collisions = 0;
  bool safe_state = false;      // forced before the normal shutdown (failsafe, watchdog or a signal)
  std::string safe_state_reason;  // why: "failsafe policy", "watchdog", "SIGINT", ... comma-separated
  bool safe_at_end = false;     // the actuators reported the safe state after shutdown
  bool failsafe = false;
  bool watchdog = false;
  bool interrupted = false;
  int signal = 0;               // the stop signal that ended the run (0: none)
  std::uint64_t trajectory_hash = 0;  // FNV-1a over the recorded poses: equal hashes, equal runs
  std::uint64_t run_hash = 0;         // the trajectory hash and every decision of the schedule, vision
                                      // and the machines (no host measurements): the golden-run check
  std::vector<MachineSummary> machines;
  std::uint64_t fsm_status_seen = 0;  // FsmStatus delivered by the stack's whiteboard subscription
  std::uint64_t dropped_samples = 0;  // trajectory samples the buffer had no room for
  std::optional<TruthSummary> truth;  // only with ground truth
  std::optional<VisionStats> vision;  // with a camera: what vision found
  std::optional<RemoteSummary> remote;  // with [remote] enabled
  std::optional<hal::BoardHealth> board;  // a backend with a board (can): the link at the end
};

/// `safe_before_shutdown`: the failsafe policy or the watchdog forced the safe state; a signal in
/// `outcome` counts as forcing it too (it commands the safe state at once, see run_mission).
[[nodiscard]] MissionSummary summarize(const FirmwareStack& stack, const RunOutcome& outcome, bool safe_before_shutdown);

/// FNV-1a over the bit patterns of the poses.
[[nodiscard]] std::uint64_t trajectory_hash(std::span<const hal::Pose2> poses) noexcept;

void print_summary(std::ostream& out, const MissionSummary& s);
[[nodiscard]] nlohmann::json summary_json(const MissionSummary& s);

/// The world with the driven trajectory as SVG (backends with ground truth; false otherwise).
bool write_picture(std::ostream& out, const FirmwareStack& stack, const MissionSummary& s);

/// Process exit code for a run: 0 mission complete; 3 incomplete (time ran out); 4 the safe state
/// was forced (failsafe policy or watchdog); 128 + the signal's number when a stop signal ended it
/// (130 SIGINT, 143 SIGTERM, 129 SIGHUP, 131 SIGQUIT; 130 when the signal is unknown).
[[nodiscard]] int exit_code(const MissionSummary& s) noexcept;

}  // namespace ringlet::firmware
