#pragma once
// One logic-labeled finite-state machine (Mi-Pal LLFSM) and the ringlet that executes it.
//
// A ringlet is the complete assessment of the current state, in this order (behaviour/README.md
// has the full contract, tests/behaviour/ringlet_test.cpp checks every clause):
//   0. apply the pending control request (restart > suspend > resume), see Request;
//   1. snapshot(): copy the READ footprint of the current state from the whiteboard;
//   2. OnResume if the machine was resumed at step 0, OnEntry if the state was entered since the
//      last ringlet (also after a self-transition or a restart);
//   3. fire(): the state's transitions in declared order, the first true guard wins:
//        OnExit, change state (posting FsmStatus), else Internal;
//   4. write_back(): post the WRITE footprint of the state whose code ran.
// The generated code (behaviour/llfsmc) implements the hooks; the semantics live here only, so
// hand-written machines in the tests exercise exactly what generated machines get.
#include <chrono>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "ringlet/hal/time.hpp"

namespace ringlet::behaviour::llfsm {

using StateIndex = std::uint16_t;
inline constexpr StateIndex kNoState = 0xFFFF;

/// Control requests, in increasing priority: when several arrive for one machine before its next
/// ringlet, the highest one wins (order-independent, so reordering the schedule or the sender
/// cannot change the outcome). Restart also clears a suspension.
enum class Request : std::uint8_t { kNone = 0, kResume = 1, kSuspend = 2, kRestart = 3 };

/// What a parent does to the submachine it owns when it enters the owning state (on leaving, the
/// child is always suspended).
enum class SubmachineEntry : std::uint8_t { kRestart, kResume };

struct SubmachineLink {
  std::string_view machine;  // empty: the state owns no submachine
  SubmachineEntry on_entry = SubmachineEntry::kRestart;
};

/// What a machine reports on every state change, suspend, resume and restart (the whiteboard
/// adapter turns it into an FsmStatus message).
struct StatusEvent {
  std::string_view machine;
  std::string_view state;
  std::string_view previous;
  std::uint64_t ringlets = 0;
  bool suspended = false;
};

class Schedule;

class Machine {
 public:
  Machine(const Machine&) = delete;
  Machine& operator=(const Machine&) = delete;
  virtual ~Machine() = default;

  [[nodiscard]] std::string_view name() const noexcept { return name_; }
  [[nodiscard]] StateIndex current_state() const noexcept { return state_; }
  [[nodiscard]] std::string_view current_state_name() const noexcept { return state_name(state_); }
  [[nodiscard]] bool suspended() const noexcept { return suspended_; }
  /// Ringlets executed (suspended slots do not count); kept across restarts.
  [[nodiscard]] std::uint64_t ringlets() const noexcept { return ringlets_; }
  /// Time in the current state on the executive's clock: `now` of this ringlet minus `now` of the
  /// ringlet that ran the state's OnEntry (so 0 during OnEntry; suspended time counts).
  [[nodiscard]] hal::Nanos state_time() const noexcept { return entered_ ? hal::Nanos{0} : now_ - entered_at_; }
  [[nodiscard]] Request pending_request() const noexcept { return pending_; }

  /// Queue a request; it takes effect at the start of this machine's next ringlet.
  void request(Request r) noexcept {
    if (static_cast<std::uint8_t>(r) > static_cast<std::uint8_t>(pending_)) pending_ = r;
  }

  /// Executes one ringlet at executive time `now`. The Schedule calls it; public for tests.
  void ringlet(hal::Nanos now) noexcept;

  // Introspection, implemented by the generated code.
  [[nodiscard]] virtual std::size_t state_count() const noexcept = 0;
  [[nodiscard]] virtual std::string_view state_name(StateIndex s) const noexcept = 0;
  /// REQUIRES (union of the READ footprints) and PROVIDES (union of the WRITE footprints), as
  /// whiteboard type names.
  [[nodiscard]] virtual std::span<const std::string_view> requires_types() const noexcept { return {}; }
  [[nodiscard]] virtual std::span<const std::string_view> provides_types() const noexcept { return {}; }
  [[nodiscard]] virtual SubmachineLink submachine(StateIndex) const noexcept { return {}; }

 protected:
  Machine(std::string_view name, StateIndex initial) noexcept : name_(name), initial_(initial), state_(initial) {}

  // --- What action code and guards may call ---------------------------------------------------
  [[nodiscard]] hal::Nanos now() const noexcept { return now_; }
  template <class Rep, class Period>
  [[nodiscard]] bool after(std::chrono::duration<Rep, Period> d) const noexcept {
    return state_time() >= std::chrono::duration_cast<hal::Nanos>(d);
  }
  [[nodiscard]] bool after_ms(std::int64_t ms) const noexcept { return after(std::chrono::milliseconds(ms)); }
  /// Requests to another machine of the same schedule, by name; false if there is none.
  bool suspend_machine(std::string_view machine) noexcept { return send(machine, Request::kSuspend); }
  bool resume_machine(std::string_view machine) noexcept { return send(machine, Request::kResume); }
  bool restart_machine(std::string_view machine) noexcept { return send(machine, Request::kRestart); }

  // --- Hooks (one switch over the state each in generated code) --------------------------------
  virtual void snapshot(StateIndex) noexcept {}
  virtual void on_entry(StateIndex) {}
  virtual void on_exit(StateIndex) {}
  virtual void internal(StateIndex) {}
  virtual void on_suspend(StateIndex) {}
  virtual void on_resume(StateIndex) {}
  /// Evaluates the state's guards in declared order; returns the first true one's target, or
  /// kNoState. Guards are side-effect free (the generator rejects anything else).
  [[nodiscard]] virtual StateIndex fire(StateIndex s) noexcept = 0;
  virtual void write_back(StateIndex) noexcept {}
  /// Local variables back to their initial values (restart).
  virtual void reset_locals() noexcept {}

 private:
  friend class Schedule;

  bool send(std::string_view machine, Request r) noexcept;
  void publish(StateIndex previous) noexcept;
  void restart() noexcept;
  /// Parent-side submachine bookkeeping when the current state changes from `from` to `to`.
  void hand_over_children(StateIndex from, StateIndex to) noexcept;
  [[nodiscard]] Machine* child(StateIndex s) const noexcept {
    return s < children_.size() ? children_[s] : nullptr;
  }

  std::string_view name_;
  StateIndex initial_;
  StateIndex state_;
  bool entered_ = true;  // the next ringlet runs OnEntry
  bool suspended_ = false;
  Request pending_ = Request::kNone;
  std::uint64_t ringlets_ = 0;
  hal::Nanos now_{0};
  hal::Nanos entered_at_{0};
  Schedule* schedule_ = nullptr;
  std::vector<Machine*> children_;  // per state, resolved by Schedule::start (start-up only)
};

}  // namespace ringlet::behaviour::llfsm
