#pragma once
// The deterministic schedule: an ordered vector of machines, each with its number of ringlets per
// turn. run_turn() gives every machine its ringlets in order; machines run one after another, so
// a machine sees another's writes only at its own next snapshot, never in the middle of a ringlet.
//
// Firmware wraps run_turn() as one executive task; this header knows nothing of the executive.
// Everything is built at start-up (add, start); run_turn never allocates.
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "ringlet/behaviour/llfsm/fsm_bus.hpp"
#include "ringlet/behaviour/llfsm/machine.hpp"
#include "ringlet/hal/clock.hpp"
#include "ringlet/hal/time.hpp"

namespace ringlet::behaviour::llfsm {

/// Per-machine timing of its ringlets, measured with the schedule's Stopwatch (suspended slots
/// are measured too: they are part of the turn's cost).
struct RingletStats {
  std::uint64_t samples = 0;
  hal::Nanos last_wall{0}, max_wall{0}, total_wall{0};
  hal::Nanos last_cpu{0}, max_cpu{0}, total_cpu{0};

  [[nodiscard]] hal::Nanos mean_wall() const noexcept {
    return samples == 0 ? hal::Nanos{0} : total_wall / static_cast<std::int64_t>(samples);
  }
};

/// What the schedule measures around each ringlet. The thread CPU clock is a system call on
/// Linux (~0.3-0.4 us per read on the dev host, against ~10 ns for a ringlet), so by default
/// only wall time is measured; the *_cpu stats then stay 0.
enum class Timing : std::uint8_t { kOff, kWall, kWallAndCpu };

class Schedule {
 public:
  /// `bus` may be null (no status out, no control in: tests and benchmarks).
  explicit Schedule(hal::Stopwatch& stopwatch, FsmBus* bus = nullptr, Timing timing = Timing::kWall) noexcept
      : stopwatch_(stopwatch), bus_(bus), timing_(timing) {}
  Schedule(const Schedule&) = delete;
  Schedule& operator=(const Schedule&) = delete;

  /// Start-up only. Appends `machine` (not owned; must outlive the schedule). Throws
  /// std::invalid_argument for a duplicate name, zero ringlets, or after start().
  void add(Machine& machine, std::uint32_t ringlets_per_turn = 1);

  /// Start-up only: resolves submachine links (throws std::invalid_argument naming the parent,
  /// state and missing child), suspends every machine some state owns, hands each parent's
  /// initial state its child, and publishes every machine's initial status. run_turn calls it
  /// if nobody did (then the first turn allocates).
  void start();

  /// One turn at executive time `now`: poll the bus for control requests, then every machine's
  /// ringlets in schedule order.
  void run_turn(hal::Nanos now) noexcept;

  /// Queue a request for the named machine (takes effect at its next ringlet). False: unknown.
  bool request(std::string_view machine, Request r) noexcept;

  [[nodiscard]] Machine* find(std::string_view machine) const noexcept;
  [[nodiscard]] std::size_t size() const noexcept { return entries_.size(); }
  [[nodiscard]] Machine& machine(std::size_t i) const noexcept { return *entries_[i].machine; }
  [[nodiscard]] std::uint32_t ringlets_per_turn(std::size_t i) const noexcept { return entries_[i].ringlets; }
  [[nodiscard]] const RingletStats& stats(std::size_t i) const noexcept { return entries_[i].stats; }
  /// Stats by machine name, or nullptr.
  [[nodiscard]] const RingletStats* stats(std::string_view machine) const noexcept;
  [[nodiscard]] std::uint64_t turns() const noexcept { return turns_; }
  [[nodiscard]] bool started() const noexcept { return started_; }

 private:
  friend class Machine;

  struct Entry {
    Machine* machine = nullptr;
    std::uint32_t ringlets = 1;
    RingletStats stats{};
  };

  void publish(const StatusEvent& event) noexcept {
    if (bus_ != nullptr) bus_->publish(event);
  }

  void measured_ringlet(Entry& e, hal::Nanos now) noexcept;

  hal::Stopwatch& stopwatch_;
  FsmBus* bus_;
  Timing timing_;
  std::vector<Entry> entries_;
  std::uint64_t turns_ = 0;
  bool started_ = false;
};

}  // namespace ringlet::behaviour::llfsm
