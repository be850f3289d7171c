// kNN regression on nanoflann against a brute-force search (rank by distance, then insertion
// index), on random data with many exact ties; the double-buffered index: what is added becomes
// visible only at publish(), and the cycle side never waits for a rebuild.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <thread>

#include "ringlet/hal/splitmix64.hpp"
#include "ringlet/planning/knn_regressor.hpp"

namespace ringlet::planning {
namespace {

/// Features quantised to a few levels (like occupied fractions of small regions): many points
/// share a distance to a query, and many are duplicates.
Features random_features(hal::SplitMix64& rng, int levels) {
  Features x{};
  for (double& v : x) v = static_cast<double>(rng.below(static_cast<std::uint64_t>(levels))) / (levels - 1);
  x[kDiagonal] = static_cast<double>(rng.below(2));
  return x;
}

std::vector<Experience> random_data(std::size_t n, int levels, std::uint64_t seed) {
  hal::SplitMix64 rng(seed);
  std::vector<Experience> out(n);
  for (Experience& e : out) {
    e.features = random_features(rng, levels);
    e.achieved_speed = static_cast<double>(rng.below(2000)) / 1000.0;
  }
  return out;
}

/// The reference: sort every point by (squared distance, index), average the first k.
double brute_force(const std::vector<Experience>& data, const Features& q, int k, bool weighted,
                   std::vector<Neighbour>& ranked) {
  ranked.clear();
  for (std::size_t i = 0; i < data.size(); ++i)
    ranked.push_back({static_cast<std::uint32_t>(i), squared_distance(q, data[i].features)});
  std::sort(ranked.begin(), ranked.end(), [](const Neighbour& a, const Neighbour& b) {
    return a.squared_distance != b.squared_distance ? a.squared_distance < b.squared_distance : a.index < b.index;
  });
  ranked.resize(std::min(ranked.size(), static_cast<std::size_t>(k)));
  double sum = 0.0, weights = 0.0;
  for (const Neighbour& n : ranked) {
    const double w = weighted ? 1.0 / (std::sqrt(n.squared_distance) + KnnRegressor::kWeightEpsilon) : 1.0;
    sum += w * data[n.index].achieved_speed;
    weights += w;
  }
  return sum / weights;
}

TEST(KnnRegressor, AgreesWithBruteForceBitForBit) {
  for (const int levels : {3, 5, 65}) {  // 3: almost everything ties; 65: the fractions of 8×8 regions
    const auto data = random_data(2000, levels, 100 + static_cast<std::uint64_t>(levels));
    for (const int k : {1, 2, 5, 15, 50}) {
      for (const bool weighted : {false, true}) {
        KnnRegressor knn({.k = k, .distance_weighted = weighted});
        knn.fit(data);
        ASSERT_EQ(knn.visible(), data.size());
        hal::SplitMix64 rng(7);
        std::vector<Neighbour> expected;
        std::array<Neighbour, KnnRegressor::kMaxK> got{};
        for (int q = 0; q < 200; ++q) {
          // Half the queries are stored points (distance-0 ties), half fresh.
          const Features x = q % 2 == 0 ? data[rng.below(data.size())].features : random_features(rng, levels);
          const double want = brute_force(data, x, k, weighted, expected);
          ASSERT_EQ(knn.predict(x), want) << "levels " << levels << ", k " << k << ", weighted " << weighted << ", query " << q;
          ASSERT_EQ(knn.neighbours(x, got), expected.size());
          for (std::size_t i = 0; i < expected.size(); ++i) {
            ASSERT_EQ(got[i].index, expected[i].index) << "k " << k << ", query " << q << ", rank " << i;
            ASSERT_EQ(got[i].squared_distance, expected[i].squared_distance);
          }
        }
      }
    }
  }
}

TEST(KnnRegressor, FewerPointsThanKUsesThemAllAndNoneGivesThePrior) {
  KnnRegressor knn({.k = 5, .prior_speed = 1.5});
  knn.reserve(4);
  EXPECT_EQ(knn.predict(Features{}), 1.5);
  Features a{}, b{};
  b[kTo] = 1.0;
  ASSERT_TRUE(knn.add(a, 1.0));
  ASSERT_TRUE(knn.add(b, 2.0));
  ASSERT_TRUE(knn.rebuild());
  ASSERT_TRUE(knn.publish());
  EXPECT_EQ(knn.predict(a), 1.5);  // both neighbours, unweighted
}

TEST(KnnRegressor, AddedExperiencesBecomeVisibleOnlyWhenPublished) {
  KnnRegressor knn({.k = 1, .prior_speed = 0.25});
  knn.reserve(3);
  Features x{};
  x[kAhead] = 0.5;
  EXPECT_FALSE(knn.publish());  // nothing rebuilt
  ASSERT_TRUE(knn.add(x, 1.0));
  EXPECT_EQ(knn.stored(), 1U);
  EXPECT_EQ(knn.visible(), 0U);
  EXPECT_EQ(knn.predict(x), 0.25);
  ASSERT_TRUE(knn.rebuild());
  EXPECT_FALSE(knn.rebuild());       // its result waits to be published
  EXPECT_EQ(knn.predict(x), 0.25);   // still the old (empty) index
  ASSERT_TRUE(knn.add(x, 3.0));      // stored after the rebuild began: not in it
  ASSERT_TRUE(knn.publish());
  EXPECT_FALSE(knn.publish());
  EXPECT_EQ(knn.visible(), 1U);
  EXPECT_EQ(knn.predict(x), 1.0);
  ASSERT_TRUE(knn.rebuild());
  ASSERT_TRUE(knn.publish());
  EXPECT_EQ(knn.visible(), 2U);
  EXPECT_EQ(knn.predict(x), 1.0);    // a tie: the earlier experience wins
  ASSERT_TRUE(knn.add(x, 5.0));
  EXPECT_FALSE(knn.add(x, 6.0));     // full: refused, nothing stored
  EXPECT_EQ(knn.stored(), 3U);
}

TEST(KnnRegressor, RebuildsOnAnotherThreadWhileTheCyclePredictsAndAdds) {
  const auto data = random_data(6000, 65, 3);
  KnnRegressor knn({.k = 5});
  knn.reserve(data.size());
  for (std::size_t i = 0; i < 1000; ++i) ASSERT_TRUE(knn.add(data[i].features, data[i].achieved_speed));
  ASSERT_TRUE(knn.rebuild());
  ASSERT_TRUE(knn.publish());
  std::size_t next = 1000, publishes = 0;
  while (next < data.size()) {
    std::thread service([&] { (void)knn.rebuild(); });
    // The cycle goes on: predicts from the published index and stores new experiences.
    const std::size_t visible = knn.visible();
    for (int i = 0; i < 100 && next < data.size(); ++i, ++next) {
      ASSERT_TRUE(knn.add(data[next].features, data[next].achieved_speed));
      const double p = knn.predict(data[next].features);
      ASSERT_TRUE(p >= 0.0 && p <= 2.0);
      ASSERT_EQ(knn.visible(), visible);
    }
    service.join();
    publishes += knn.publish() ? 1U : 0U;
  }
  EXPECT_GE(publishes, 40U);
  ASSERT_TRUE(knn.rebuild());
  ASSERT_TRUE(knn.publish());
  // The same state as a model fitted in one go.
  KnnRegressor whole({.k = 5});
  whole.fit(data);
  hal::SplitMix64 rng(9);
  for (int q = 0; q < 100; ++q) {
    const Features x = random_features(rng, 65);
    EXPECT_EQ(knn.predict(x), whole.predict(x));
  }
}

TEST(KnnParams, ValidateNamesTheField) {
  EXPECT_EQ(KnnParams{}.validate(), "");
  EXPECT_NE(KnnParams{.k = 0}.validate().find("k must be"), std::string::npos);
  EXPECT_NE(KnnParams{.k = 65}.validate().find("k must be"), std::string::npos);
  EXPECT_NE(KnnParams{.prior_speed = -1.0}.validate().find("prior_speed"), std::string::npos);
}

}  // namespace
}  // namespace ringlet::planning
