#pragma once
// The start-up check of the whole controller's data flow, in one place: every whiteboard type a
// scheduled task or machine REQUIRES is PROVIDED by a scheduled task or machine, and no type is
// provided by two tasks. Declarations come from the tasks (TaskDeclaration) and the machines (their
// footprints); nothing is listed by hand.
#include <span>

#include "ringlet/behaviour/llfsm/schedule.hpp"
#include "ringlet/firmware/config.hpp"
#include "ringlet/firmware/task_declaration.hpp"

namespace ringlet::firmware {

/// Throws ConfigError listing every problem: a task's names its declaration's "file:line", a
/// machine's the task table's place in the configuration.
void check_contracts(const FirmwareConfig& config, std::span<const TaskDeclaration* const> tasks,
                     const behaviour::llfsm::Schedule& schedule);

/// [remote] accept: a type a monitor may write must have no writer in the controller (a whiteboard
/// type has one writer; remote writes are posted by the whiteboard task). Throws ConfigError at
/// remote.accept naming the task (its declaration's file:line) or machine that posts it.
void check_remote_writers(const FirmwareConfig& config, std::span<const TaskDeclaration* const> tasks,
                          const behaviour::llfsm::Schedule& schedule);

}  // namespace ringlet::firmware
