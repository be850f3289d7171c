// ringlet: the one firmware binary, for the simulated and (later) the real robot.
//   ringlet --config firmware/config/spl_field.toml --report out/report.json --svg out/spl_field.svg
// Exit codes: 0 mission complete, 1 internal or output error, 2 bad input (flags, config, world,
// output paths), 3 mission incomplete, 4 safe state forced (failsafe/watchdog), 128 + N ended by
// signal N (SIGINT 130, SIGTERM 143, SIGHUP 129, SIGQUIT 131) after the safe state and the report.
#include <atomic>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>

#include <CLI/CLI.hpp>

#include "ringlet/executive/report.hpp"
#include "ringlet/firmware/command_line.hpp"
#include "ringlet/firmware/config.hpp"
#include "ringlet/firmware/mission_report.hpp"
#include "ringlet/firmware/mission_runner.hpp"
#include "ringlet/firmware/output_file.hpp"
#include "ringlet/firmware/schedule_report.hpp"
#include "ringlet/firmware/stack.hpp"
#ifdef RINGLET_HAVE_OPENCV_CAMERA
#include "ringlet/firmware/opencv_camera.hpp"
#endif

namespace {

std::atomic<bool> g_interrupt{false};
std::atomic<int> g_signal{0};  // the first stop signal received
std::atomic<std::atomic<bool>*> g_executive_stop{nullptr};
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free &&
              std::atomic<std::atomic<bool>*>::is_always_lock_free);

extern "C" void on_signal(int signo) {
  // Only lock-free atomics: async-signal-safe. The watchdog thread sees g_interrupt and commands
  // the safe state at once; the cycle sees the executive's stop flag after the current frame.
  int none = 0;
  (void)g_signal.compare_exchange_strong(none, signo);
  g_interrupt.store(true);
  if (std::atomic<bool>* stop = g_executive_stop.load()) stop->store(true);
}

// Installed before anything else happens, so that a signal during start-up also ends in an
// orderly way (the run then stops before its first frame) instead of killing the process. A signal
// that was already ignored when ringlet started stays ignored, as the convention asks: `nohup`
// ignores SIGHUP, a shell without job control ignores SIGINT and SIGQUIT for background jobs.
void install_signal_handlers() {
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  for (const int signo : ringlet::firmware::kStopSignals) {
    struct sigaction inherited {};
    if (sigaction(signo, nullptr, &inherited) == 0 && inherited.sa_handler == SIG_IGN) continue;
    sigaction(signo, &sa, nullptr);
  }
  // A closed pipe on stdout (`ringlet | head`) must not kill the controller mid-run: writes then
  // fail quietly instead.
  std::signal(SIGPIPE, SIG_IGN);
}

int signal_exit_code() { return 128 + g_signal.load(); }

// [camera] backend = "opencv": this binary's own, where the build has OpenCV.
#ifdef RINGLET_HAVE_OPENCV_CAMERA
constexpr ringlet::firmware::OpenCvCameraMaker kOpenCvCamera = ringlet::firmware::make_opencv_camera;
#else
constexpr ringlet::firmware::OpenCvCameraMaker kOpenCvCamera = nullptr;
#endif

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

}  // namespace

int main(int argc, char** argv) {
  using namespace ringlet;
  install_signal_handlers();
  CLI::App app{"Ringlet firmware: the cyclic executive driving the simulated (or real) robot"};
  std::filesystem::path config_path = "firmware/config/spl_field.toml";
  std::optional<std::string> duration_text;
  bool realtime = false;
  bool lockstep = false;
  std::optional<std::string> seed_text;
  std::optional<std::filesystem::path> report_path;
  std::optional<std::filesystem::path> svg_path;
  std::optional<std::filesystem::path> record_path;
  std::optional<std::filesystem::path> wb_log_path;
  bool check_only = false;
  app.add_option("-c,--config", config_path, "configuration file (TOML)")->capture_default_str()->type_name("FILE");
  app.add_option("-d,--duration", duration_text,
                 "run at most this many seconds of schedule time, 0 < S <= " +
                     std::to_string(static_cast<long>(firmware::kMaxRunSeconds)) + " (default: mission.timeout_s)")
      ->type_name("S");
  auto* rt = app.add_flag("--realtime", realtime, "pace the cycle by the real clock (clock_nanosleep)");
  app.add_flag("--lockstep", lockstep, "run on the virtual clock as fast as possible (simulation)")->excludes(rt);
  app.add_option("--seed", seed_text, "override the backend's seed, e.g. sim.seed (0 to 2^64-1)")->type_name("N");
  app.add_option("-r,--report", report_path, "write the mission summary and timing report as JSON")->type_name("FILE");
  app.add_option("--svg", svg_path, "write a picture of the world and the trajectory (backends with ground truth: sim)")->type_name("FILE");
  app.add_option("--record", record_path,
                 "record the robot's inputs (sensors, ball sensor, camera) to a HAL log that the replay backend plays back")
      ->type_name("FILE");
  app.add_option("--wb-log", wb_log_path, "log every whiteboard message to FILE (compare a replay with its recording)")
      ->type_name("FILE");
  app.add_flag("--check", check_only, "validate the configuration and world, print the task table, and exit");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }

  try {
    // Flags first: a typo costs nothing, not even reading the configuration.
    // 0: not given (parse_duration never returns it). A plain double: GCC 12 misjudges an
    // optional<double> here as maybe-uninitialized.
    const double duration = duration_text ? firmware::parse_duration(*duration_text) : 0.0;
    const std::optional<std::uint64_t> seed =
        seed_text ? std::optional<std::uint64_t>(firmware::parse_seed(*seed_text)) : std::nullopt;
    if (config_path.empty()) throw firmware::UsageError("--config: needs a file name");
    if (report_path && svg_path && *report_path == *svg_path) {
      throw firmware::UsageError("--report and --svg name the same file: " + report_path->string());
    }

    auto cfg = firmware::load_config(config_path);
    if (realtime) cfg.clock = firmware::ClockMode::kRealtime;
    if (lockstep) cfg.clock = firmware::ClockMode::kLockstep;
    if (seed) cfg.seed_override = *seed;
    if (record_path) cfg.record_log = *record_path;
    if (wb_log_path) cfg.whiteboard_log = *wb_log_path;
    if (duration > 0.0) {
      // The recording buffers are sized for the whole run at start-up: refuse what would not fit.
      if (const std::string why = firmware::run_length_problem(cfg, duration); !why.empty()) {
        throw firmware::UsageError("--duration: " + why);
      }
      cfg.mission.timeout_s = duration;
    }

    firmware::FirmwareStack stack(cfg, firmware::production_tasks(), kOpenCvCamera);
    print_table(cfg);
    if (check_only) {
      std::printf("configuration OK: %s, %s backend (%s)\n", config_path.c_str(), cfg.backend.c_str(),
                  cfg.backend_settings ? cfg.backend_settings->source_name().c_str() : "no settings");
      return g_interrupt.load() ? signal_exit_code() : 0;
    }

    // Claimed before the run: a path that cannot be written fails now, not after the run.
    std::optional<firmware::PendingOutput> report;
    std::optional<firmware::PendingOutput> svg;
    if (report_path) report.emplace(*report_path, "--report", "the report");
    if (svg_path) svg.emplace(*svg_path, "--svg", "the picture");

    g_executive_stop.store(&stack.executive().stop_flag());
    if (g_interrupt.load()) stack.executive().request_stop();  // a signal arrived during start-up
    const auto outcome = [&] {
      auto o = firmware::run_mission(stack, cfg.mission.timeout_s, g_interrupt, std::cerr);
      o.signal = g_signal.load();
      return o;
    }();
    g_executive_stop.store(nullptr);
    bool log_failed = false;
    for (const std::string& problem : stack.finish_logs()) {
      std::cerr << "ringlet: " << problem << '\n';
      log_failed = true;
    }
    if (!outcome.experiences_error.empty()) {
      std::cerr << "ringlet: " << outcome.experiences_error << '\n';
      log_failed = true;
    }

    const bool forced = stack.executive().failsafe_triggered() || outcome.watchdog_fired;
    const auto summary = firmware::summarize(stack, outcome, forced);
    std::cout << '\n';
    firmware::print_summary(std::cout, summary);
    std::cout << '\n';
    executive::print_timing_table(std::cout, stack.executive());
    std::cout << '\n';
    firmware::print_schedule_timing(std::cout, stack.schedule());

    // Each output is written even when the other fails; a failure is reported and turns the exit
    // code into 1, except after a stop signal, whose 128 + N stands.
    bool output_failed = false;
    const auto finish = [&output_failed](firmware::PendingOutput& out, const std::string& content, const char* label) {
      if (const std::string error = out.commit(content); !error.empty()) {
        std::cerr << "ringlet: " << error << '\n';
        output_failed = true;
      } else {
        std::cout << label << out.path().string() << '\n';
      }
    };
    if (report) {
      const nlohmann::json j{{"mission", firmware::summary_json(summary)},
                             {"timing", executive::timing_json(stack.executive())},
                             {"schedule", firmware::schedule_timing_json(stack.schedule())}};
      finish(*report, j.dump(2) + "\n", "report:  ");
    }
    if (svg) {
      std::ostringstream picture;
      if (firmware::write_picture(picture, stack, summary)) {
        finish(*svg, picture.str(), "picture: ");
      } else {
        std::cerr << "ringlet: no picture: the " << cfg.backend << " backend has no world to draw\n";
      }
    }
    const int code = firmware::exit_code(summary);
    return (output_failed || log_failed) && !summary.interrupted ? 1 : code;
  } catch (const firmware::UsageError& e) {
    std::cerr << "ringlet: " << e.what() << '\n';
    return 2;
  } catch (const firmware::OutputError& e) {
    std::cerr << "ringlet: " << e.what() << '\n';
    return 2;
  } catch (const firmware::ConfigError& e) {
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
