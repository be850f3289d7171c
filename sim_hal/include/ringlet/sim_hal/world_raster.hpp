#pragma once
// A world as a grid of blocked cells: the map a robot may be given before it drives (the
// planner's prior map, firmware's ringlet-world-map). Off the cycle path: it allocates.
#include <cstdint>
#include <vector>

#include "ringlet/sim_hal/world.hpp"

namespace ringlet::sim_hal {

struct RasterGrid {
  double origin_x = 0.0, origin_y = 0.0;  // the grid's south-west corner (m)
  double resolution = 0.25;               // a cell's side (m)
  int width = 0, height = 0;              // cells along x and y
};

/// Row-major, row 0 the grid's south edge: 1 where an obstacle (or the world's edge) comes within
/// half a cell of the cell's centre, the footprint a laser marks over time; else 0.
[[nodiscard]] std::vector<std::uint8_t> blocked_cells(const World& world, const RasterGrid& grid);

}  // namespace ringlet::sim_hal
