// D* Lite against Dijkstra from scratch: on random graphs, after random sequences of step-cost
// changes and moves of the start, its g-values and its path's cost are the true goal distances.
// A sliced search (any budget) ends exactly where an unsliced one does.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "ringlet/planning/dstar_lite.hpp"
#include "test_graph.hpp"

namespace ringlet::planning {
namespace {

using testing::TableGraph;

constexpr std::int64_t kUnsliced = std::int64_t{1} << 40;

std::unique_ptr<TableGraph> random_graph(std::mt19937& rng, double p_block) {
  std::uniform_int_distribution<int> size(2, 18);
  const int w = size(rng), h = size(rng);
  auto g = std::make_unique<TableGraph>(w, h, 1000);
  for (int v = 0; v < g->vertex_count(); ++v) g->randomise_vertex(v, rng, p_block);
  return g;
}

/// The cost of a path along the graph's step costs (infinite if two vertices are not adjacent).
Cost path_cost(const GridGraph& g, const std::vector<int>& path) {
  Cost c = 0;
  for (std::size_t i = 1; i < path.size(); ++i) {
    Cost step = kInfiniteCost;
    for (int k = 0; k < 8; ++k)
      if (g.neighbour(path[i - 1], k) == path[i]) step = g.step_cost(path[i - 1], k);
    c = add_cost(c, step);
  }
  return c;
}

/// Everything the search claims, checked against Dijkstra from scratch.
void expect_matches_dijkstra(DStarLite& d, const TableGraph& g, const char* where) {
  SCOPED_TRACE(where);
  const std::vector<Cost> truth = testing::distances_to(g, d.goal());
  const Cost best = truth[static_cast<std::size_t>(d.start())];
  if (best == kInfiniteCost) {
    EXPECT_EQ(d.status(), SearchStatus::kUnreachable);
    return;
  }
  ASSERT_EQ(d.status(), SearchStatus::kReady);
  EXPECT_EQ(d.plan_cost(), best);
  std::vector<int> path(static_cast<std::size_t>(g.vertex_count()));
  const int n = d.extract_path(path);
  ASSERT_GT(n, 0);
  path.resize(static_cast<std::size_t>(n));
  EXPECT_EQ(path.front(), d.start());
  EXPECT_EQ(path.back(), d.goal());
  EXPECT_EQ(path_cost(g, path), best);
  // Past the start (which may be left overconsistent: plan_cost() is its rhs), every vertex of
  // the path has its true distance as g.
  for (std::size_t i = 1; i < path.size(); ++i)
    EXPECT_EQ(d.g(path[i]), truth[static_cast<std::size_t>(path[i])]) << "path vertex " << path[i];
  // The search's invariant (Koenig & Likhachev): a locally consistent vertex whose key is not
  // above the queue's smallest key has its true distance as g.
  const SearchKey top = d.top_key();
  for (int v = 0; v < g.vertex_count(); ++v) {
    if (d.g(v) == d.rhs(v) && !(top < d.key(v))) {
      EXPECT_EQ(d.g(v), truth[static_cast<std::size_t>(v)]) << "vertex " << v;
    }
  }
}

/// Random edits: re-draws the step costs out of a few vertices (and the steps into them from one
/// neighbour), tells the planner, and sometimes moves the start along the plan or anywhere.
void random_edit(DStarLite& d, TableGraph& g, std::mt19937& rng, double p_block) {
  std::uniform_int_distribution<int> vertex(0, g.vertex_count() - 1);
  std::uniform_int_distribution<int> count(1, 4);
  for (int i = count(rng); i > 0; --i) {
    const int v = vertex(rng);
    g.randomise_vertex(v, rng, p_block);
    const int k = std::uniform_int_distribution<int>(0, 7)(rng);
    const int u = g.neighbour(v, k);
    if (u >= 0) g.set(u, opposite(k), TableGraph::random_cost(rng, opposite(k), g.min_step_cost(), p_block));
    d.vertex_changed(v);
  }
  const int move = std::uniform_int_distribution<int>(0, 3)(rng);
  if (move == 0 && d.status() == SearchStatus::kReady) {
    const int next = d.next_vertex();
    if (next >= 0) d.move_start(next);
  } else if (move == 1) {
    d.move_start(vertex(rng));
  }
}

TEST(DStarLite, InitialSearchEqualsDijkstraOnRandomGraphs) {
  std::mt19937 rng(11);
  DStarLite d;
  d.reserve(18 * 18);
  for (int trial = 0; trial < 300; ++trial) {
    const auto graph = random_graph(rng, trial % 3 == 0 ? 0.35 : 0.1);
    TableGraph& g = *graph;
    std::uniform_int_distribution<int> vertex(0, g.vertex_count() - 1);
    ASSERT_TRUE(d.begin(g, vertex(rng), vertex(rng)));
    const SearchStatus s = d.step(kUnsliced);
    EXPECT_NE(s, SearchStatus::kSearching);
    expect_matches_dijkstra(d, g, "initial");
  }
}

TEST(DStarLite, RepairsAfterRandomCostChangesAndMovesEqualDijkstraFromScratch) {
  std::mt19937 rng(2024);
  DStarLite d;
  d.reserve(18 * 18);
  for (int trial = 0; trial < 150; ++trial) {
    const double p_block = trial % 2 == 0 ? 0.3 : 0.08;
    const auto graph = random_graph(rng, p_block);
    TableGraph& g = *graph;
    std::uniform_int_distribution<int> vertex(0, g.vertex_count() - 1);
    ASSERT_TRUE(d.begin(g, vertex(rng), vertex(rng)));
    d.step(kUnsliced);
    for (int round = 0; round < 12; ++round) {
      random_edit(d, g, rng, p_block);
      d.step(kUnsliced);
      expect_matches_dijkstra(d, g, "after edits");
      if (::testing::Test::HasFailure()) return;
    }
  }
}

TEST(DStarLite, ChangesArrivingMidSearchStillEndCorrect) {
  std::mt19937 rng(7);
  DStarLite d;
  d.reserve(18 * 18);
  for (int trial = 0; trial < 100; ++trial) {
    const auto graph = random_graph(rng, 0.2);
    TableGraph& g = *graph;
    std::uniform_int_distribution<int> vertex(0, g.vertex_count() - 1);
    ASSERT_TRUE(d.begin(g, vertex(rng), vertex(rng)));
    for (int round = 0; round < 8; ++round) {
      d.step(3);  // a slice, then the world changes before the search is done
      random_edit(d, g, rng, 0.2);
    }
    d.step(kUnsliced);
    expect_matches_dijkstra(d, g, "mid-search edits");
    if (::testing::Test::HasFailure()) return;
  }
}

TEST(DStarLite, SlicedSearchEndsExactlyWhereTheUnslicedOneDoes) {
  for (std::int64_t budget : {1, 2, 3, 7, 64}) {
    std::mt19937 rng_a(99), rng_b(99);
    const auto graph_a = random_graph(rng_a, 0.15), graph_b = random_graph(rng_b, 0.15);
    TableGraph &ga = *graph_a, &gb = *graph_b;
    DStarLite a, b;
    a.reserve(ga.vertex_count());
    b.reserve(gb.vertex_count());
    std::uniform_int_distribution<int> vertex(0, ga.vertex_count() - 1);
    const int start = vertex(rng_a), goal = vertex(rng_a);
    ASSERT_EQ(vertex(rng_b), start);  // both generators stay in step
    ASSERT_EQ(vertex(rng_b), goal);
    ASSERT_TRUE(a.begin(ga, start, goal));
    ASSERT_TRUE(b.begin(gb, start, goal));
    int total_slices = 0;
    for (int round = 0; round < 10; ++round) {
      a.step(kUnsliced);
      int slices = 0;
      while (b.step(budget) == SearchStatus::kSearching) ++slices;
      EXPECT_EQ(a.status(), b.status());
      EXPECT_EQ(a.counters().expansions, b.counters().expansions);
      EXPECT_EQ(a.counters().pops, b.counters().pops);
      for (int v = 0; v < ga.vertex_count(); ++v) {
        ASSERT_EQ(a.g(v), b.g(v));
        ASSERT_EQ(a.rhs(v), b.rhs(v));
      }
      std::vector<int> pa(static_cast<std::size_t>(ga.vertex_count())), pb(pa.size());
      ASSERT_EQ(a.extract_path(pa), b.extract_path(pb));
      EXPECT_EQ(pa, pb);
      total_slices += slices;
      // The same edits to both.
      random_edit(a, ga, rng_a, 0.15);
      random_edit(b, gb, rng_b, 0.15);
    }
    if (budget == 1) {
      EXPECT_GT(total_slices, 10);  // the search really was cut into slices
    }
  }
}

TEST(DStarLite, AHalfDoneSearchOffersNoPlan) {
  TableGraph g(16, 16, 100);
  for (int v = 0; v < g.vertex_count(); ++v)
    for (int k = 0; k < 8; ++k) g.set(v, k, is_diagonal(k) ? 141 : 100);
  DStarLite d;
  d.reserve(g.vertex_count());
  ASSERT_TRUE(d.begin(g, g.vertex(0, 0), g.vertex(15, 15)));
  EXPECT_EQ(d.step(2), SearchStatus::kSearching);
  std::vector<int> path(256);
  EXPECT_EQ(d.extract_path(path), 0);
  EXPECT_EQ(d.next_vertex(), -1);
  EXPECT_EQ(d.plan_cost(), kInfiniteCost);
  EXPECT_EQ(d.step(kUnsliced), SearchStatus::kReady);
  EXPECT_EQ(d.plan_cost(), 15 * 141);
  EXPECT_EQ(d.next_vertex(), g.vertex(1, 1));
}

TEST(DStarLite, AWalledGoalIsUnreachableUntilTheWallOpens) {
  TableGraph g(9, 9, 100);
  const auto open_all = [&] {
    for (int v = 0; v < g.vertex_count(); ++v)
      for (int k = 0; k < 8; ++k) g.set(v, k, is_diagonal(k) ? 141 : 100);
  };
  open_all();
  // Column x = 4 is a wall: no step into it.
  for (int y = 0; y < 9; ++y)
    for (int k = 0; k < 8; ++k) {
      const int s = g.neighbour(g.vertex(4, y), k);
      if (s >= 0) g.set(s, opposite(k), kInfiniteCost);
    }
  DStarLite d;
  d.reserve(g.vertex_count());
  ASSERT_TRUE(d.begin(g, g.vertex(0, 4), g.vertex(8, 4)));
  EXPECT_EQ(d.step(kUnsliced), SearchStatus::kUnreachable);
  EXPECT_EQ(d.next_vertex(), -1);
  open_all();  // the wall is gone: tell the planner where it stood
  for (int y = 0; y < 9; ++y) d.vertex_changed(g.vertex(4, y));
  EXPECT_EQ(d.step(kUnsliced), SearchStatus::kReady);
  EXPECT_EQ(d.plan_cost(), 800);
}

TEST(DStarLite, RefusesGraphsAndVerticesThatDoNotFit) {
  TableGraph g(4, 4, 1);
  DStarLite d;
  d.reserve(8);
  EXPECT_FALSE(d.begin(g, 0, 1));  // 16 vertices, room for 8
  EXPECT_EQ(d.status(), SearchStatus::kIdle);
  d.reserve(16);
  EXPECT_FALSE(d.begin(g, -1, 3));
  EXPECT_FALSE(d.begin(g, 0, 16));
  EXPECT_TRUE(d.begin(g, 0, 0));
  EXPECT_EQ(d.step(1), SearchStatus::kReady);
  EXPECT_EQ(d.plan_cost(), 0.0);
  EXPECT_EQ(d.next_vertex(), 0);
}

}  // namespace
}  // namespace ringlet::planning
