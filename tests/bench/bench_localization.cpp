// The particle filter's price (issue 17), against the localization task's cost model
// (firmware/app/include/ringlet/firmware/tasks/localization_task.hpp): kModelledNsPerParticleMoved
// and kModelledNsPerTerm are this host's time per particle moved and per observation term
// evaluated, times the board slowdown of 4. Each benchmark prints the measured host time per unit
// beside the model's host share (the constant ÷ 4) and their ratio, so that a drift of the model
// shows at once (model_over_host below 1: the model undercharges this host).
//
//   BM_Predict/N    odometry for N particles (the task's every-frame work)
//   BM_Correct/N    a correction with N particles on synthetic views of the SPL field: weighing,
//                   resampling, injection and the estimate (the task's work when vision posts)
//   BM_CorrectLost  the same from a uniform cloud, with candidates injected every update
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "ringlet/firmware/tasks/localization_task.hpp"
#include "ringlet/localization/field_model.hpp"
#include "ringlet/localization/motion_model.hpp"
#include "ringlet/localization/particle_filter.hpp"
#include "ringlet/localization/synthetic_view.hpp"

namespace {

using ringlet::firmware::LocalizationTask;
using ringlet::hal::Pose2;
using ringlet::hal::SplitMix64;
using namespace ringlet::localization;

constexpr double kBoardSlowdown = 4.0;

// 64 views round the SPL field's mission loop, the head sweeping, with vision's dropped and false
// lines: what a correction sees in a match.
std::vector<Observations> mission_views(const FieldModel& field) {
  std::vector<Observations> views;
  SplitMix64 rng(11);
  ViewParams view{.drop = 0.15, .false_line = 0.2};
  for (int i = 0; i < 64; ++i) {
    const double a = 2.0 * std::numbers::pi * i / 64.0;
    const Pose2 truth{3.0 * std::cos(a), 2.2 * std::sin(a), a + std::numbers::pi};
    view.head_yaw = std::sin(0.7 * i);
    views.push_back(synthetic_view(field, truth, view, rng));
  }
  return views;
}

FilterParams params(std::int64_t particles) {
  FilterParams p;
  p.particles = static_cast<int>(particles);
  p.seed = 17;
  return p;
}

void report(benchmark::State& state, double units, double model_ns_per_unit, const char* unit) {
  // Seconds per unit (rate counter, inverted), the model's host share, and the ratio.
  state.counters[std::string("host_s_per_") + unit] =
      benchmark::Counter(units, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters[std::string(unit) + "_per_iter"] = benchmark::Counter(units, benchmark::Counter::kAvgIterations);
  state.counters[std::string("model_host_ns_per_") + unit] = model_ns_per_unit / kBoardSlowdown;
}

void BM_Predict(benchmark::State& state) {
  const FieldModel field;
  ParticleFilter filter(field, params(state.range(0)));
  filter.reset_to({-1.5, -2.2, std::numbers::pi / 2}, 0.1, 0.05);
  const OdometryDelta step{0.02, 0.001, 0.01};  // one 100 Hz frame at 2 m/s, turning
  const std::uint64_t before = filter.particles_moved();
  for (auto _ : state) {
    filter.predict(step);
    benchmark::DoNotOptimize(filter.particles().data());
  }
  report(state, static_cast<double>(filter.particles_moved() - before), LocalizationTask::kModelledNsPerParticleMoved,
         "particle");
}
BENCHMARK(BM_Predict)->Arg(100)->Arg(300)->Arg(1000)->Unit(benchmark::kMicrosecond);

void correct_loop(benchmark::State& state, bool lost) {
  const FieldModel field;
  const std::vector<Observations> views = mission_views(field);
  ParticleFilter filter(field, params(state.range(0)));
  const std::uint64_t before = filter.terms_evaluated();
  std::size_t i = 0;
  for (auto _ : state) {
    if (lost) {
      state.PauseTiming();
      filter.reset_uniform();
      state.ResumeTiming();
    }
    filter.correct(views[i++ % views.size()]);
    benchmark::DoNotOptimize(filter.estimate());
  }
  report(state, static_cast<double>(filter.terms_evaluated() - before), LocalizationTask::kModelledNsPerTerm, "term");
}

void BM_Correct(benchmark::State& state) { correct_loop(state, false); }
BENCHMARK(BM_Correct)->Arg(100)->Arg(300)->Arg(1000)->Unit(benchmark::kMicrosecond);

void BM_CorrectLost(benchmark::State& state) { correct_loop(state, true); }
BENCHMARK(BM_CorrectLost)->Arg(300)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
