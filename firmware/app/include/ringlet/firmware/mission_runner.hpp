#pragma once
// Runs a built stack: real-time settings, the watchdog, a non-real-time thread that prints the
// executive's events and progress, the executive itself, and the shutdown into the safe state.
#include <atomic>
#include <csignal>
#include <ostream>
#include <string>

#include "ringlet/executive/executive.hpp"
#include "ringlet/firmware/stack.hpp"

namespace ringlet::firmware {

/// The signals that end a run in order: each stops the cycle, commands the safe state, and the
/// run is summarised and reported as usual; the binary then exits with 128 + the signal's number.
inline constexpr int kStopSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};

/// "SIGINT", "SIGTERM", "SIGHUP", "SIGQUIT", else "signal N".
[[nodiscard]] std::string signal_name(int signo);

struct RunOutcome {
  executive::StopReason reason = executive::StopReason::kFrameLimit;
  bool interrupted = false;     // a stop signal (or the interrupt flag) ended the run
  int signal = 0;               // which signal, when the caller knows it (0: none or unknown)
  bool safe_at_end = false;     // the robot's actuators reported the safe state after shutdown
  bool watchdog_fired = false;
  double schedule_seconds = 0;  // frames run × period
  double wall_seconds = 0;      // how long it took on the host
  std::size_t experiences_written = 0;  // [planner] record: experiences written to the file
  std::string experiences_error;        // why they could not be written (empty: written, or none asked for)
};

/// Runs at most `duration_s` of schedule time or until the mission ends or the executive's stop
/// flag is set (the signal handler sets it together with `interrupt`, which the watchdog watches
/// to command the safe state at once even if the cycle is stuck). Ends in the safe state.
/// Warnings and events go to `log`. Then, off the cycle, writes the experiences the planner recorded
/// to [planner] record (whole, atomically: a temporary file renamed over it).
RunOutcome run_mission(FirmwareStack& stack, double duration_s, const std::atomic<bool>& interrupt, std::ostream& log);

}  // namespace ringlet::firmware
