#pragma once
// The LLFSM schedule's part of the timing report: every machine in schedule order with its
// ringlets per turn and the wall time of its ringlets (the fsm task's row in the executive's
// table is their sum plus the bus).
#include <ostream>

#include <nlohmann/json.hpp>

#include "ringlet/behaviour/llfsm/schedule.hpp"

namespace ringlet::firmware {

void print_schedule_timing(std::ostream& out, const behaviour::llfsm::Schedule& schedule);
[[nodiscard]] nlohmann::json schedule_timing_json(const behaviour::llfsm::Schedule& schedule);

}  // namespace ringlet::firmware
