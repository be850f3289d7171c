#pragma once
// The five behaviours and the arbiter of Powers & Balch §III-A. Each behaviour casts votes for
// (positive) or against (negative) every arc and sets a maximum allowable speed on each; the
// arbiter sums the votes with per-behaviour weights, picks the arc with the most, and drives it at
// the smallest of the behaviours' maximum speeds for that arc. One addition to the paper: a speed
// limit of 0 vetoes an arc while another can be driven (see arbitrate()).
//
//   Move to Waypoint       + votes around the arc of a linear law from the heading error
//   Avoid Obstacles        − votes by how soon the arc enters the obstacles' configuration space
//   Maintain Headway       speed limit by how soon the arc enters that configuration space
//   Slow for Congested     speed limit by how soon the arc enters a much larger one
//   Slow for Turns         speed limit from a maximum yaw rate: v ≤ ω_max / |κ|
//
// Every function is pure, fixed-size and allocation-free; a behaviour that has nothing to say
// leaves votes at 0 and speeds at top speed.
#include <array>
#include <string>

#include "ringlet/behaviour/reactive/arcs.hpp"

namespace ringlet::behaviour::reactive {

enum class Behaviour : int { kMoveToWaypoint, kAvoidObstacles, kMaintainHeadway, kSlowForCongestion, kSlowForTurns };
inline constexpr int kBehaviours = 5;
inline constexpr std::array<const char*, kBehaviours> kBehaviourNames{
    "move_to_waypoint", "avoid_obstacles", "maintain_headway", "slow_for_congestion", "slow_for_turns"};

/// What one behaviour says about every arc.
struct ArcVotes {
  PerArc vote{};       // weighted by the arbiter; ≥ 0 for, ≤ 0 against
  PerArc max_speed{};  // m/s
};

struct ReactiveParams {
  ArcSet arcs;
  double top_speed = 1.0;        // m/s
  double robot_radius = 0.3;     // m
  double margin = 0.15;          // m, added to the radius: the configuration space
  double lookahead = 3.0;        // m along an arc: nothing further away matters
  // Move to Waypoint: κ* = gain · heading error; the vote falls linearly from 1 at κ* to 0 at
  // vote_width away (in 1/m).
  double waypoint_gain = 2.0;
  double vote_width = 1.0;
  // Maintain Headway: stop within stop_distance of contact, full speed from slow_distance.
  double stop_distance = 0.2;    // m
  double slow_distance = 1.5;    // m
  // Slow for Congested Areas: a configuration space congestion_margin wider; entering it within
  // the lookahead limits the speed to congested_speed (scaled up to top speed with the distance).
  double congestion_margin = 0.8;  // m
  double congested_speed = 0.4;    // m/s
  // Slow for Turns.
  double max_yaw_rate = 1.0;     // rad/s
  // The arbiter's weights.
  std::array<double, kBehaviours> weight{1.0, 2.0, 0.0, 0.0, 0.0};

  /// Empty when usable, else what is wrong (names the field).
  [[nodiscard]] std::string validate() const;
};

/// The heading error to a waypoint in the robot frame, as behaviour::heading_error: positive when
/// it lies clockwise (to the right), so that a positive curvature turns towards it.
[[nodiscard]] double heading_error_to(const hal::RobotPoint& waypoint) noexcept;
/// Move to Waypoint: κ* = waypoint_gain · heading error, clamped to the arcs. A waypoint inside
/// the tightest turning circle on its side cannot be reached by turning towards it (the robot
/// would circle it for ever): then κ* = 0, straight on, until it lies outside.
void move_to_waypoint_votes(const ReactiveParams& p, const hal::RobotPoint& waypoint, ArcVotes& out) noexcept;
/// Avoid Obstacles, from the clearance of every arc in the configuration space (clearances()
/// with robot_radius + margin, capped at lookahead): −(1 − d / lookahead).
void avoid_obstacles_votes(const ReactiveParams& p, const PerArc& clearance, ArcVotes& out) noexcept;
/// Maintain Headway, from the same clearances.
void maintain_headway_votes(const ReactiveParams& p, const PerArc& clearance, ArcVotes& out) noexcept;
/// Slow for Congested Areas, from the clearances in the wide configuration space.
void slow_for_congestion_votes(const ReactiveParams& p, const PerArc& wide_clearance, ArcVotes& out) noexcept;
/// Slow for Turns.
void slow_for_turns_votes(const ReactiveParams& p, ArcVotes& out) noexcept;

struct ArbiterDecision {
  int arc = -1;            // the chosen arc
  double curvature = 0.0;  // its κ
  double speed = 0.0;      // the minimum of the behaviours' maximum speeds on it
  PerArc total{};          // the weighted sum of votes per arc
};

/// The weighted sum, the arc with the most votes (ties: the straighter arc, then the lower
/// index, so the choice is the same on every host), and the slowest speed limit on it. An arc
/// whose speed limit is 0 is chosen only when every arc's is (then the robot stops).
[[nodiscard]] ArbiterDecision arbitrate(const ReactiveParams& p, const std::array<ArcVotes, kBehaviours>& votes) noexcept;

/// Everything the reactive layer computes in one activation: each behaviour's votes (for
/// inspection: the whiteboard and the debug picture show them) and the decision.
struct ReactiveStep {
  std::array<ArcVotes, kBehaviours> votes{};
  PerArc clearance{}, wide_clearance{};
  ArbiterDecision decision;
};

/// One activation: clearances from the obstacles, the five behaviours, the arbiter; `waypoint` in
/// the robot frame.
void reactive_step(const ReactiveParams& p, const hal::RobotPoint& waypoint, const ObstaclePoints& obstacles,
                   ReactiveStep& out) noexcept;

}  // namespace ringlet::behaviour::reactive
