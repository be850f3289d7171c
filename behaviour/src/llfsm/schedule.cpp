#include "ringlet/behaviour/llfsm/schedule.hpp"

#include <stdexcept>
#include <string>

namespace ringlet::behaviour::llfsm {

void Schedule::add(Machine& machine, std::uint32_t ringlets_per_turn) {
  if (started_) throw std::invalid_argument("llfsm: cannot add '" + std::string(machine.name()) + "' after start()");
  if (ringlets_per_turn == 0) {
    throw std::invalid_argument("llfsm: machine '" + std::string(machine.name()) + "' needs at least one ringlet per turn");
  }
  if (find(machine.name()) != nullptr) {
    throw std::invalid_argument("llfsm: duplicate machine name '" + std::string(machine.name()) + "'");
  }
  if (machine.schedule_ != nullptr) {
    throw std::invalid_argument("llfsm: machine '" + std::string(machine.name()) + "' is already scheduled");
  }
  machine.schedule_ = this;
  entries_.push_back(Entry{&machine, ringlets_per_turn, {}});
}

void Schedule::start() {
  if (started_) return;
  for (Entry& e : entries_) {
    Machine& m = *e.machine;
    m.children_.assign(m.state_count(), nullptr);
    for (std::size_t s = 0; s < m.state_count(); ++s) {
      const auto state = static_cast<StateIndex>(s);
      const SubmachineLink link = m.submachine(state);
      if (link.machine.empty()) continue;
      Machine* const c = find(link.machine);
      if (c == nullptr || c == &m) {
        throw std::invalid_argument("llfsm: machine '" + std::string(m.name()) + "' state '" +
                                    std::string(m.state_name(state)) + "': submachine '" +
                                    std::string(link.machine) + (c == nullptr ? "' is not scheduled" : "' is itself"));
      }
      m.children_[s] = c;
      c->suspended_ = true;  // a submachine runs only while its owning state is current
    }
  }
  for (Entry& e : entries_) e.machine->hand_over_children(kNoState, e.machine->state_);
  for (Entry& e : entries_) e.machine->publish(kNoState);
  started_ = true;
}

void Schedule::run_turn(hal::Nanos now) noexcept {
  if (!started_) start();
  if (bus_ != nullptr) bus_->poll(*this);
  for (Entry& e : entries_) {
    for (std::uint32_t i = 0; i < e.ringlets; ++i) {
      if (timing_ == Timing::kOff) {
        e.machine->ringlet(now);
      } else {
        measured_ringlet(e, now);
      }
    }
  }
  ++turns_;
}

void Schedule::measured_ringlet(Entry& e, hal::Nanos now) noexcept {
  const bool cpu_too = timing_ == Timing::kWallAndCpu;
  const hal::Nanos c0 = cpu_too ? stopwatch_.cpu_now() : hal::Nanos{0};
  const hal::Nanos w0 = stopwatch_.wall_now();
  e.machine->ringlet(now);
  const hal::Nanos wall = stopwatch_.wall_now() - w0;
  RingletStats& st = e.stats;
  ++st.samples;
  st.last_wall = wall;
  st.total_wall += wall;
  if (wall > st.max_wall) st.max_wall = wall;
  if (cpu_too) {
    const hal::Nanos cpu = stopwatch_.cpu_now() - c0;
    st.last_cpu = cpu;
    st.total_cpu += cpu;
    if (cpu > st.max_cpu) st.max_cpu = cpu;
  }
}

bool Schedule::request(std::string_view machine, Request r) noexcept {
  Machine* const m = find(machine);
  if (m == nullptr) return false;
  m->request(r);
  return true;
}

Machine* Schedule::find(std::string_view machine) const noexcept {
  for (const Entry& e : entries_) {
    if (e.machine->name() == machine) return e.machine;
  }
  return nullptr;
}

const RingletStats* Schedule::stats(std::string_view machine) const noexcept {
  for (const Entry& e : entries_) {
    if (e.machine->name() == machine) return &e.stats;
  }
  return nullptr;
}

}  // namespace ringlet::behaviour::llfsm
