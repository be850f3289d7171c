#include "ringlet/planning/occupancy_grid.hpp"

#include <algorithm>
#include <cmath>

namespace ringlet::planning {

std::string MapConfig::validate() const {
  if (!(resolution > 0.0) || !std::isfinite(resolution)) return "resolution must be a positive number of metres";
  if (!std::isfinite(origin_x) || !std::isfinite(origin_y)) return "origin_x and origin_y must be finite";
  if (width_cells <= 0 || height_cells <= 0) return "width_cells and height_cells must be positive";
  if (width_cells > 4096 || height_cells > 4096) return "width_cells and height_cells must be at most 4096";
  if (region_cells <= 0) return "region_cells must be positive";
  if (width_cells % region_cells != 0 || height_cells % region_cells != 0)
    return "width_cells and height_cells must be multiples of region_cells (regions tile the grid)";
  return {};
}

OccupancyGrid::OccupancyGrid(const MapConfig& config)
    : config_(config),
      cells_(static_cast<std::size_t>(config.width_cells) * static_cast<std::size_t>(config.height_cells), 0),
      counts_(static_cast<std::size_t>(config.regions_x() * config.regions_y()), 0),
      changed_(counts_.size(), 0),
      queued_(counts_.size(), 0) {}

bool OccupancyGrid::cell_of(double wx, double wy, int& cx, int& cy) const noexcept {
  const double fx = std::floor((wx - config_.origin_x) / config_.resolution);
  const double fy = std::floor((wy - config_.origin_y) / config_.resolution);
  // NaN fails both comparisons, so it is outside too.
  if (!(fx >= 0.0 && fx < config_.width_cells && fy >= 0.0 && fy < config_.height_cells)) return false;
  cx = static_cast<int>(fx);
  cy = static_cast<int>(fy);
  return true;
}

int OccupancyGrid::region_at(double wx, double wy) const noexcept {
  int cx = 0, cy = 0;
  return cell_of(wx, wy, cx, cy) ? region_of_cell(cx, cy) : -1;
}

hal::Pose2 OccupancyGrid::region_centre(int region) const noexcept {
  const int rx = region % config_.regions_x(), ry = region / config_.regions_x();
  const double size = config_.region_size();
  return {config_.origin_x + (rx + 0.5) * size, config_.origin_y + (ry + 0.5) * size, 0.0};
}

bool OccupancyGrid::mark(double wx, double wy) noexcept {
  int cx = 0, cy = 0;
  return cell_of(wx, wy, cx, cy) && mark_cell(cx, cy);
}

bool OccupancyGrid::mark_cell(int cx, int cy) noexcept {
  std::uint8_t& cell = cells_[static_cast<std::size_t>(cy * config_.width_cells + cx)];
  if (cell != 0) return false;  // an occupied cell stays occupied: the obstacle has no effect
  cell = 1;
  ++occupied_total_;
  const auto r = static_cast<std::size_t>(region_of_cell(cx, cy));
  ++counts_[r];
  if (queued_[r] == 0) {
    queued_[r] = 1;
    changed_[changed_count_++] = static_cast<int>(r);
  }
  return true;
}

int OccupancyGrid::integrate(const hal::LaserScan& scan, const hal::Pose2& pose) noexcept {
  int marked = 0;
  const std::size_t beams = std::min<std::size_t>(scan.beam_count, hal::LaserScan::kMaxBeams);
  for (std::size_t i = 0; i < beams; ++i) {
    if (!scan.valid[i]) continue;
    // Beam angles are in the robot frame with theta's sense (positive to the right), so the
    // world bearing is their sum (hal/geometry.hpp: ahead is (sin θ, cos θ)).
    const double bearing = pose.theta + scan.beam_angle(i);
    const double r = static_cast<double>(scan.range[i]);
    if (mark(pose.x + r * std::sin(bearing), pose.y + r * std::cos(bearing))) ++marked;
  }
  return marked;
}

void OccupancyGrid::clear_changes() noexcept {
  for (std::size_t i = 0; i < changed_count_; ++i) queued_[static_cast<std::size_t>(changed_[i])] = 0;
  changed_count_ = 0;
}

}  // namespace ringlet::planning
