// The experience features (eq. 22) are in the robot's frame: the same local situation turned by
// 90° gives the same features, a mirrored one swaps left and right, and each slot reads the
// region the documentation says.
#include <gtest/gtest.h>

#include "ringlet/hal/splitmix64.hpp"
#include "ringlet/planning/experience.hpp"
#include "ringlet/planning/region_graph.hpp"

namespace ringlet::planning {
namespace {

constexpr int kRegions = 7;      // 7 × 7 regions: the transition's window fits around the centre
constexpr int kRegionCells = 4;  // 16 cells a region

MapConfig square_map() {
  MapConfig c;
  c.resolution = 0.25;
  c.width_cells = kRegions * kRegionCells;
  c.height_cells = kRegions * kRegionCells;
  c.region_cells = kRegionCells;
  return c;
}

/// Cells to occupy; a map is built from them turned or mirrored as a test needs.
struct Cell {
  int x, y;
};

std::vector<Cell> random_cells(std::uint64_t seed) {
  hal::SplitMix64 rng(seed);
  std::vector<Cell> cells;
  const int n = kRegions * kRegionCells;
  for (int i = 0; i < 300; ++i)
    cells.push_back({static_cast<int>(rng.below(static_cast<std::uint64_t>(n))), static_cast<int>(rng.below(static_cast<std::uint64_t>(n)))});
  return cells;
}

constexpr int kSide = kRegions * kRegionCells;
Cell turned(Cell c) { return {kSide - 1 - c.y, c.x}; }  // 90° counter-clockwise about the centre
Cell mirrored_x(Cell c) { return {c.x, kSide - 1 - c.y}; }  // across the horizontal axis

void fill(OccupancyGrid& m, const std::vector<Cell>& cells) {
  for (const Cell& c : cells) m.mark_cell(c.x, c.y);
}

/// The region centre turned like the cells.
int turned_region(const GridGraph& g, int v) { return g.vertex(kRegions - 1 - g.y_of(v), g.x_of(v)); }
int mirrored_region(const GridGraph& g, int v) { return g.vertex(g.x_of(v), kRegions - 1 - g.y_of(v)); }

TEST(ExperienceFeatures, TurningTheSituationBy90DegreesGivesTheSameFeatures) {
  const BinaryCostModel model({.max_occupied = 2, .top_speed = 2.0});
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    std::vector<Cell> cells = random_cells(seed);
    OccupancyGrid map(square_map());
    fill(map, cells);
    const RegionGraph graph(map, model);
    const int centre = graph.vertex(3, 3);
    for (int k = 0; k < kGridDirections; ++k) {
      const Features original = transition_features(graph.transition(centre, k));
      // Turn the world (cells, start region, direction) by 90° up to three times.
      std::vector<Cell> c = cells;
      int v = centre, dir = k;
      for (int turn = 1; turn <= 3; ++turn) {
        for (Cell& cell : c) cell = turned(cell);
        v = turned_region(graph, v);
        dir = (dir + 2) % kGridDirections;
        OccupancyGrid turned_map(square_map());
        fill(turned_map, c);
        const RegionGraph turned_graph(turned_map, model);
        EXPECT_EQ(transition_features(turned_graph.transition(v, dir)), original)
            << "seed " << seed << ", direction " << k << ", turned " << turn << " times";
      }
    }
  }
}

TEST(ExperienceFeatures, AMirroredSituationSwapsLeftAndRight) {
  const BinaryCostModel model({.max_occupied = 2, .top_speed = 2.0});
  int asymmetric = 0;
  for (std::uint64_t seed = 11; seed <= 20; ++seed) {
    std::vector<Cell> cells = random_cells(seed);
    OccupancyGrid map(square_map());
    fill(map, cells);
    std::vector<Cell> mirror_cells = cells;
    for (Cell& c : mirror_cells) c = mirrored_x(c);
    OccupancyGrid mirror_map(square_map());
    fill(mirror_map, mirror_cells);
    const RegionGraph graph(map, model), mirror_graph(mirror_map, model);
    const int centre = graph.vertex(3, 3);
    for (int k = 0; k < kGridDirections; ++k) {
      const Features x = transition_features(graph.transition(centre, k));
      asymmetric += x != mirrored(x) ? 1 : 0;
      const int mirror_k = (kGridDirections - k) % kGridDirections;  // y → −y
      const Features m = transition_features(mirror_graph.transition(mirrored_region(graph, centre), mirror_k));
      EXPECT_EQ(m, mirrored(x)) << "seed " << seed << ", direction " << k;
    }
  }
  EXPECT_GT(asymmetric, 40);  // the swap is tested, not a situation that is its own mirror image
}

TEST(ExperienceFeatures, EachSlotReadsItsRegion) {
  OccupancyGrid map(square_map());
  const BinaryCostModel model({.max_occupied = 2, .top_speed = 2.0});
  const RegionGraph graph(map, model);
  // A distinct count (1 … 15 cells of 16) in every region around (2, 2) → (3, 2) (straight east)
  // and (2, 2) → (3, 3) (diagonal north-east).
  auto put = [&](int rx, int ry, int n) {
    for (int i = 0; i < n; ++i) map.mark_cell(rx * kRegionCells + i % kRegionCells, ry * kRegionCells + i / kRegionCells);
  };
  int n = 1;
  for (int ry = 1; ry <= 4; ++ry)
    for (int rx = 1; rx <= 4; ++rx) put(rx, ry, n++ % 16);
  auto frac = [&](int rx, int ry) { return map.region_count(graph.vertex(rx, ry)) / 16.0; };

  const Features s = transition_features(graph.transition(graph.vertex(2, 2), 0));
  EXPECT_EQ(s[kDiagonal], 0.0);
  EXPECT_EQ(s[kFrom], frac(2, 2));
  EXPECT_EQ(s[kTo], frac(3, 2));
  EXPECT_EQ(s[kFromLeft], frac(2, 3));
  EXPECT_EQ(s[kFromRight], frac(2, 1));
  EXPECT_EQ(s[kToLeft], frac(3, 3));
  EXPECT_EQ(s[kToRight], frac(3, 1));
  EXPECT_EQ(s[kBehind], frac(1, 2));
  EXPECT_EQ(s[kAhead], frac(4, 2));
  EXPECT_EQ(s[kCornerLeft], frac(4, 3));
  EXPECT_EQ(s[kCornerRight], frac(4, 1));

  const Features d = transition_features(graph.transition(graph.vertex(2, 2), 1));
  EXPECT_EQ(d[kDiagonal], 1.0);
  EXPECT_EQ(d[kFrom], frac(2, 2));
  EXPECT_EQ(d[kTo], frac(3, 3));
  EXPECT_EQ(d[kFromLeft], frac(1, 3));
  EXPECT_EQ(d[kFromRight], frac(3, 1));
  EXPECT_EQ(d[kToLeft], frac(2, 4));
  EXPECT_EQ(d[kToRight], frac(4, 2));
  EXPECT_EQ(d[kBehind], frac(1, 1));
  EXPECT_EQ(d[kAhead], frac(4, 4));
  EXPECT_EQ(d[kCornerLeft], frac(2, 3));
  EXPECT_EQ(d[kCornerRight], frac(3, 2));
}

TEST(ExperienceFeatures, OffTheMapIsFullAndTheRobotsRegionIsEmpty) {
  OccupancyGrid map(square_map());
  const BinaryCostModel model({.max_occupied = 2, .top_speed = 2.0});
  RegionGraph graph(map, model);
  for (int i = 0; i < 5; ++i) map.mark_cell(i % kRegionCells, i / kRegionCells);  // 5 cells in region (0, 0)
  const Features x = transition_features(graph.transition(graph.vertex(0, 0), 0));  // east along the edge
  EXPECT_EQ(x[kFrom], 5.0 / 16.0);
  EXPECT_EQ(x[kFromRight], 1.0);  // y = −1: off the map
  EXPECT_EQ(x[kToRight], 1.0);
  EXPECT_EQ(x[kBehind], 1.0);     // x = −1
  EXPECT_EQ(x[kFromLeft], 0.0);
  graph.set_robot_region(graph.vertex(0, 0));
  EXPECT_EQ(transition_features(graph.transition(graph.vertex(0, 0), 0))[kFrom], 0.0);
}

}  // namespace
}  // namespace ringlet::planning
