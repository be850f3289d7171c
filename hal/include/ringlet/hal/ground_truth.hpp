#pragma once
// What really happened in a run, for scoring it and drawing it — never for the controller. Only a
// simulator knows it; a real board or a replayed log has none (hal::Robot::ground_truth() is
// null), and the firmware's report then leaves the truth columns out.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <ostream>
#include <span>
#include <string_view>

#include "ringlet/hal/geometry.hpp"

namespace ringlet::hal {

/// A named point in the world frame: a PDDL problem's place.
struct NamedPoint {
  WorldPoint at{};
  std::string_view name;
};

/// The planner's map and plans, as the run recorded them (all empty when it had no planner).
struct PlanPicture {
  WorldPoint origin{};   // the grid's lower-left corner (m)
  double cell = 0.0;     // cell side (m); 0: no map
  int width_cells = 0, height_cells = 0, region_cells = 0;
  std::span<const std::uint32_t> occupied;   // occupied cells: row · width_cells + column
  std::span<const WorldPoint> plan_points;   // every recorded plan's path, one after the other
  std::span<const std::uint32_t> plan_ends;  // plan i is plan_points[plan_ends[i-1] .. plan_ends[i])
  std::span<const NamedPoint> places;        // a task planner's places (PDDL objects), if any
  std::span<const WorldPoint> reported;      // obstacles the controller reported to its planner
};

/// A segment in the world frame (m).
struct WorldSegment {
  WorldPoint a{};
  WorldPoint b{};
};

/// One moment of the localization drawn: its estimate, the particles then and the observations
/// that correction weighed (ground segments taken into the world with the estimate).
struct LocalizationSnapshot {
  double time_s = 0.0;
  Pose2 estimate{};
  std::uint32_t particles_end = 0;  // this snapshot's particles: particles[previous end .. particles_end)
  std::uint32_t segments_end = 0;   // ... and its segments: segments[previous end .. segments_end)
  std::string_view reason;          // why it was taken ("start", "relocalized", "correction", "every 5 s")
};

/// The localization over the run (all empty without one): the true trajectory beside the
/// estimated one (RunPicture::trajectory) and snapshots of the filter.
struct LocalizationPicture {
  std::span<const Pose2> truth;                   // the simulator's true pose, in driving order
  std::span<const LocalizationSnapshot> snapshots;
  std::span<const Pose2> particles;               // every snapshot's particles, one after the other
  std::span<const WorldSegment> segments;         // every snapshot's observed segments, likewise
};

/// What the controller did, to be drawn over the world.
struct RunPicture {
  std::span<const Pose2> trajectory;      // in driving order
  std::span<const WorldPoint> collisions;
  std::span<const WorldPoint> goals;      // the mission's, in order
  std::size_t goals_reached = 0;          // the first N goals are drawn as reached
  std::string_view caption;               // one line under the picture
  PlanPicture plans{};                    // the planner's map and plans, if any
  LocalizationPicture localization{};     // true vs estimated pose and the filter, if any
};

class GroundTruth {
 public:
  virtual ~GroundTruth() = default;
  /// Where the world's ball really is in the robot frame now (none: the world has no ball).
  [[nodiscard]] virtual std::optional<RobotPoint> ball_in_robot_frame() const noexcept = 0;
  /// Contact events between the robot and anything solid so far.
  [[nodiscard]] virtual std::uint64_t collisions() const noexcept = 0;
  /// Where the robot really is (none: this backend cannot say).
  [[nodiscard]] virtual std::optional<Pose2> robot_pose() const noexcept { return std::nullopt; }
  /// Path length really driven so far (m).
  [[nodiscard]] virtual double distance_travelled() const noexcept = 0;
  /// The world as an SVG picture with the run drawn over it.
  virtual void write_picture(std::ostream& out, const RunPicture& run) const = 0;
};

}  // namespace ringlet::hal
