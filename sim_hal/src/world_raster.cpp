#include "ringlet/sim_hal/world_raster.hpp"

#include "ringlet/sim_hal/collision.hpp"

namespace ringlet::sim_hal {

std::vector<std::uint8_t> blocked_cells(const World& world, const RasterGrid& grid) {
  std::vector<std::uint8_t> out;
  out.reserve(static_cast<std::size_t>(grid.width) * static_cast<std::size_t>(grid.height));
  for (int cy = 0; cy < grid.height; ++cy) {
    for (int cx = 0; cx < grid.width; ++cx) {
      const Vec2 centre{grid.origin_x + (cx + 0.5) * grid.resolution, grid.origin_y + (cy + 0.5) * grid.resolution};
      out.push_back(disc_collides(world, centre, 0.5 * grid.resolution) ? 1 : 0);
    }
  }
  return out;
}

}  // namespace ringlet::sim_hal
