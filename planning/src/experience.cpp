#include "ringlet/planning/experience.hpp"

#include <utility>

#include "ringlet/planning/grid_graph.hpp"
#include "ringlet/planning/occupancy_grid.hpp"

namespace ringlet::planning {
namespace {

struct Offset {
  int x, y;
};

// The region slots (every feature but kDiagonal) in the travel frame: travel along +x for a
// straight move, along +x+y for a diagonal one (experience.hpp has the table and the reasons).
constexpr std::array<Offset, kFeatureCount> kStraightSlots{{
    {0, 0},  // kDiagonal: no region
    {0, 0}, {1, 0},    // from, to
    {0, 1}, {0, -1},   // from_left, from_right
    {1, 1}, {1, -1},   // to_left, to_right
    {-1, 0}, {2, 0},   // behind, ahead
    {2, 1}, {2, -1},   // corner_left, corner_right
}};
constexpr std::array<Offset, kFeatureCount> kDiagonalSlots{{
    {0, 0},
    {0, 0}, {1, 1},
    {-1, 1}, {1, -1},
    {0, 2}, {2, 0},
    {-1, -1}, {2, 2},
    {0, 1}, {1, 0},
}};

/// Turns a travel-frame offset back into the map by `quarter_turns` × 90° counter-clockwise:
/// direction k is direction k mod 2 turned k / 2 times.
constexpr Offset rotate(Offset o, int quarter_turns) noexcept {
  for (int i = 0; i < quarter_turns; ++i) o = {-o.y, o.x};
  return o;
}

}  // namespace

Features transition_features(const RegionTransition& t) noexcept {
  const OccupancyGrid& map = *t.map;
  const MapConfig& c = map.config();
  const double cells = static_cast<double>(c.region_cells) * static_cast<double>(c.region_cells);
  const bool diagonal = is_diagonal(t.direction);
  const int fx = t.from % c.regions_x(), fy = t.from / c.regions_x();

  Features x{};
  x[kDiagonal] = diagonal ? 1.0 : 0.0;
  for (int i = kFrom; i < kFeatureCount; ++i) {
    const RegionOffset o = feature_offset(t.direction, i);
    const int rx = fx + o.dx, ry = fy + o.dy;
    int count = c.region_cells * c.region_cells;  // off the map: full
    if (i == kFrom) {
      count = t.from_occupied;
    } else if (i == kTo) {
      count = t.to_occupied;
    } else if (rx >= 0 && ry >= 0 && rx < c.regions_x() && ry < c.regions_y()) {
      count = map.region_count(ry * c.regions_x() + rx);
    }
    x[static_cast<std::size_t>(i)] = static_cast<double>(count) / cells;
  }
  return x;
}

RegionOffset feature_offset(int direction, int slot) noexcept {
  const auto& slots = is_diagonal(direction) ? kDiagonalSlots : kStraightSlots;
  const Offset o = rotate(slots[static_cast<std::size_t>(slot)], direction / 2);
  return {o.x, o.y};
}

Features mirrored(const Features& x) noexcept {
  Features m = x;
  std::swap(m[kFromLeft], m[kFromRight]);
  std::swap(m[kToLeft], m[kToRight]);
  std::swap(m[kCornerLeft], m[kCornerRight]);
  return m;
}

}  // namespace ringlet::planning
