#pragma once
// Every task the firmware can run, by name. The task table in the configuration says which of
// them run, how often, in which phase, with what budget and overrun policy; the registry says what
// each one is. Adding a task: its own file (a class with kDeclaration and make()), one add<>()
// line in production_tasks(), one row in the table (README: "Adding a task").
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "ringlet/executive/task.hpp"
#include "ringlet/firmware/task_declaration.hpp"
#include "ringlet/firmware/task_services.hpp"

namespace ringlet::firmware {

struct RegisteredTask {
  const TaskDeclaration* declaration;
  std::unique_ptr<executive::Task> (*make)(TaskServices& services);
};

class TaskRegistry {
 public:
  /// T has `static constexpr TaskDeclaration kDeclaration` and
  /// `static std::unique_ptr<executive::Task> make(TaskServices&)` (throws ConfigError when the
  /// robot or the configuration cannot give it what it needs).
  template <class T>
  void add() {
    tasks_.push_back({&T::kDeclaration, &T::make});
  }
  [[nodiscard]] const RegisteredTask* find(std::string_view name) const noexcept;
  [[nodiscard]] std::span<const RegisteredTask> tasks() const noexcept { return tasks_; }

 private:
  std::vector<RegisteredTask> tasks_;
};

/// The tasks of the shipped firmware.
[[nodiscard]] TaskRegistry production_tasks();

}  // namespace ringlet::firmware
