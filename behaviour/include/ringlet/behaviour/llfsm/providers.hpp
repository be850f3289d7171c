#pragma once
// Start-up check that the schedule is complete: every whiteboard type some machine REQUIRES is
// PROVIDED by a scheduled machine (a readwrite external provides itself: the machine reads back
// what it wrote) or by a non-FSM task (sensors, estimators), listed by the caller.
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ringlet/behaviour/llfsm/schedule.hpp"

namespace ringlet::behaviour::llfsm {

struct MissingProvider {
  std::string_view machine;
  std::string_view type;
};

struct ProviderReport {
  std::vector<MissingProvider> missing;  // in schedule order, then REQUIRES order

  [[nodiscard]] bool ok() const noexcept { return missing.empty(); }
  /// One line per gap: "machine 'BallTracker' requires 'BallBelief': no provider".
  [[nodiscard]] std::string describe() const;
};

/// Start-up only (allocates the report).
[[nodiscard]] ProviderReport check_providers(const Schedule& schedule,
                                             std::span<const std::string_view> provided_by_tasks = {});

}  // namespace ringlet::behaviour::llfsm
