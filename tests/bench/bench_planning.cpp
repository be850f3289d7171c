// The learned cost model's price (issue 14): a kNN prediction (k = 5) over n experiences through
// the k-d tree, against a brute-force scan of the same store ranked the same way (the baseline:
// the ratio says what the tree buys), and the off-cycle rebuild of the index. The planner's
// modelled cost charges PlannerTask::kCostPerPrediction per prediction; this is what backs it.
//
// Two feature distributions: "uniform" (every slot uniformly random in [0, 1], the k-d tree's
// worst case in 11 dimensions) and "sparse" (as on a real map: each region empty with
// probability 0.7, else a few occupied cells of 16), seeded so every run measures the same data.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include "ringlet/planning/experience.hpp"
#include "ringlet/planning/knn_regressor.hpp"

namespace {

using ringlet::planning::Features;
using ringlet::planning::KnnParams;
using ringlet::planning::KnnRegressor;
using ringlet::planning::kFeatureCount;

constexpr int kK = 5;
constexpr std::size_t kQueries = 1024;

Features draw(std::mt19937_64& rng, bool sparse) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Features x{};
  x[0] = u(rng) < 0.3 ? 1.0 : 0.0;  // diagonal
  for (int i = 1; i < kFeatureCount; ++i) {
    if (!sparse) {
      x[static_cast<std::size_t>(i)] = u(rng);
    } else if (u(rng) >= 0.7) {
      x[static_cast<std::size_t>(i)] = static_cast<double>(1 + static_cast<int>(u(rng) * 4.0)) / 16.0;
    }
  }
  return x;
}

struct Data {
  std::vector<Features> store, queries;
  std::vector<double> labels;
};

Data make_data(std::size_t n, bool sparse) {
  std::mt19937_64 rng(n * 2 + (sparse ? 1 : 0));
  Data d;
  std::uniform_real_distribution<double> speed(0.0, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    d.store.push_back(draw(rng, sparse));
    d.labels.push_back(speed(rng));
  }
  for (std::size_t i = 0; i < kQueries; ++i) d.queries.push_back(draw(rng, sparse));
  return d;
}

void fill(KnnRegressor& knn, const Data& d) {
  knn.reserve(d.store.size());
  for (std::size_t i = 0; i < d.store.size(); ++i) (void)knn.add(d.store[i], d.labels[i]);
  (void)knn.rebuild();
  (void)knn.publish();
}

/// The baseline: every stored experience's distance, the k nearest by (distance, index), their
/// mean label: what KnnRegressor::predict returns, without the tree.
double brute_force(const Data& d, const Features& q) {
  std::array<std::pair<double, std::size_t>, kK + 1> best{};
  std::size_t found = 0;
  for (std::size_t i = 0; i < d.store.size(); ++i) {
    double s = 0.0;
    for (std::size_t j = 0; j < q.size(); ++j) {
      const double dj = d.store[i][j] - q[j];
      s += dj * dj;
    }
    const std::pair<double, std::size_t> c{s, i};
    if (found == static_cast<std::size_t>(kK) && !(c < best[found - 1])) continue;
    std::size_t at = found < static_cast<std::size_t>(kK) ? found++ : found - 1;
    while (at > 0 && c < best[at - 1]) {
      best[at] = best[at - 1];
      --at;
    }
    best[at] = c;
  }
  double sum = 0.0;
  for (std::size_t i = 0; i < found; ++i) sum += d.labels[best[i].second];
  return sum / static_cast<double>(found);
}

void BM_KnnPredict(benchmark::State& state) {
  const Data d = make_data(static_cast<std::size_t>(state.range(0)), state.range(1) != 0);
  KnnRegressor knn(KnnParams{kK, false, 1.0});
  fill(knn, d);
  std::size_t q = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(knn.predict(d.queries[q]));
    q = (q + 1) % d.queries.size();
  }
  state.SetLabel(state.range(1) != 0 ? "sparse" : "uniform");
}

void BM_BruteForcePredict(benchmark::State& state) {
  const Data d = make_data(static_cast<std::size_t>(state.range(0)), state.range(1) != 0);
  std::size_t q = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(brute_force(d, d.queries[q]));
    q = (q + 1) % d.queries.size();
  }
  state.SetLabel(state.range(1) != 0 ? "sparse" : "uniform");
}

void BM_KnnRebuild(benchmark::State& state) {
  const Data d = make_data(static_cast<std::size_t>(state.range(0)), true);
  KnnRegressor knn(KnnParams{kK, false, 1.0});
  fill(knn, d);
  for (auto _ : state) {
    (void)knn.rebuild();
    (void)knn.publish();
  }
}

void sizes(benchmark::internal::Benchmark* b) {
  for (const std::int64_t n : {500, 5000}) {
    for (const std::int64_t sparse : {0, 1}) b->Args({n, sparse});
  }
}

}  // namespace

BENCHMARK(BM_KnnPredict)->Apply(sizes);
BENCHMARK(BM_BruteForcePredict)->Apply(sizes);
BENCHMARK(BM_KnnRebuild)->Arg(500)->Arg(5000)->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
