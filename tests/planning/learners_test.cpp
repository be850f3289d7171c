// The learners without a k-d tree: the baseline over features is BinaryCostModel's rule, the mean
// learner is the training mean, linear regression recovers a linear law exactly.
#include <gtest/gtest.h>

#include "ringlet/hal/splitmix64.hpp"
#include "ringlet/planning/linear_regression.hpp"
#include "ringlet/planning/region_graph.hpp"

namespace ringlet::planning {
namespace {

TEST(BaselineLearner, AgreesWithBinaryCostModelOnEveryTransition) {
  MapConfig c;
  c.resolution = 0.25;
  c.width_cells = 40;
  c.height_cells = 40;
  c.region_cells = 5;  // 25 cells a region: fractions that are not dyadic
  OccupancyGrid map(c);
  hal::SplitMix64 rng(5);
  for (int i = 0; i < 400; ++i) map.mark_cell(static_cast<int>(rng.below(40)), static_cast<int>(rng.below(40)));
  const BinaryCostModel::Params p{.max_occupied = 6, .top_speed = 1.75};
  const BinaryCostModel model(p);
  RegionGraph graph(map, model);
  graph.set_robot_region(graph.vertex(3, 3));
  const BaselineLearner baseline(p, 25);
  int blocked = 0, open = 0;
  for (int v = 0; v < graph.vertex_count(); ++v)
    for (int k = 0; k < kGridDirections; ++k) {
      const RegionTransition t = graph.transition(v, k);
      if (t.to < 0) continue;
      const double want = model.expected_speed(t);
      EXPECT_EQ(baseline.predict(transition_features(t)), want) << "region " << v << ", direction " << k;
      (want == 0.0 ? blocked : open) += 1;
    }
  EXPECT_GT(blocked, 50);  // both outcomes are exercised
  EXPECT_GT(open, 50);
}

std::vector<Experience> linear_data(std::size_t n, std::uint64_t seed) {
  hal::SplitMix64 rng(seed);
  std::vector<Experience> out(n);
  for (Experience& e : out) {
    for (double& f : e.features) f = static_cast<double>(rng.below(65)) / 64.0;
    e.features[kDiagonal] = static_cast<double>(rng.below(2));
    e.achieved_speed = 1.8 - 0.9 * e.features[kTo] - 0.4 * e.features[kAhead] + 0.25 * e.features[kDiagonal] -
                       0.1 * e.features[kCornerLeft];
  }
  return out;
}

TEST(LinearRegression, RecoversALinearLaw) {
  LinearRegression lr;
  lr.fit(linear_data(300, 1));
  const auto& w = lr.coefficients();
  EXPECT_NEAR(w[kFeatureCount], 1.8, 1e-12);
  EXPECT_NEAR(w[kTo], -0.9, 1e-12);
  EXPECT_NEAR(w[kAhead], -0.4, 1e-12);
  EXPECT_NEAR(w[kDiagonal], 0.25, 1e-12);
  EXPECT_NEAR(w[kCornerLeft], -0.1, 1e-12);
  EXPECT_NEAR(w[kFrom], 0.0, 1e-12);
  for (const Experience& e : linear_data(50, 2)) EXPECT_NEAR(lr.predict(e.features), e.achieved_speed, 1e-12);
}

TEST(LinearRegression, AConstantFeatureStillGivesAFit) {
  auto data = linear_data(100, 3);
  for (Experience& e : data) {  // straight moves only: a column of zeros, and the law without it
    e.achieved_speed -= 0.25 * e.features[kDiagonal];
    e.features[kDiagonal] = 0.0;
  }
  LinearRegression lr;
  lr.fit(data);
  for (const Experience& e : data) EXPECT_NEAR(lr.predict(e.features), e.achieved_speed, 1e-12);
}

TEST(MeanLearner, PredictsTheTrainingMean) {
  std::vector<Experience> data(4);
  for (std::size_t i = 0; i < data.size(); ++i) data[i].achieved_speed = static_cast<double>(i);
  MeanLearner m;
  m.fit(data);
  EXPECT_EQ(m.predict(Features{}), 1.5);
}

}  // namespace
}  // namespace ringlet::planning
