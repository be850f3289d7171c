#pragma once
// A hand-written machine for the runtime tests: states and ordered transitions built at run time,
// every hook appends "<machine>.<hook>:<state>" to a shared log, so a test can check the exact
// ringlet order. It allocates (std::function, std::string): use it for semantics, not for the
// allocation test.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "ringlet/behaviour/llfsm/fsm_bus.hpp"
#include "ringlet/behaviour/llfsm/machine.hpp"
#include "ringlet/behaviour/llfsm/schedule.hpp"

namespace ringlet::behaviour::llfsm::test {

using Log = std::vector<std::string>;

struct NameHolder {
  std::string held_name;
};

class ScriptedMachine : private NameHolder, public Machine {
 public:
  using Guard = std::function<bool(ScriptedMachine&)>;
  using Action = std::function<void(ScriptedMachine&)>;

  ScriptedMachine(std::string machine_name, std::vector<std::string> states, Log& log)
      : NameHolder{std::move(machine_name)}, Machine(held_name, 0), states_(std::move(states)), log_(log),
        transitions_(states_.size()), submachines_(states_.size()), internals_(states_.size()) {}

  void add_transition(StateIndex from, Guard guard, StateIndex to) {
    transitions_[from].push_back({std::move(guard), to});
  }
  void own_submachine(StateIndex s, std::string child, SubmachineEntry mode) {
    submachines_[s] = {std::move(child), mode};
  }
  void on_internal(StateIndex s, Action a) { internals_[s] = std::move(a); }

  [[nodiscard]] std::size_t state_count() const noexcept override { return states_.size(); }
  [[nodiscard]] std::string_view state_name(StateIndex s) const noexcept override { return states_[s]; }
  [[nodiscard]] SubmachineLink submachine(StateIndex s) const noexcept override {
    return {submachines_[s].first, submachines_[s].second};
  }

  // What generated action code can call, opened up for the lambdas.
  using Machine::after;
  using Machine::after_ms;
  using Machine::now;
  using Machine::restart_machine;
  using Machine::resume_machine;
  using Machine::suspend_machine;

  int local = 0;  // a "local variable": reset on restart

 protected:
  void snapshot(StateIndex s) noexcept override { note("snapshot", s); }
  void on_entry(StateIndex s) override { note("entry", s); }
  void on_exit(StateIndex s) override { note("exit", s); }
  void internal(StateIndex s) override {
    note("internal", s);
    if (internals_[s]) internals_[s](*this);
  }
  void on_suspend(StateIndex s) override { note("suspend", s); }
  void on_resume(StateIndex s) override { note("resume", s); }
  [[nodiscard]] StateIndex fire(StateIndex s) noexcept override {
    for (auto& [guard, to] : transitions_[s]) {
      if (guard(*this)) return to;
    }
    return kNoState;
  }
  void write_back(StateIndex s) noexcept override { note("write", s); }
  void reset_locals() noexcept override {
    local = 0;
    log_.push_back(std::string(name()) + ".reset");
  }

 private:
  void note(const char* hook, StateIndex s) {
    log_.push_back(std::string(name()) + "." + hook + ":" + states_[s]);
  }

  std::vector<std::string> states_;
  Log& log_;
  std::vector<std::vector<std::pair<Guard, StateIndex>>> transitions_;
  std::vector<std::pair<std::string, SubmachineEntry>> submachines_;
  std::vector<Action> internals_;
};

/// Records status events as "machine:previous->state[ringlets]" (+ " suspended") and hands out
/// queued control requests at poll time.
class RecordingBus final : public FsmBus {
 public:
  void publish(const StatusEvent& e) noexcept override {
    events.push_back(std::string(e.machine) + ":" + std::string(e.previous) + "->" + std::string(e.state) + "[" +
                     std::to_string(e.ringlets) + "]" + (e.suspended ? " suspended" : ""));
  }
  void poll(Schedule& schedule) noexcept override {
    for (auto& [m, r] : queued) schedule.request(m, r);
    queued.clear();
  }
  std::vector<std::string> events;
  std::vector<std::pair<std::string, Request>> queued;
};

inline bool always(ScriptedMachine&) { return true; }
inline bool never(ScriptedMachine&) { return false; }

}  // namespace ringlet::behaviour::llfsm::test
