#pragma once
// The global occupancy grid of Powers & Balch §III-B: obstacles the laser (or vision) reports are
// placed into cells by their discretised world position. A free cell hit by an obstacle becomes
// occupied; an occupied cell stays occupied (no decay: the paper's worlds are static). Cells are
// grouped into square regions that keep a count of their occupied cells, which the region graph's
// cost model reads; a region whose count changed is queued once for the planner to repair.
//
// Sized once from the configuration; marking never allocates.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "ringlet/hal/geometry.hpp"
#include "ringlet/hal/sensors.hpp"

namespace ringlet::planning {

/// Where the map lies and how fine it is ([planner] in the firmware's configuration).
struct MapConfig {
  double origin_x = 0.0;   // world x of the grid's lower-left corner (m)
  double origin_y = 0.0;   // world y of the grid's lower-left corner (m)
  double resolution = 0.25;  // side of a cell (m)
  int width_cells = 160;   // cells along x
  int height_cells = 160;  // cells along y
  int region_cells = 8;    // side of a region in cells: regions tile the grid exactly

  /// Empty when usable, else what is wrong (names the field).
  [[nodiscard]] std::string validate() const;
  [[nodiscard]] int regions_x() const noexcept { return width_cells / region_cells; }
  [[nodiscard]] int regions_y() const noexcept { return height_cells / region_cells; }
  [[nodiscard]] double region_size() const noexcept { return resolution * region_cells; }
};

class OccupancyGrid {
 public:
  /// Allocates the cells and regions (start-up). The config must validate().
  explicit OccupancyGrid(const MapConfig& config);

  [[nodiscard]] const MapConfig& config() const noexcept { return config_; }

  /// Marks the cell holding world point (wx, wy) occupied; false when it was already occupied
  /// or lies outside the map.
  bool mark(double wx, double wy) noexcept;
  /// Marks cell (cx, cy), which must lie inside the map; false when it was already occupied.
  bool mark_cell(int cx, int cy) noexcept;
  /// Marks the end point of every valid beam of `scan`, taken at `pose` (eq. 20: an invalid beam
  /// saw nothing and marks nothing). Returns the number of newly occupied cells.
  int integrate(const hal::LaserScan& scan, const hal::Pose2& pose) noexcept;

  /// The cell holding world point (wx, wy); false outside the map.
  [[nodiscard]] bool cell_of(double wx, double wy, int& cx, int& cy) const noexcept;
  [[nodiscard]] bool occupied(int cx, int cy) const noexcept {
    return cells_[static_cast<std::size_t>(cy * config_.width_cells + cx)] != 0;
  }
  [[nodiscard]] int occupied_cells() const noexcept { return occupied_total_; }

  /// Regions are numbered row by row: index = ry * regions_x + rx.
  [[nodiscard]] int region_of_cell(int cx, int cy) const noexcept {
    return (cy / config_.region_cells) * config_.regions_x() + cx / config_.region_cells;
  }
  /// The region holding world point (wx, wy), or −1 outside the map.
  [[nodiscard]] int region_at(double wx, double wy) const noexcept;
  [[nodiscard]] int region_count(int region) const noexcept { return counts_[static_cast<std::size_t>(region)]; }
  /// The world position of a region's centre: the waypoint of the control law that drives into it.
  [[nodiscard]] hal::Pose2 region_centre(int region) const noexcept;

  /// Regions whose count changed since the last clear_changes(), each once, in the order they
  /// changed; the span is valid until the next mark.
  [[nodiscard]] std::span<const int> changed_regions() const noexcept {
    return {changed_.data(), changed_count_};
  }
  void clear_changes() noexcept;

 private:
  MapConfig config_;
  std::vector<std::uint8_t> cells_;
  std::vector<int> counts_;
  std::vector<int> changed_;           // capacity: one entry per region
  std::vector<std::uint8_t> queued_;   // whether a region is in changed_
  std::size_t changed_count_ = 0;
  int occupied_total_ = 0;
};

}  // namespace ringlet::planning
