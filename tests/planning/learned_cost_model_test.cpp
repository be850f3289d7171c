// The learned cost model in the planner's loop: its per-edge cache and feature memo against fresh
// predictions after random map changes, robot moves and publishes; D* Lite repaired after a
// publish against a search from scratch with the new costs; the transition recorder.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "ringlet/planning/dstar_lite.hpp"
#include "ringlet/planning/learned_cost_model.hpp"
#include "ringlet/planning/rebuild_worker.hpp"
#include "ringlet/planning/region_graph.hpp"
#include "ringlet/planning/transition_recorder.hpp"
#include "test_graph.hpp"

namespace ringlet::planning {
namespace {

MapConfig small_map() {
  MapConfig c;
  c.resolution = 0.25;
  c.width_cells = 48;
  c.height_cells = 40;
  c.region_cells = 4;  // 12 × 10 regions of 1 m
  return c;
}

/// Random experiences whose speed falls with the occupancy around the transition: a model that
/// gives different edges different costs.
void add_experiences(KnnRegressor& knn, std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < n; ++i) {
    Features x{};
    x[kDiagonal] = u(rng) < 0.5 ? 1.0 : 0.0;
    double load = 0.0;
    for (int s = kFrom; s < kFeatureCount; ++s) {
      x[static_cast<std::size_t>(s)] = u(rng) < 0.6 ? 0.0 : std::floor(u(rng) * 8.0) / 16.0;
      load += x[static_cast<std::size_t>(s)];
    }
    ASSERT_TRUE(knn.add(x, std::max(0.05, 1.0 - 0.4 * load + 0.1 * u(rng))));
  }
}

void mark_random(OccupancyGrid& map, std::mt19937& rng, int cells) {
  std::uniform_int_distribution<int> cx(0, map.config().width_cells - 1), cy(0, map.config().height_cells - 1);
  for (int i = 0; i < cells; ++i) (void)map.mark_cell(cx(rng), cy(rng));
}

/// What the model must answer for edge (v, k) now: the wall rule, else a fresh prediction.
double fresh_speed(const LearnedCostModel& model, const KnnRegressor& knn, const RegionTransition& t) {
  const int wall = model.params().wall_occupied;
  if (t.from_occupied > wall || t.to_occupied > wall) return 0.0;
  return std::clamp(knn.predict(transition_features(t)), 0.0, model.top_speed());
}

/// Forgets what the map's changes and the robot's move touched, as the planner task does.
void forget(LearnedCostModel& model, OccupancyGrid& map, int old_robot, int robot, DStarLite* search) {
  std::array<int, LearnedCostModel::kMaxSources> sources{};
  if (old_robot != robot) {
    model.edges_from_changed(old_robot);
    model.edges_from_changed(robot);
    if (search != nullptr) {
      search->edges_changed(old_robot);
      search->edges_changed(robot);
    }
  }
  for (const int r : map.changed_regions()) {
    const std::size_t n = model.region_changed(r, sources);
    ASSERT_LE(n, sources.size());
    if (search != nullptr) {
      for (std::size_t i = 0; i < n; ++i) search->edges_changed(sources[i]);
    }
  }
  map.clear_changes();
}

TEST(LearnedCostModel, CacheEqualsFreshPredictionsAfterRandomChangesMovesAndPublishes) {
  for (const std::uint32_t seed : {1U, 2U, 3U, 4U}) {
    std::mt19937 rng(seed);
    OccupancyGrid map(small_map());
    KnnRegressor knn({.k = 3, .distance_weighted = seed % 2 == 0, .prior_speed = 1.0});
    knn.reserve(2000);
    add_experiences(knn, rng, 300);
    ASSERT_TRUE(knn.rebuild());
    ASSERT_TRUE(knn.publish());
    LearnedCostModel model(knn, {.top_speed = 1.0, .wall_occupied = 5, .memo_capacity = 256}, map.config());
    RegionGraph graph(map, model);
    std::uniform_int_distribution<int> region(0, graph.vertex_count() - 1);
    int robot = -1;
    for (int round = 0; round < 40; ++round) {
      const int old_robot = robot;
      robot = region(rng);
      graph.set_robot_region(robot);
      mark_random(map, rng, 6);
      forget(model, map, old_robot, robot, nullptr);
      if (round % 7 == 3) {  // a publish, sometimes while the map changes mid-refresh
        add_experiences(knn, rng, 50);
        ASSERT_TRUE(knn.rebuild());
        ASSERT_TRUE(model.begin_refresh());
        (void)model.refresh(graph, 5, 40);
        mark_random(map, rng, 6);
        forget(model, map, robot, robot, nullptr);
        (void)graph.step_cost(region(rng), 0);  // a lookup mid-refresh: the old index answers
        while (!model.refresh(graph, 5, 40)) {
        }
        (void)model.finish_refresh();
      }
      for (int v = 0; v < graph.vertex_count(); ++v) {
        for (int k = 0; k < kGridDirections; ++k) {
          const RegionTransition t = graph.transition(v, k);
          if (t.to < 0) continue;
          ASSERT_EQ(model.expected_speed(t), fresh_speed(model, knn, t))
              << "seed " << seed << " round " << round << " edge " << v << "/" << k;
        }
      }
    }
    EXPECT_GT(model.predictions(), 0U);
  }
}

TEST(LearnedCostModel, TheMemoAnswersRepeatedFeaturesWithoutAQuery) {
  std::mt19937 rng(5);
  OccupancyGrid map(small_map());
  KnnRegressor knn({.k = 5, .distance_weighted = false, .prior_speed = 1.0});
  knn.fit({});
  knn.reserve(100);
  add_experiences(knn, rng, 100);
  ASSERT_TRUE(knn.rebuild());
  ASSERT_TRUE(knn.publish());
  LearnedCostModel model(knn, {.top_speed = 1.0, .wall_occupied = 5, .memo_capacity = 64}, map.config());
  const RegionGraph graph(map, model);
  for (int v = 0; v < graph.vertex_count(); ++v) {
    for (int k = 0; k < kGridDirections; ++k) (void)graph.step_cost(v, k);
  }
  // An empty map: inside, one straight and one diagonal situation; along the borders a few more
  // (off the map counts as full). Far fewer than the 960 edges.
  EXPECT_LT(model.predictions(), 60U);
}

TEST(LearnedCostModel, WallsStayImpassableWhateverTheModelSays) {
  OccupancyGrid map(small_map());
  KnnRegressor knn({.k = 1, .distance_weighted = false, .prior_speed = 1.0});
  knn.fit({});  // no experience: the prior (top speed) everywhere
  LearnedCostModel model(knn, {.top_speed = 1.0, .wall_occupied = 3, .memo_capacity = 64}, map.config());
  const RegionGraph graph(map, model);
  const int v = graph.vertex(3, 3);
  EXPECT_EQ(graph.step_cost(v, 0), 1'000'000'000);
  for (int i = 0; i < 4; ++i) (void)map.mark_cell(16, 12 + i);  // a line of 4 cells in region (4, 3)
  std::array<int, LearnedCostModel::kMaxSources> sources{};
  for (const int r : map.changed_regions()) (void)model.region_changed(r, sources);
  EXPECT_EQ(graph.step_cost(v, 0), kInfiniteCost);
}

TEST(LearnedCostModel, ARegionChangeNamesEveryEdgeSourceWhoseFeaturesReadIt) {
  OccupancyGrid map(small_map());
  KnnRegressor knn({.k = 1, .distance_weighted = false, .prior_speed = 1.0});
  knn.fit({});
  LearnedCostModel model(knn, {.top_speed = 1.0, .wall_occupied = 3, .memo_capacity = 64}, map.config());
  const RegionGraph graph(map, model);
  const int r = graph.vertex(5, 5);
  std::array<int, LearnedCostModel::kMaxSources> sources{};
  const std::size_t n = model.region_changed(r, sources);
  // Brute force: every edge whose feature window holds r.
  std::vector<int> expected;
  for (int v = 0; v < graph.vertex_count(); ++v) {
    for (int k = 0; k < kGridDirections; ++k) {
      for (int s = kFrom; s < kFeatureCount; ++s) {
        const RegionOffset o = feature_offset(k, s);
        if (graph.x_of(v) + o.dx == 5 && graph.y_of(v) + o.dy == 5 &&
            std::find(expected.begin(), expected.end(), v) == expected.end())
          expected.push_back(v);
      }
    }
  }
  std::vector<int> got(sources.begin(), sources.begin() + static_cast<std::ptrdiff_t>(n));
  std::sort(got.begin(), got.end());
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(got, expected);
}

TEST(LearnedCostModel, DStarLiteRepairedAfterAPublishEqualsASearchFromScratch) {
  for (const std::uint32_t seed : {11U, 12U, 13U, 14U, 15U, 16U}) {
    std::mt19937 rng(seed);
    OccupancyGrid map(small_map());
    KnnRegressor knn({.k = 4, .distance_weighted = true, .prior_speed = 1.0});
    knn.reserve(2000);
    add_experiences(knn, rng, 200);
    ASSERT_TRUE(knn.rebuild());
    ASSERT_TRUE(knn.publish());
    LearnedCostModel model(knn, {.top_speed = 1.0, .wall_occupied = 4, .memo_capacity = 512}, map.config());
    RegionGraph graph(map, model);
    mark_random(map, rng, 120);
    map.clear_changes();
    const int start = graph.vertex(0, 0), goal = graph.vertex(11, 9);
    graph.set_robot_region(start);
    DStarLite search;
    search.reserve(graph.vertex_count());
    ASSERT_TRUE(search.begin(graph, start, goal));
    (void)search.step(1'000'000);
    // New experiences (other speeds), an index rebuilt, the refresh sliced, the changes fed in;
    // more obstacles arrive during the refresh too.
    add_experiences(knn, rng, 400);
    ASSERT_TRUE(knn.rebuild());
    ASSERT_TRUE(model.begin_refresh());
    (void)model.refresh(graph, 10, 100);
    mark_random(map, rng, 20);
    forget(model, map, start, start, &search);
    (void)search.step(1'000'000);
    while (!model.refresh(graph, 10, 100)) {
    }
    const auto changed = model.finish_refresh();
    EXPECT_GT(changed.size(), 0U) << "the new index must change some costs";
    for (const int v : changed) search.edges_changed(v);
    const SearchStatus status = search.step(1'000'000);
    DStarLite fresh;
    fresh.reserve(graph.vertex_count());
    ASSERT_TRUE(fresh.begin(graph, start, goal));
    ASSERT_EQ(fresh.step(1'000'000), status) << "seed " << seed;
    EXPECT_EQ(search.plan_cost(), fresh.plan_cost()) << "seed " << seed;
    const std::vector<Cost> d = testing::distances_to(graph, goal);
    EXPECT_EQ(search.plan_cost(), status == SearchStatus::kReady ? d[static_cast<std::size_t>(start)] : kInfiniteCost);
  }
}

TEST(RebuildWorker, RebuildsOffTheCallingThreadOverTheRequestedCount) {
  std::mt19937 rng(3);
  KnnRegressor knn({.k = 2, .distance_weighted = false, .prior_speed = 1.0});
  knn.reserve(100);
  add_experiences(knn, rng, 30);
  RebuildWorker worker(knn);
  worker.request(20);
  add_experiences(knn, rng, 10);  // after the request: not in this index
  worker.wait_idle();
  EXPECT_TRUE(worker.idle());
  ASSERT_TRUE(knn.pending());
  ASSERT_TRUE(knn.publish());
  EXPECT_EQ(knn.visible(), 20U);
}

/// A 12 × 10 region graph over an empty map, for the recorder.
struct RecorderRig {
  OccupancyGrid map{small_map()};
  BinaryCostModel model{{.max_occupied = 2, .top_speed = 1.0}};
  RegionGraph graph{map, model};
  TransitionRecorder recorder{1.0};
  bool at(int rx, int ry, double x, double y, double t_s, std::uint64_t leg, Experience& out, double command = 0.8) {
    const int region = graph.vertex(rx, ry);
    graph.set_robot_region(region);
    TransitionSample s;
    s.region = region;
    s.x = x;
    s.y = y;
    s.time_ns = static_cast<std::int64_t>(std::llround(t_s * 1e9));
    s.frame = static_cast<std::uint64_t>(std::llround(t_s * 100));
    s.commanded_speed = command;
    s.leg = leg;
    return recorder.observe(graph, s, out);
  }
};

TEST(TransitionRecorder, AnAdjacentRegionEnteredIsOneExperience) {
  RecorderRig rig;
  Experience e;
  EXPECT_FALSE(rig.at(2, 2, 2.0, 2.5, 1.0, 1, e, 1.0));   // the first region: nothing before it
  EXPECT_FALSE(rig.at(2, 2, 2.4, 2.5, 1.5, 1, e, 0.5));   // still there
  ASSERT_TRUE(rig.at(3, 2, 3.0, 2.5, 2.0, 1, e, 0.9));    // entered (3, 2): 1 m of progress in 1 s
  EXPECT_DOUBLE_EQ(e.duration_s, 1.0);
  EXPECT_DOUBLE_EQ(e.achieved_speed, 1.0);
  EXPECT_DOUBLE_EQ(e.commanded_speed, 0.75);  // the samples in (2, 2)
  EXPECT_EQ(e.frame, 200U);
  EXPECT_EQ(e.features[kDiagonal], 0.0);
  ASSERT_TRUE(rig.at(4, 3, 4.0, 3.0, 4.0, 1, e));  // diagonal, 1.118 m of progress in 2 s
  EXPECT_EQ(e.features[kDiagonal], 1.0);
  EXPECT_NEAR(e.achieved_speed, std::hypot(1.0, 0.5) / 2.0, 1e-12);
}

TEST(TransitionRecorder, JumpsLegChangesAndLostPosesAreNotExperiences) {
  RecorderRig rig;
  Experience e;
  EXPECT_FALSE(rig.at(2, 2, 2.5, 2.5, 1.0, 1, e));
  EXPECT_FALSE(rig.at(4, 2, 4.5, 2.5, 2.0, 1, e));  // two regions on: a jump
  EXPECT_FALSE(rig.at(5, 2, 5.0, 2.5, 3.0, 2, e));  // a new target: the leg starts afresh
  ASSERT_TRUE(rig.at(6, 2, 6.0, 2.5, 4.0, 2, e));
  TransitionSample lost;
  EXPECT_FALSE(rig.recorder.observe(rig.graph, lost, e));  // no region: forgets the last
  EXPECT_FALSE(rig.at(7, 2, 7.0, 2.5, 5.0, 2, e));
  ASSERT_TRUE(rig.at(8, 2, 8.0, 2.5, 5.1, 2, e));  // 1 m in 0.1 s: clamped to the top speed
  EXPECT_DOUBLE_EQ(e.achieved_speed, 1.0);
}

}  // namespace
}  // namespace ringlet::planning
