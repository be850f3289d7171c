#include "ringlet/behaviour/llfsm/machine.hpp"

#include "ringlet/behaviour/llfsm/schedule.hpp"

namespace ringlet::behaviour::llfsm {

void Machine::ringlet(hal::Nanos now) noexcept {
  now_ = now;
  const Request r = pending_;
  pending_ = Request::kNone;
  bool resumed = false;
  switch (r) {
    case Request::kRestart:
      restart();
      break;
    case Request::kSuspend:
      if (!suspended_) {
        // OnSuspend is code of the current state: it gets the state's footprint like any action.
        snapshot(state_);
        on_suspend(state_);
        write_back(state_);
        suspended_ = true;
        if (Machine* c = child(state_)) c->request(Request::kSuspend);
        publish(state_);
      }
      return;  // the suspending slot is used up either way
    case Request::kResume:
      if (suspended_) {
        suspended_ = false;
        resumed = true;
        if (Machine* c = child(state_)) c->request(Request::kResume);
        publish(state_);
      }
      break;
    case Request::kNone:
      break;
  }
  if (suspended_) return;

  const StateIndex s = state_;
  snapshot(s);
  if (resumed) on_resume(s);
  if (entered_) {
    entered_ = false;
    entered_at_ = now;
    on_entry(s);
  }
  const StateIndex t = fire(s);
  ++ringlets_;
  if (t != kNoState) {
    on_exit(s);
    state_ = t;
    entered_ = true;  // also for a self-transition: OnExit ran, so OnEntry runs again
    write_back(s);
    hand_over_children(s, t);
    publish(s);
  } else {
    internal(s);
    write_back(s);
  }
}

void Machine::restart() noexcept {
  // A restart abandons the current state without OnExit: it is a reset, not a transition.
  const StateIndex from = state_;
  reset_locals();
  state_ = initial_;
  entered_ = true;
  suspended_ = false;
  hand_over_children(from, initial_);
  publish(from);
}

void Machine::hand_over_children(StateIndex from, StateIndex to) noexcept {
  Machine* const old_child = child(from);
  Machine* const new_child = child(to);
  if (old_child != nullptr && old_child != new_child) old_child->request(Request::kSuspend);
  if (new_child != nullptr) {
    new_child->request(submachine(to).on_entry == SubmachineEntry::kRestart ? Request::kRestart
                                                                            : Request::kResume);
  }
}

bool Machine::send(std::string_view machine, Request r) noexcept {
  return schedule_ != nullptr && schedule_->request(machine, r);
}

void Machine::publish(StateIndex previous) noexcept {
  if (schedule_ == nullptr) return;
  schedule_->publish(StatusEvent{name_, state_name(state_),
                                 previous == kNoState ? std::string_view{} : state_name(previous),
                                 ringlets_, suspended_});
}

}  // namespace ringlet::behaviour::llfsm
