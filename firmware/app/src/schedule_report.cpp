#include "ringlet/firmware/schedule_report.hpp"

#include <cstdio>
#include <string>

namespace ringlet::firmware {
namespace {

double us(hal::Nanos t) { return hal::to_seconds(t) * 1e6; }

}  // namespace

void print_schedule_timing(std::ostream& out, const behaviour::llfsm::Schedule& schedule) {
  char line[256];
  std::snprintf(line, sizeof line, "LLFSM schedule (task fsm), %llu turns\n%-3s %-14s %9s %10s %10s %10s  %s\n",
                static_cast<unsigned long long>(schedule.turns()), "#", "MACHINE", "PER-TURN", "RINGLETS",
                "AVG", "MAX", "FINAL STATE");
  out << line;
  for (std::size_t i = 0; i < schedule.size(); ++i) {
    const auto& m = schedule.machine(i);
    const auto& st = schedule.stats(i);
    std::snprintf(line, sizeof line, "%-3zu %-14s %9u %10llu %10.2f %10.2f  %s%s\n", i, std::string(m.name()).c_str(),
                  schedule.ringlets_per_turn(i), static_cast<unsigned long long>(m.ringlets()), us(st.mean_wall()),
                  us(st.max_wall), std::string(m.current_state_name()).c_str(), m.suspended() ? " (suspended)" : "");
    out << line;
  }
  out << "(ringlet wall time in us, per ringlet)\n";
}

nlohmann::json schedule_timing_json(const behaviour::llfsm::Schedule& schedule) {
  nlohmann::json machines = nlohmann::json::array();
  for (std::size_t i = 0; i < schedule.size(); ++i) {
    const auto& m = schedule.machine(i);
    const auto& st = schedule.stats(i);
    machines.push_back({{"name", std::string(m.name())},
                        {"ringlets_per_turn", schedule.ringlets_per_turn(i)},
                        {"ringlets", m.ringlets()},
                        {"samples", st.samples},
                        {"mean_us", us(st.mean_wall())},
                        {"max_us", us(st.max_wall)},
                        {"final_state", std::string(m.current_state_name())},
                        {"suspended", m.suspended()}});
  }
  return {{"turns", schedule.turns()}, {"machines", machines}};
}

}  // namespace ringlet::firmware
