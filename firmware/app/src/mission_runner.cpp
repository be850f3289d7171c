#include "ringlet/firmware/mission_runner.hpp"

#include <chrono>
#include <condition_variable>
#include <map>
#include <string>
#include <mutex>
#include <optional>
#include <thread>

#include "ringlet/executive/realtime.hpp"
#include "ringlet/executive/report.hpp"
#include "ringlet/executive/watchdog.hpp"
#include "ringlet/planning/experience_file.hpp"

namespace ringlet::firmware {
namespace {

// A frame of the SPL field under qemu-aarch64 with a busy neighbour takes about a second of real
// time; ten is far beyond any healthy frame and still stops a hung task.
constexpr hal::Nanos kLockstepWatchdog = std::chrono::seconds{10};

// The non-real-time side of a run: prints what the cycle reported through the event log, and a
// progress line every few seconds. It never touches the cycle's data except through atomics.
class Narrator {
 public:
  Narrator(FirmwareStack& stack, std::ostream& log, double total_s)
      : stack_(stack), log_(log), total_s_(total_s), thread_([this] { loop(); }) {}
  ~Narrator() {
    {
      std::lock_guard lock(mutex_);
      done_ = true;
    }
    wake_.notify_all();
    thread_.join();
    drain();
  }
  Narrator(const Narrator&) = delete;
  Narrator& operator=(const Narrator&) = delete;

 private:
  void loop() {
    using namespace std::chrono_literals;
    auto next_progress = std::chrono::steady_clock::now() + 2s;
    std::unique_lock lock(mutex_);
    while (!wake_.wait_for(lock, 20ms, [this] { return done_; })) {
      drain();
      if (std::chrono::steady_clock::now() >= next_progress) {
        next_progress += 2s;
        const auto frames = stack_.executive().heartbeat().load(std::memory_order_acquire);
        const double t = static_cast<double>(frames) * hal::to_seconds(stack_.config().executive.period);
        log_ << "ringlet: running: " << t << " s of at most " << total_s_ << " s (" << frames << " frames)\n"
             << std::flush;
      }
    }
  }
  void drain() {
    executive::Event e;
    while (stack_.events().pop(e)) {
      log_ << "ringlet: " << executive::describe(e, stack_.executive()) << '\n';
    }
    wb::FsmStatus status;
    while (stack_.fsm_status_log().pop(status)) print(status);
  }

  // The first changes of each machine (the ball tracker changes state every frame by design).
  void print(const wb::FsmStatus& status) {
    static constexpr std::uint64_t kShownPerMachine = 20;
    std::uint64_t& shown = shown_[std::string(status.machine.view())];
    if (++shown > kShownPerMachine + 1) return;
    log_ << "ringlet: fsm " << status.machine.view() << ": ";
    if (shown == kShownPerMachine + 1) {
      log_ << "further changes not shown\n";
      return;
    }
    if (status.previous.view().empty()) {
      log_ << "starts in " << status.state.view();
    } else if (status.previous.view() == status.state.view()) {
      log_ << (status.suspended ? "suspended in " : "resumed in ") << status.state.view();
    } else {
      log_ << status.previous.view() << " -> " << status.state.view();
    }
    log_ << " (ringlet " << status.ringlets << ")\n";
  }

  FirmwareStack& stack_;
  std::ostream& log_;
  double total_s_;
  std::mutex mutex_;  // guards done_ only; the cycle never takes it
  std::condition_variable wake_;
  bool done_ = false;
  std::map<std::string, std::uint64_t> shown_;  // FsmStatus lines printed per machine
  std::thread thread_;
};

}  // namespace

std::string signal_name(int signo) {
  switch (signo) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    case SIGHUP: return "SIGHUP";
    case SIGQUIT: return "SIGQUIT";
    default: return "signal " + std::to_string(signo);
  }
}

RunOutcome run_mission(FirmwareStack& stack, double duration_s, const std::atomic<bool>& interrupt, std::ostream& log) {
  const auto& cfg = stack.config();

  auto& exec = stack.executive();
  auto& actuators = stack.robot().actuators();
  RunOutcome outcome;
  RemoteLink* remote = stack.remote();
  // Before the watchdog starts: waiting for monitors is not a stalled frame.
  if (remote != nullptr) remote->begin_run(log);
  const auto wall_start = std::chrono::steady_clock::now();
  {
    hal::MonotonicClock watchdog_clock;  // the watchdog always watches real time
    std::optional<executive::WatchdogThread> watchdog;
    if (cfg.executive.watchdog_periods > 0) {
      // On the real clock a frame is due every period, so a few missed periods mean a stall. In
      // lockstep a frame takes whatever the host needs (rendering, a sanitizer, qemu, a loaded
      // machine), and a run must not change with the host's load, so there the watchdog only
      // catches a hang: kLockstepWatchdog without a frame.
      auto timeout = cfg.executive.period * cfg.executive.watchdog_periods;
      if (cfg.clock == ClockMode::kLockstep) timeout = std::max<hal::Nanos>(timeout, kLockstepWatchdog);
      const auto poll = std::max(cfg.executive.period / 2, hal::Nanos{1'000'000});
      watchdog.emplace(watchdog_clock, exec.heartbeat(), actuators, timeout, poll, &interrupt);
      // Above the cycle's priority: a cycle spinning at SCHED_FIFO must not starve its watchdog.
      if (const int priority = executive::watchdog_priority(cfg.realtime.fifo_priority); priority > 0) {
        for (const auto& w : executive::set_fifo_priority(watchdog->native_handle(), priority, "watchdog")) {
          log << "ringlet: warning: " << w << '\n';
        }
      }
    }
    {
      Narrator narrator(stack, log, duration_s);
      // The cycle's thread only, after every other thread has started (the watchdog, the
      // narrator, the remote bridge's), so that none of them inherits the cycle's SCHED_FIFO
      // priority or its CPU. The watchdog got its own priority, one above the cycle's, when it started.
      for (const auto& w : executive::apply_realtime_settings(cfg.realtime)) log << "ringlet: warning: " << w << '\n';
      outcome.reason = exec.run(stack.frames_for(duration_s));
      if (remote != nullptr) remote->end_run();
    }
    if (watchdog) {
      watchdog->stop();
      outcome.watchdog_fired = watchdog->fired();
    }
  }
  actuators.enter_safe_state();  // clean shutdown: motors stopped, head held
  outcome.safe_at_end = actuators.in_safe_state();
  outcome.interrupted = interrupt.load();
  outcome.schedule_seconds = static_cast<double>(exec.next_frame()) * hal::to_seconds(cfg.executive.period);
  outcome.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  if (!cfg.planner.record.empty()) {
    const ExperienceLog& experiences = stack.experiences();
    try {
      planning::save_experiences(cfg.planner.record, experiences.experiences());
      outcome.experiences_written = experiences.experiences().size();
      log << "ringlet: experiences: " << outcome.experiences_written << " written to " << cfg.planner.record.string();
      if (experiences.dropped() > 0) log << " (" << experiences.dropped() << " more dropped: [planner] capacity is full)";
      log << '\n';
    } catch (const planning::ExperienceFileError& e) {
      outcome.experiences_error = std::string("[planner] record: ") + e.what();
    }
  }
  return outcome;
}

}  // namespace ringlet::firmware
