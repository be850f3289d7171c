// ringlet-jitter: how late does the cycle wake up on this machine, and what does the executive
// add? In one run it measures the wake-up latency (actual wake - scheduled deadline, on
// CLOCK_MONOTONIC) of
//   (a) a bare clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME) loop, and
//   (b) the Executive on hal::MonotonicClock with one trivial task (its wake_latency histogram),
// one after the other, each for --duration seconds, and prints p50/p99/p99.9/max of both.
//
// Exit codes: 0 ok, 1 the JSON file could not be written, 2 bad flags.
#include <time.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "ringlet/executive/executive.hpp"
#include "ringlet/executive/histogram.hpp"
#include "ringlet/executive/realtime.hpp"
#include "ringlet/hal/null_actuators.hpp"
#include "ringlet/hal/monotonic_clock.hpp"

namespace {

using ringlet::executive::DurationHistogram;
using ringlet::hal::Nanos;

constexpr int kExitOk = 0;
constexpr int kExitIo = 1;
constexpr int kExitUsage = 2;

struct Options {
  std::int64_t period_us = 1000;
  double duration_s = 2.0;
  int fifo_priority = 0;
  int cpu = -1;
  bool lock_memory = false;
  std::string json_path;
};

struct PhaseResult {
  DurationHistogram latency;
  std::uint64_t wakeups = 0;
  std::uint64_t overruns = 0;        // task budget overruns (executive only)
  std::uint64_t frame_overruns = 0;  // frames that ended after the next was due
  std::uint64_t slips = 0;           // deadlines given up to keep the phase
};

Nanos monotonic_now() noexcept {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return Nanos{static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec};
}

void sleep_until(Nanos deadline) noexcept {
  timespec ts{};
  ts.tv_sec = static_cast<time_t>(deadline.count() / 1'000'000'000);
  ts.tv_nsec = static_cast<long>(deadline.count() % 1'000'000'000);
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {
  }
}

// (a) The bare loop, with the executive's rule for a late wake-up (skip to the next deadline
// still in the future, never burst) so that both loops are judged the same way.
PhaseResult measure_bare(Nanos period, std::uint64_t frames) {
  PhaseResult r;
  const Nanos start = monotonic_now();
  std::uint64_t k = 0;
  while (k < frames) {
    const Nanos due = start + static_cast<std::int64_t>(k) * period;
    sleep_until(due);
    const Nanos woke = monotonic_now();
    r.latency.record(woke - due);
    ++r.wakeups;
    std::uint64_t next = k + 1;
    if (woke > due + period) {
      next = static_cast<std::uint64_t>(((woke - start).count() + period.count() - 1) / period.count());
      ++r.frame_overruns;
      r.slips += next - (k + 1);
    }
    k = next;
  }
  return r;
}

class TrivialTask final : public ringlet::executive::Task {
 public:
  void run(const ringlet::executive::TaskContext& ctx) noexcept override { sum_ += ctx.frame; }
  [[nodiscard]] std::uint64_t sum() const noexcept { return sum_; }

 private:
  std::uint64_t sum_ = 0;
};

// (b) The executive loop on the real clock.
PhaseResult measure_executive(Nanos period, std::uint64_t frames) {
  ringlet::hal::MonotonicClock clock;
  ringlet::hal::ThreadStopwatch stopwatch;
  ringlet::hal::NullActuators actuators;
  TrivialTask task;
  ringlet::executive::ExecutiveConfig config;
  config.period = period;
  ringlet::executive::TaskSpec spec;
  spec.name = "trivial";
  spec.budget = period / 2 > Nanos{0} ? period / 2 : period;
  ringlet::executive::Executive exec(config, {ringlet::executive::TaskBinding{spec, &task}}, clock, stopwatch,
                                     actuators);
  exec.run(frames);

  PhaseResult r;
  const auto& f = exec.frame_stats();
  r.latency = f.wake_latency;
  r.wakeups = f.frames;
  r.overruns = exec.task_stats()[0].overruns;
  r.frame_overruns = f.frame_overruns;
  r.slips = f.slips;
  return r;
}

double us(Nanos d) { return static_cast<double>(d.count()) / 1000.0; }

std::string ratio_text(Nanos num, Nanos den) {
  if (den <= Nanos{0}) return "n/a";
  char buf[32];
  std::snprintf(buf, sizeof buf, "x%.2f", static_cast<double>(num.count()) / static_cast<double>(den.count()));
  return buf;
}

double ratio_value(Nanos num, Nanos den) {
  return den > Nanos{0} ? static_cast<double>(num.count()) / static_cast<double>(den.count()) : 0.0;
}

nlohmann::json phase_json(const PhaseResult& r) {
  return {{"wakeups", r.wakeups},
          {"p50_us", us(r.latency.percentile(0.50))},
          {"p99_us", us(r.latency.percentile(0.99))},
          {"p999_us", us(r.latency.percentile(0.999))},
          {"max_us", us(r.latency.max())},
          {"mean_us", us(r.latency.mean())},
          {"overruns", r.overruns},
          {"frame_overruns", r.frame_overruns},
          {"slips", r.slips}};
}

void print_row(const char* name, const PhaseResult& r) {
  std::printf("%-24s %9llu %9.1f %9.1f %9.1f %9.1f %9llu %7llu\n", name, static_cast<unsigned long long>(r.wakeups),
              us(r.latency.percentile(0.50)), us(r.latency.percentile(0.99)), us(r.latency.percentile(0.999)),
              us(r.latency.max()), static_cast<unsigned long long>(r.frame_overruns),
              static_cast<unsigned long long>(r.slips));
}

}  // namespace

int main(int argc, char** argv) {
  Options opt;
  CLI::App app{
      "ringlet-jitter: wake-up latency of a bare clock_nanosleep loop versus the Ringlet executive loop, "
      "measured one after the other on CLOCK_MONOTONIC."};
  app.add_option("--period-us", opt.period_us, "Cycle period in microseconds (> 0)")->capture_default_str();
  app.add_option("--duration", opt.duration_s, "Seconds to measure each loop (> 0)")->capture_default_str();
  app.add_option("--fifo-priority", opt.fifo_priority, "SCHED_FIFO priority 1..99; 0 keeps the normal scheduler")
      ->capture_default_str();
  app.add_option("--cpu", opt.cpu, "Pin the measuring thread to this CPU; -1 leaves affinity alone")
      ->capture_default_str();
  app.add_flag("--lock-memory", opt.lock_memory, "mlockall(MCL_CURRENT | MCL_FUTURE) before measuring");
  app.add_option("--json", opt.json_path, "Also write the results as JSON to this file");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);  // prints help, or the error with a hint
    return rc == 0 ? kExitOk : kExitUsage;
  }

  std::vector<std::string> errors;
  if (opt.period_us <= 0) errors.push_back("--period-us must be > 0 (got " + std::to_string(opt.period_us) + ")");
  if (opt.period_us > 10'000'000) errors.push_back("--period-us must be at most 10000000 (10 s)");
  if (!std::isfinite(opt.duration_s) || opt.duration_s <= 0.0) {
    std::ostringstream got;
    got << opt.duration_s;
    errors.push_back("--duration must be a number of seconds > 0 (got " + got.str() + ")");
  } else if (opt.duration_s > 86'400.0) {
    errors.push_back("--duration must be at most 86400 s");
  }
  if (opt.cpu < -1) errors.push_back("--cpu must be a CPU number or -1 (got " + std::to_string(opt.cpu) + ")");
  if (!errors.empty()) {
    for (const auto& e : errors) std::cerr << "ringlet-jitter: " << e << "\n";
    std::cerr << "Run with --help for more information.\n";
    return kExitUsage;
  }

  std::ofstream json_out;
  if (!opt.json_path.empty()) {
    json_out.open(opt.json_path);
    if (!json_out) {
      std::cerr << "ringlet-jitter: cannot write " << opt.json_path << "\n";
      return kExitIo;
    }
  }

  const Nanos period = std::chrono::microseconds(opt.period_us);
  const auto frames = std::max<std::uint64_t>(
      1, static_cast<std::uint64_t>(std::llround(opt.duration_s * 1e9 / static_cast<double>(period.count()))));

  ringlet::executive::RealtimeSettings rt;
  rt.fifo_priority = opt.fifo_priority;
  rt.cpu = opt.cpu;
  rt.lock_memory = opt.lock_memory;
  const auto warnings = ringlet::executive::apply_realtime_settings(rt);

  std::printf("ringlet-jitter: period %lld us, %.3g s per loop (%llu deadlines each), SCHED_FIFO %s, cpu %s%s\n",
              static_cast<long long>(opt.period_us), opt.duration_s, static_cast<unsigned long long>(frames),
              opt.fifo_priority != 0 ? std::to_string(opt.fifo_priority).c_str() : "off",
              opt.cpu >= 0 ? std::to_string(opt.cpu).c_str() : "any", opt.lock_memory ? ", memory locked" : "");
  for (const auto& w : warnings) std::printf("warning: %s\n", w.c_str());
  std::fflush(stdout);

  std::printf("[1/2] bare clock_nanosleep loop ... ");
  std::fflush(stdout);
  const PhaseResult bare = measure_bare(period, frames);
  std::printf("done: %llu wake-ups\n", static_cast<unsigned long long>(bare.wakeups));
  std::printf("[2/2] executive loop, 1 trivial task ... ");
  std::fflush(stdout);
  const PhaseResult exec = measure_executive(period, frames);
  std::printf("done: %llu frames\n", static_cast<unsigned long long>(exec.wakeups));

  std::printf("\nwake-up latency (us)      wake-ups       p50       p99     p99.9       max  late>per   slips\n");
  print_row("bare clock_nanosleep", bare);
  print_row("executive", exec);
  const Nanos bare50 = bare.latency.percentile(0.50);
  const Nanos bare99 = bare.latency.percentile(0.99);
  const Nanos exec50 = exec.latency.percentile(0.50);
  const Nanos exec99 = exec.latency.percentile(0.99);
  std::printf("ratio executive/bare     p50 %s  p99 %s\n", ratio_text(exec50, bare50).c_str(),
              ratio_text(exec99, bare99).c_str());
  std::printf("executive: task overruns %llu, frame overruns %llu, slips %llu\n",
              static_cast<unsigned long long>(exec.overruns), static_cast<unsigned long long>(exec.frame_overruns),
              static_cast<unsigned long long>(exec.slips));

  if (json_out.is_open()) {
    const nlohmann::json j = {{"period_us", opt.period_us},
                              {"duration_s", opt.duration_s},
                              {"fifo_priority", opt.fifo_priority},
                              {"cpu", opt.cpu},
                              {"lock_memory", opt.lock_memory},
                              {"realtime_warnings", warnings},
                              {"bare", phase_json(bare)},
                              {"executive", phase_json(exec)},
                              {"ratio_executive_over_bare",
                               {{"p50", ratio_value(exec50, bare50)}, {"p99", ratio_value(exec99, bare99)}}}};
    json_out << j.dump(2) << "\n";
    json_out.close();
    if (!json_out) {
      std::cerr << "ringlet-jitter: error writing " << opt.json_path << "\n";
      return kExitIo;
    }
    std::printf("JSON written to %s\n", opt.json_path.c_str());
  }
  return kExitOk;
}
