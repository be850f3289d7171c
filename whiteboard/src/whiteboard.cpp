// The non-template parts of the whiteboard: dispatch, by-name access, subscription bookkeeping.
#include "ringlet/whiteboard/whiteboard.hpp"

#include <bit>
#include <stdexcept>

#include "ringlet/whiteboard/tool_thread.hpp"

namespace ringlet::wb {

Whiteboard::Whiteboard(std::size_t generations)
    : depth_(std::bit_ceil(generations < 2 ? std::size_t{2} : generations)), channels_(depth_) {}

Whiteboard::~Whiteboard() { stop_tool_thread(); }

void Whiteboard::check_can_subscribe() const {
  if (frozen_.load(std::memory_order_relaxed)) {
    throw std::logic_error(
        "whiteboard: subscribe() after dispatch() or start_tool_thread(); subscribe at start-up");
  }
}

void Whiteboard::dispatch() noexcept {
  frozen_.store(true, std::memory_order_relaxed);
  // AllMessages is in id order, so this is the documented order: type id, then subscription.
  for_each_type([this](auto type) {
    using T = typename decltype(type)::type;
    auto& ch = channel<T>();
    deliver(ch.ring, ch.cycle_subs);
  });
}

void Whiteboard::deliver_tool_subscriptions() noexcept {
  for_each_type([this](auto type) {
    using T = typename decltype(type)::type;
    auto& ch = channel<T>();
    deliver(ch.ring, ch.tool_subs);
  });
}

std::uint64_t Whiteboard::missed(SubscriptionId id) const noexcept {
  if (id.value >= missed_counters_.size()) return 0;
  return missed_counters_[id.value]->load(std::memory_order_relaxed);
}

void Whiteboard::start_tool_thread(std::chrono::milliseconds period) {
  frozen_.store(true, std::memory_order_relaxed);
  if (tool_) return;
  tool_ = std::make_unique<ToolThread>(*this, period);
}

void Whiteboard::stop_tool_thread() noexcept { tool_.reset(); }

bool Whiteboard::tool_thread_running() const noexcept { return tool_ != nullptr; }

Status Whiteboard::post_text(std::string_view type_name, std::string_view text) {
  Status status = Error{"whiteboard: no message type named \"" + std::string{type_name} + "\""};
  for_each_type([&](auto type) {
    using T = typename decltype(type)::type;
    if (T::kName == type_name) status = post_result(T::from_string(text));
  });
  return status;
}

Result<std::string> Whiteboard::describe_newest(std::string_view type_name) const {
  Result<std::string> out = Error{"whiteboard: no message type named \"" + std::string{type_name} + "\""};
  for_each_type([&](auto type) {
    using T = typename decltype(type)::type;
    if (T::kName == type_name) out = get<T>().description();
  });
  return out;
}

Status Whiteboard::post_binary(std::span<const std::byte> bytes) {
  Result<WireHeader> header = peek_header(bytes);
  if (!header) return Error{header.error()};
  Status status = Error{"whiteboard: unknown type id " + std::to_string(to_underlying(header->id))};
  for_each_type([&](auto type) {
    using T = typename decltype(type)::type;
    if (T::kId == header->id) status = post_result(decode<T>(bytes));
  });
  return status;
}

}  // namespace ringlet::wb
