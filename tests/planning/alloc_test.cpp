// After reserve(), a search, its slices, its repairs and its path allocate nothing; marking the
// map allocates nothing. The learned model's cycle side allocates nothing either: an experience's
// features, storing an experience up to the reserved capacity, predicting, publishing.
#include <gtest/gtest.h>

#include <array>

#include "allocation_counter.hpp"
#include "ringlet/planning/dstar_lite.hpp"
#include "ringlet/planning/knn_regressor.hpp"
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

TEST(PlanningNoAllocation, FeaturesAddPredictAndPublishAllocateNothing) {
  MapConfig c;
  c.width_cells = 64;
  c.height_cells = 64;
  c.region_cells = 8;
  OccupancyGrid map(c);
  for (int i = 0; i < 64; ++i) map.mark_cell(i, (i * 7) % 64);
  const BinaryCostModel model({.max_occupied = 2, .top_speed = 2.0});
  const RegionGraph graph(map, model);
  for (const bool weighted : {false, true}) {
    KnnRegressor knn({.k = KnnRegressor::kMaxK, .distance_weighted = weighted});
    knn.reserve(2000);
    for (int i = 0; i < 1000; ++i) {
      const RegionTransition t = graph.transition(i % graph.vertex_count(), i % kGridDirections);
      if (t.to >= 0) {
        ASSERT_TRUE(knn.add(transition_features(t), 0.001 * i));
      }
    }
    ASSERT_TRUE(knn.rebuild());  // off the cycle: allocates
    double sum = 0.0;
    const std::uint64_t before = ringlet::test::allocations();
    ASSERT_TRUE(knn.publish());
    for (int v = 0; v < graph.vertex_count(); ++v)
      for (int k = 0; k < kGridDirections; ++k) {
        const RegionTransition t = graph.transition(v, k);
        if (t.to < 0) continue;
        const Features x = transition_features(t);
        sum += knn.predict(x);
        (void)knn.add(x, 1.0);
      }
    EXPECT_EQ(ringlet::test::allocations() - before, 0U);
    EXPECT_GT(sum, 0.0);
  }
}

}  // namespace
}  // namespace ringlet::planning
