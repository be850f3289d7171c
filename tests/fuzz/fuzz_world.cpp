// Fuzz target: the world file parser (text -> World). Any input must either give a world that
// keeps the parser's promises (and that the simulator's geometry and the SVG writer can use), or
// a WorldError naming the source; any other exception, crash or sanitizer report is a bug.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <span>
#include <sstream>
#include <string>
#include <string_view>

#include "ringlet/sim_hal/collision.hpp"
#include "ringlet/sim_hal/world.hpp"
#include "ringlet/sim_hal/world_svg.hpp"

namespace {

constexpr std::string_view kSource = "fuzz.world";

bool finite(ringlet::sim_hal::Vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }

bool inside(const ringlet::sim_hal::World& w, ringlet::sim_hal::Vec2 v) {
  return v.x >= w.min.x && v.x <= w.max.x && v.y >= w.min.y && v.y <= w.max.y;
}

// What the simulator relies on once parse_world returned (world.hpp, sim_hal/README.md).
void check(const ringlet::sim_hal::World& w) {
  if (!finite(w.min) || !finite(w.max) || !(w.min.x < w.max.x) || !(w.min.y < w.max.y)) __builtin_trap();
  const ringlet::sim_hal::Vec2 start{w.start.x, w.start.y};
  if (!finite(start) || !inside(w, start)) __builtin_trap();
  // Headings are wrapped to (-pi, pi] (a NaN fails these comparisons too).
  if (!(std::abs(w.start.theta) <= std::numbers::pi)) __builtin_trap();
  if (!(std::abs(w.lighting.sun_angle) <= std::numbers::pi) || !std::isfinite(w.lighting.sun_phase)) __builtin_trap();
  for (const auto& c : w.circles) {
    if (!finite(c.centre) || !(c.radius > 0.0) || !std::isfinite(c.radius)) __builtin_trap();
  }
  for (const auto& p : w.polygons) {
    if (p.vertices.size() < 3) __builtin_trap();
    for (const auto& v : p.vertices) {
      if (!finite(v)) __builtin_trap();
    }
  }

  // Use it the way the simulator does: the laser's rays and the robot's collision disc from the
  // start pose, and the picture.
  constexpr double kMaxRange = 8.0;
  for (int i = 0; i < 8; ++i) {
    const double d = ringlet::sim_hal::cast_ray(w, start, i * (std::numbers::pi / 4.0), kMaxRange);
    if (std::isnan(d) || d < 0.0) __builtin_trap();
  }
  (void)ringlet::sim_hal::disc_collides(w, start, 0.25);
  // Goals are the mission's, not the world's: the picture draws them from the run. One at the
  // start, reached, so that drawing them is exercised on every world.
  const ringlet::hal::WorldPoint goal{start.x, start.y};
  ringlet::hal::RunPicture picture;
  picture.goals = std::span<const ringlet::hal::WorldPoint>(&goal, 1);
  picture.goals_reached = 1;
  std::ostringstream svg;
  ringlet::sim_hal::write_world_svg(svg, w, picture);
  if (svg.str().find("</svg>") == std::string::npos) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    check(ringlet::sim_hal::parse_world(text, kSource));
  } catch (const ringlet::sim_hal::WorldError& e) {
    // Every message names where: "fuzz.world:line: ...".
    if (std::string_view(e.what()).substr(0, kSource.size() + 1) != std::string(kSource) + ":") __builtin_trap();
  }
  return 0;
}
