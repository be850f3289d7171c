#pragma once
// The simulated world: bounds, obstacles (circles and polygons), optional field markings, a ball,
// the start pose and the ordered goal sequence. Loaded from the versioned text format documented
// in sim_hal/README.md. Loading is all-or-nothing: on any error a WorldError("file:line: message")
// is thrown and no World exists.
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "ringlet/hal/geometry.hpp"

namespace ringlet::sim {

struct Vec2 {
  double x = 0.0;
  double y = 0.0;
};

struct Circle {
  Vec2 centre{};
  double radius = 0.0;
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

struct Ball {
  Vec2 position{};
  double radius = 0.05;
};

struct World {
  static constexpr int kFormatVersion = 1;

  std::string name;
  Vec2 min{};  // bounds: the walls of the world, an obstacle for the robot and the laser
  Vec2 max{};
  hal::Pose2 start{};
  std::vector<Circle> circles;
  std::vector<Polygon> polygons;
  std::vector<Marking> markings;
  std::optional<Ball> ball;
  std::vector<Vec2> goals;  // visited in order
};

class WorldError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Parses world text. `source` names it in error messages ("<source>:<line>: <message>").
[[nodiscard]] World parse_world(std::string_view text, std::string_view source);
/// Reads and parses a world file; an unreadable file is a WorldError naming the path.
[[nodiscard]] World load_world(const std::filesystem::path& path);

}  // namespace ringlet::sim
