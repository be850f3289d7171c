#include "ringlet/behaviour/llfsm/providers.hpp"

#include <algorithm>

namespace ringlet::behaviour::llfsm {

std::string ProviderReport::describe() const {
  std::string out;
  for (const MissingProvider& m : missing) {
    out += "machine '";
    out += m.machine;
    out += "' requires '";
    out += m.type;
    out += "': no provider\n";
  }
  return out;
}

ProviderReport check_providers(const Schedule& schedule, std::span<const std::string_view> provided_by_tasks) {
  const auto provided = [&](std::string_view type) {
    if (std::find(provided_by_tasks.begin(), provided_by_tasks.end(), type) != provided_by_tasks.end()) return true;
    for (std::size_t i = 0; i < schedule.size(); ++i) {
      const auto p = schedule.machine(i).provides_types();
      if (std::find(p.begin(), p.end(), type) != p.end()) return true;
    }
    return false;
  };
  ProviderReport report;
  for (std::size_t i = 0; i < schedule.size(); ++i) {
    const Machine& m = schedule.machine(i);
    for (const std::string_view type : m.requires_types()) {
      if (!provided(type)) report.missing.push_back(MissingProvider{m.name(), type});
    }
  }
  return report;
}

}  // namespace ringlet::behaviour::llfsm
