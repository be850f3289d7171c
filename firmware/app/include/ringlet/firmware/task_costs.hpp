#pragma once
// The modelled board cost of every firmware task, in one place beside the task table: what the
// executive judges budgets on in lockstep (ExecutiveConfig::judge_on_model), so that a simulated
// run is a pure function of seed and configuration. Tasks whose work does not vary have a nominal
// cost; the schedule's grows with its ringlets, and vision's comes from vision/cost_model.hpp.
// The figures are this host's p99 thread CPU time in the main job times vision's board_slowdown
// (4), rounded up; the timing table prints MODEL-P99 beside CPU-P99 so a drift shows.
#include "ringlet/hal/time.hpp"

namespace ringlet::firmware::task_costs {

using hal::Nanos;

/// HAL read and posting. The simulator's own work inside read() (ray casting the laser, waiting
/// for the render thread) is not the robot's and is not modelled.
inline constexpr Nanos kSense{40'000};
/// An activation of the vision task that finds no new camera frame.
inline constexpr Nanos kVisionNoFrame{2'000};
/// The LLFSM schedule: a fixed part per turn (bus poll) and one per ringlet.
inline constexpr Nanos kFsmTurn{2'000};
inline constexpr Nanos kFsmPerRinglet{1'000};
inline constexpr Nanos kActuate{3'000};
inline constexpr Nanos kTelemetry{4'000};
inline constexpr Nanos kWhiteboard{6'000};

}  // namespace ringlet::firmware::task_costs
