#include "ringlet/behaviour/llfsm/whiteboard_bus.hpp"

#include "ringlet/behaviour/llfsm/schedule.hpp"

namespace ringlet::behaviour::llfsm {
namespace {

Request to_request(wb::FsmCommand c) noexcept {
  switch (c) {
    case wb::FsmCommand::kSuspend:
      return Request::kSuspend;
    case wb::FsmCommand::kResume:
      return Request::kResume;
    case wb::FsmCommand::kRestart:
      return Request::kRestart;
  }
  return Request::kNone;
}

}  // namespace

WhiteboardFsmBus::WhiteboardFsmBus(wb::Whiteboard& board) noexcept
    : board_(board), seen_(board.generation<wb::FsmControl>()) {}

void WhiteboardFsmBus::publish(const StatusEvent& event) noexcept {
  wb::FsmStatus s{};
  s.machine = event.machine;
  s.state = event.state;
  s.previous = event.previous;
  s.ringlets = event.ringlets;
  s.suspended = event.suspended;
  board_.post(s);
}

void WhiteboardFsmBus::poll(Schedule& schedule) noexcept {
  const std::uint64_t head = board_.generation<wb::FsmControl>();
  while (seen_ < head) {
    const auto r = board_.read<wb::FsmControl>(seen_ + 1);
    if (r.status == wb::ReadStatus::kMissed) {
      missed_ += r.missed;
      seen_ += r.missed;
      continue;
    }
    ++seen_;
    if (!r.ok()) continue;  // overwritten while reading: counted by the next kMissed, if any
    if (!schedule.request(r.msg.machine.view(), to_request(r.msg.command))) ++unknown_;
  }
}

}  // namespace ringlet::behaviour::llfsm
