#pragma once
// Where a Schedule sends FsmStatus and gets FsmControl. The runtime's semantics do not depend on
// the whiteboard; WhiteboardFsmBus (whiteboard_bus.hpp) is the production implementation and the
// tests can use a recording fake.
#include "ringlet/behaviour/llfsm/machine.hpp"

namespace ringlet::behaviour::llfsm {

class FsmBus {
 public:
  virtual ~FsmBus() = default;
  /// Every state change, suspend, resume and restart. No allocation: runs in the turn.
  virtual void publish(const StatusEvent& event) noexcept = 0;
  /// At the start of each turn: forward the control requests that arrived since the last turn
  /// (Schedule::request). No allocation.
  virtual void poll(Schedule& schedule) noexcept = 0;
};

}  // namespace ringlet::behaviour::llfsm
