// After reserve(), a search, its slices, its repairs and its path allocate nothing; marking the
// map allocates nothing.
#include <gtest/gtest.h>

#include <array>

#include "allocation_counter.hpp"
#include "ringlet/planning/dstar_lite.hpp"
#include "ringlet/planning/region_graph.hpp"

namespace ringlet::planning {
namespace {

TEST(PlanningNoAllocation, SearchRepairAndPathAllocateNothing) {
  MapConfig c;
  c.resolution = 0.25;
  c.width_cells = 160;
  c.height_cells = 160;
  c.region_cells = 4;
  OccupancyGrid map(c);
  const BinaryCostModel model({.max_occupied = 0, .top_speed = 1.5});
  const RegionGraph graph(map, model);
  DStarLite d;
  d.reserve(graph.vertex_count());
  std::array<int, 4096> path{};
  const std::uint64_t before = ringlet::test::allocations();
  ASSERT_TRUE(d.begin(graph, graph.vertex(1, 1), graph.vertex(38, 38)));
  while (d.step(50) == SearchStatus::kSearching) {}
  int n = d.extract_path(path);
  for (int i = 0; i < 30; ++i) map.mark(20.0 + 0.1 * i, 1.0 + 0.3 * i);  // a wall across the way
  for (const int r : map.changed_regions()) d.vertex_changed(r);
  map.clear_changes();
  d.move_start(d.next_vertex());
  while (d.step(50) == SearchStatus::kSearching) {}
  n += d.extract_path(path);
  EXPECT_EQ(ringlet::test::allocations() - before, 0U);
  EXPECT_GT(n, 0);
  EXPECT_EQ(d.status(), SearchStatus::kReady);
}

}  // namespace
}  // namespace ringlet::planning
