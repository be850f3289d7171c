// Ringlet overhead per machine with empty actions: what the runtime itself costs (hooks, guard
// dispatch, state bookkeeping), without and with the schedule's per-ringlet timing.
#include <benchmark/benchmark.h>

#include <array>
#include <memory>
#include <vector>
#include <span>
#include <string_view>

#include "ringlet/behaviour/llfsm/machine.hpp"
#include "ringlet/behaviour/llfsm/schedule.hpp"
#include "ringlet/hal/monotonic_clock.hpp"

namespace {

using ringlet::behaviour::llfsm::kNoState;
using ringlet::behaviour::llfsm::Machine;
using ringlet::behaviour::llfsm::Schedule;
using ringlet::behaviour::llfsm::StateIndex;

/// Two states, empty actions, one transition each: A -> B when `flip`, B -> A when `flip`.
class EmptyMachine final : public Machine {
 public:
  explicit EmptyMachine(std::string_view n, bool flip) noexcept : Machine(n, 0), flip_(flip) {}
  [[nodiscard]] std::size_t state_count() const noexcept override { return 2; }
  [[nodiscard]] std::string_view state_name(StateIndex s) const noexcept override { return kStates[s]; }

 protected:
  [[nodiscard]] StateIndex fire(StateIndex s) noexcept override {
    return flip_ ? static_cast<StateIndex>(1 - s) : kNoState;
  }

 private:
  static constexpr std::array<std::string_view, 2> kStates{"A", "B"};
  bool flip_;
};

/// A stopwatch that costs nothing: isolates the runtime from the clock reads.
class NullStopwatch final : public ringlet::hal::Stopwatch {
 public:
  [[nodiscard]] ringlet::hal::Nanos wall_now() const noexcept override { return {}; }
  [[nodiscard]] ringlet::hal::Nanos cpu_now() const noexcept override { return {}; }
};

// One ringlet: nothing fires, Internal runs.
void BM_RingletInternal(benchmark::State& state) {
  EmptyMachine m("M", false);
  std::int64_t t = 0;
  for (auto _ : state) m.ringlet(ringlet::hal::Nanos{++t});
  benchmark::DoNotOptimize(m.ringlets());
}
BENCHMARK(BM_RingletInternal);

// One ringlet with a state change every time (OnExit, OnEntry next time; no bus).
void BM_RingletTransition(benchmark::State& state) {
  EmptyMachine m("M", true);
  std::int64_t t = 0;
  for (auto _ : state) m.ringlet(ringlet::hal::Nanos{++t});
  benchmark::DoNotOptimize(m.ringlets());
}
BENCHMARK(BM_RingletTransition);

// A turn of N machines through the schedule; reported per machine-ringlet.
template <class Watch, ringlet::behaviour::llfsm::Timing kTiming>
void BM_Turn(benchmark::State& state) {
  Watch watch;
  Schedule sched(watch, nullptr, kTiming);
  std::vector<std::unique_ptr<EmptyMachine>> machines;
  const auto n = static_cast<std::size_t>(state.range(0));
  static constexpr std::array<std::string_view, 8> kNames{"M0", "M1", "M2", "M3", "M4", "M5", "M6", "M7"};
  for (std::size_t i = 0; i < n; ++i) machines.push_back(std::make_unique<EmptyMachine>(kNames[i], i % 2 == 0));
  for (auto& m : machines) sched.add(*m);
  sched.start();
  std::int64_t t = 0;
  for (auto _ : state) sched.run_turn(ringlet::hal::Nanos{++t});
  state.SetItemsProcessed(state.iterations() * state.range(0));
  state.counters["ns_per_ringlet"] = benchmark::Counter(
      static_cast<double>(state.iterations() * state.range(0)),
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
using ringlet::behaviour::llfsm::Timing;
using ringlet::hal::ThreadStopwatch;
BENCHMARK(BM_Turn<NullStopwatch, Timing::kOff>)->Arg(1)->Arg(8);
BENCHMARK(BM_Turn<ThreadStopwatch, Timing::kWall>)->Arg(1)->Arg(8);
BENCHMARK(BM_Turn<ThreadStopwatch, Timing::kWallAndCpu>)->Arg(8);

}  // namespace

BENCHMARK_MAIN();
