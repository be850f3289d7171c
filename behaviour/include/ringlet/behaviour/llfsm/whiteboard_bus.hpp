#pragma once
// The production FsmBus: status out as FsmStatus, requests in from FsmControl. At the start of
// each turn every FsmControl generation posted since the last turn is read in generation order
// and forwarded by machine name (unknown names are counted and dropped); generations the ring
// has already overwritten are counted as missed.
#include <cstdint>

#include "ringlet/behaviour/llfsm/fsm_bus.hpp"
#include "ringlet/whiteboard/whiteboard.hpp"

namespace ringlet::behaviour::llfsm {

class WhiteboardFsmBus final : public FsmBus {
 public:
  /// Requests posted before construction are ignored: only new generations count.
  explicit WhiteboardFsmBus(wb::Whiteboard& board) noexcept;

  void publish(const StatusEvent& event) noexcept override;
  void poll(Schedule& schedule) noexcept override;

  [[nodiscard]] std::uint64_t missed_controls() const noexcept { return missed_; }
  [[nodiscard]] std::uint64_t unknown_machines() const noexcept { return unknown_; }

 private:
  wb::Whiteboard& board_;
  std::uint64_t seen_;  // last FsmControl generation handled
  std::uint64_t missed_ = 0;
  std::uint64_t unknown_ = 0;
};

}  // namespace ringlet::behaviour::llfsm
