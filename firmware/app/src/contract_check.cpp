#include "ringlet/firmware/contract_check.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "ringlet/behaviour/llfsm/providers.hpp"
#include "ringlet/executive/task_table.hpp"

namespace ringlet::firmware {

void check_contracts(const FirmwareConfig& config, std::span<const TaskDeclaration* const> tasks,
                     const behaviour::llfsm::Schedule& schedule) {
  const std::string table = config.positions.at("executive.tasks");
  std::vector<std::string_view> provided_by_tasks;
  std::vector<std::string> problems;
  for (const TaskDeclaration* task : tasks) {
    for (const std::string_view type : task->provides_types) {
      for (const TaskDeclaration* other : tasks) {
        if (other == task) break;
        const auto& p = other->provides_types;
        if (std::find(p.begin(), p.end(), type) != p.end()) {
          problems.push_back(table + ": tasks '" + std::string(other->name) + "' and '" + std::string(task->name) +
                             "' both provide '" + std::string(type) + "': run one of them");
        }
      }
      provided_by_tasks.push_back(type);
    }
  }
  const auto machine_provides = [&schedule](std::string_view type) {
    for (std::size_t i = 0; i < schedule.size(); ++i) {
      const auto p = schedule.machine(i).provides_types();
      if (std::find(p.begin(), p.end(), type) != p.end()) return true;
    }
    return false;
  };
  for (const TaskDeclaration* task : tasks) {
    for (const std::string_view type : task->requires_types) {
      const bool by_task = std::find(provided_by_tasks.begin(), provided_by_tasks.end(), type) != provided_by_tasks.end();
      if (!by_task && !machine_provides(type)) {
        problems.push_back(task->location() + ": task '" + std::string(task->name) + "' requires '" +
                           std::string(type) + "', but no task in the table (" + table + ") or machine provides it");
      }
    }
  }
  const auto machines = behaviour::llfsm::check_providers(schedule, provided_by_tasks);
  for (const auto& m : machines.missing) {
    problems.push_back(table + ": machine '" + std::string(m.machine) + "' requires '" + std::string(m.type) +
                       "', but no task in the table or machine provides it");
  }
  if (!problems.empty()) {
    throw ConfigError(config.source.string() + ": the controller's data flow is incomplete:" +
                      executive::list_problems(problems));
  }
}

void check_remote_writers(const FirmwareConfig& config, std::span<const TaskDeclaration* const> tasks,
                          const behaviour::llfsm::Schedule& schedule) {
  const std::string where = config.positions.at("remote.accept") + ": remote.accept: \"";
  for (const std::string& type : config.remote.accept) {
    for (const TaskDeclaration* task : tasks) {
      const auto& p = task->provides_types;
      if (std::find(p.begin(), p.end(), type) != p.end()) {
        throw ConfigError(where + type + "\" is posted by task '" + std::string(task->name) + "' (" + task->location() +
                          "); a remote writer would be its second writer");
      }
    }
    for (std::size_t i = 0; i < schedule.size(); ++i) {
      const auto p = schedule.machine(i).provides_types();
      if (std::find(p.begin(), p.end(), type) != p.end()) {
        throw ConfigError(where + type + "\" is posted by machine '" + std::string(schedule.machine(i).name()) +
                          "'; a remote writer would be its second writer");
      }
    }
  }
}

}  // namespace ringlet::firmware
