// ringlet: the one firmware binary, for the simulated and (later) the real robot.
//   ringlet --config firmware/config/spl_field.toml --report out/report.json --svg out/spl_field.svg
// Exit codes: 0 mission complete, 2 bad input (flags, config, world), 3 mission incomplete,
// 4 safe state forced (failsafe/watchdog), 130 interrupted (SIGINT/SIGTERM), 1 internal error.
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>

#include <CLI/CLI.hpp>

#include "ringlet/executive/report.hpp"
#include "ringlet/firmware/config.hpp"
#include "ringlet/firmware/mission_report.hpp"
#include "ringlet/firmware/mission_runner.hpp"
#include "ringlet/firmware/schedule_report.hpp"
#include "ringlet/firmware/stack.hpp"
#include "ringlet/sim/world.hpp"

namespace {

std::atomic<bool> g_interrupt{false};
std::atomic<bool>* g_executive_stop = nullptr;

extern "C" void on_signal(int /*signo*/) {
  // Only lock-free atomic stores: async-signal-safe.
  g_interrupt.store(true);
  if (g_executive_stop != nullptr) g_executive_stop->store(true);
}

void install_signal_handlers() {
  struct sigaction sa{};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

void print_table(const ringlet::firmware::FirmwareConfig& cfg) {
  const double base_hz = 1e9 / static_cast<double>(cfg.executive.period.count());
  std::printf("task table (base %.1f Hz, period %.1f ms, %s clock):\n", base_hz,
              static_cast<double>(cfg.executive.period.count()) / 1e6,
              cfg.clock == ringlet::firmware::ClockMode::kLockstep ? "lockstep virtual" : "real-time");
  std::printf("  %-3s %-12s %8s %6s %6s %10s  %s\n", "#", "task", "rate", "every", "phase", "budget", "on overrun");
  for (std::size_t i = 0; i < cfg.tasks.size(); ++i) {
    const auto& t = cfg.tasks[i];
    std::printf("  %-3zu %-12s %6.1fHz %6d %6d %8.0fus  %s\n", i, t.name.c_str(), base_hz / t.every, t.every, t.phase,
                static_cast<double>(t.budget.count()) / 1e3, std::string(ringlet::executive::to_string(t.policy)).c_str());
  }
}

void write_json(const std::filesystem::path& path, const nlohmann::json& j) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path);
  out << j.dump(2) << '\n';
  if (!out) throw std::runtime_error(path.string() + ": cannot write report");
}

}  // namespace

int main(int argc, char** argv) {
  using namespace ringlet;
  CLI::App app{"Ringlet firmware: the cyclic executive driving the simulated (or real) robot"};
  std::filesystem::path config_path = "firmware/config/spl_field.toml";
  std::optional<double> duration;
  bool realtime = false;
  bool lockstep = false;
  std::optional<std::uint64_t> seed;
  std::filesystem::path report_path;
  std::filesystem::path svg_path;
  bool check_only = false;
  app.add_option("-c,--config", config_path, "configuration file (TOML)")->capture_default_str();
  app.add_option("-d,--duration", duration, "run at most this many seconds (default: mission.timeout_s)")
      ->check(CLI::PositiveNumber);
  auto* rt = app.add_flag("--realtime", realtime, "pace the cycle by the real clock (clock_nanosleep)");
  app.add_flag("--lockstep", lockstep, "run on the virtual clock as fast as possible (simulation)")->excludes(rt);
  app.add_option("--seed", seed, "override sim.seed");
  app.add_option("-r,--report", report_path, "write the mission summary and timing report as JSON");
  app.add_option("--svg", svg_path, "write a picture of the world and the trajectory (sim backend)");
  app.add_flag("--check", check_only, "validate the configuration and world, print the task table, and exit");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }

  try {
    auto cfg = firmware::load_config(config_path);
    if (realtime) cfg.clock = firmware::ClockMode::kRealtime;
    if (lockstep) cfg.clock = firmware::ClockMode::kLockstep;
    if (seed) cfg.sim.seed = *seed;
    if (duration) cfg.timeout_s = *duration;

    firmware::FirmwareStack stack(cfg);
    print_table(cfg);
    if (check_only) {
      std::printf("configuration OK: %s, world %s\n", config_path.c_str(), cfg.world.c_str());
      return 0;
    }

    g_executive_stop = &stack.executive().stop_flag();
    install_signal_handlers();
    const auto outcome = firmware::run_mission(stack, cfg.timeout_s, g_interrupt, std::cerr);
    g_executive_stop = nullptr;

    const bool forced = stack.executive().failsafe_triggered() || outcome.watchdog_fired;
    const auto summary = firmware::summarize(stack, outcome, forced);
    std::cout << '\n';
    firmware::print_summary(std::cout, summary);
    std::cout << '\n';
    executive::print_timing_table(std::cout, stack.executive());
    std::cout << '\n';
    firmware::print_schedule_timing(std::cout, stack.schedule());
    if (!report_path.empty()) {
      write_json(report_path, {{"mission", firmware::summary_json(summary)},
                               {"timing", executive::timing_json(stack.executive())},
                               {"schedule", firmware::schedule_timing_json(stack.schedule())}});
      std::cout << "report:  " << report_path.string() << '\n';
    }
    if (!svg_path.empty()) {
      if (svg_path.has_parent_path()) std::filesystem::create_directories(svg_path.parent_path());
      if (firmware::write_picture(svg_path, stack, summary)) {
        std::cout << "picture: " << svg_path.string() << '\n';
      } else {
        std::cerr << "ringlet: no picture: the " << cfg.backend << " backend has no world to draw\n";
      }
    }
    return firmware::exit_code(summary);
  } catch (const firmware::ConfigError& e) {
    std::cerr << "ringlet: " << e.what() << '\n';
    return 2;
  } catch (const sim::WorldError& e) {
    std::cerr << "ringlet: " << e.what() << '\n';
    return 2;
  } catch (const executive::TableError& e) {
    std::cerr << "ringlet: " << config_path.string() << ": " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "ringlet: error: " << e.what() << '\n';
    return 1;
  }
}
