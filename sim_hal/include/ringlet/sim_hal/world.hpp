#pragma once
// The simulated world: bounds, obstacles (circles and polygons), optional field markings (lines
// and rings), the carpet's lighting, a ball and
// the start pose. (Goals are not the world's: they belong to the mission's configuration.) Loaded from the versioned text format documented
// in sim_hal/README.md. Loading is all-or-nothing: on any error a WorldError("file:line: message")
// is thrown and no World exists.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "ringlet/hal/geometry.hpp"
#include "ringlet/sim_hal/camera_look.hpp"

namespace ringlet::sim_hal {

struct Vec2 {
  double x = 0.0;
  double y = 0.0;
};

/// What an obstacle is, for the camera's colours (the laser and collisions do not care).
enum class ObstacleKind : std::uint8_t { kObstacle, kRobot, kPost };

/// A round obstacle. The camera sees it as a vertical cylinder of `height` standing on the ground.
struct Circle {
  Vec2 centre{};
  double radius = 0.0;
  double height = 0.58;  // m; the default is a NAO's height (format version 2 may set it)
  ObstacleKind kind = ObstacleKind::kObstacle;
};

/// A simple polygon (at least 3 vertices, not self-intersecting), either winding.
struct Polygon {
  std::vector<Vec2> vertices;
};

/// A painted line on the ground (field marking): visible to the camera, not an obstacle.
struct Marking {
  Vec2 a{};
  Vec2 b{};
  double width = 0.05;
};

/// A painted circle on the ground (the centre circle): visible to the camera, not an obstacle.
struct Ring {
  Vec2 centre{};
  double radius = 0.0;  // to the middle of the paint
  double width = 0.05;
};

/// How the camera sees the carpet: seed-independent appearance parameters. Sunlight falls through
/// windows as parallel stripes: bright bands of `sun_period / 2` alternating with shadow.
struct Lighting {
  double brightness = 1.0;    // overall scale, 1 = nominal
  double texture = 0.08;      // amplitude of the carpet's texture noise, fraction of its colour
  double sun_strength = 0.0;  // 0 = no stripes; bright bands gain, shadows lose this fraction
  double sun_period = 2.0;    // m, one bright and one shadow band
  double sun_angle = 0.0;     // rad, the stripes' direction as a heading (geometry.hpp convention)
  double sun_phase = 0.0;     // m, shift of the stripes across their direction
};

struct Ball {
  Vec2 position{};
  double radius = 0.05;
};

struct World {
  static constexpr int kFormatVersion = 2;     // written by this build
  static constexpr int kMinFormatVersion = 1;  // oldest still read

  std::string name;
  Vec2 min{};  // bounds: the walls of the world, an obstacle for the robot and the laser
  Vec2 max{};
  hal::Pose2 start{};
  int start_line = 0;  // the line of the `start` statement, for messages about the start pose
  std::vector<Circle> circles;
  std::vector<Polygon> polygons;
  std::vector<Marking> markings;
  std::vector<Ring> rings;
  Lighting lighting{};
  CameraLook look{};  // how the camera's pictures look (the `look` statement; plain by default)
  std::optional<Ball> ball;
  // More balls for the camera only (ringlet-dataset's scenes): drawn and given ground truth like
  // `ball`, but the ball sensor and the mission know only `ball`. The world file cannot set them.
  std::vector<Ball> extra_balls;
};

class WorldError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Parses world text. `source` names it in error messages ("<source>:<line>: <message>").
[[nodiscard]] World parse_world(std::string_view text, std::string_view source);
/// Reads (hal::read_file: a regular file of at most hal::kMaxTextFileBytes) and parses a world
/// file; an unreadable file is a WorldError naming the path and why.
[[nodiscard]] World load_world(const std::filesystem::path& path);

}  // namespace ringlet::sim_hal
