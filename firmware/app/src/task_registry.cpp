#include "ringlet/firmware/task_registry.hpp"

#include "ringlet/firmware/tasks/actuate_task.hpp"
#include "ringlet/firmware/tasks/arbiter_task.hpp"
#include "ringlet/firmware/tasks/ball_sensor_task.hpp"
#include "ringlet/firmware/tasks/fsm_task.hpp"
#include "ringlet/firmware/tasks/goals_task.hpp"
#include "ringlet/firmware/tasks/localization_task.hpp"
#include "ringlet/firmware/tasks/plan_record_task.hpp"
#include "ringlet/firmware/tasks/pddl_record_task.hpp"
#include "ringlet/firmware/tasks/pddl_task.hpp"
#include "ringlet/firmware/tasks/planner_task.hpp"
#include "ringlet/firmware/tasks/sense_task.hpp"
#include "ringlet/firmware/tasks/telemetry_task.hpp"
#include "ringlet/firmware/tasks/vision_task.hpp"
#include "ringlet/firmware/tasks/whiteboard_task.hpp"

namespace ringlet::firmware {

const RegisteredTask* TaskRegistry::find(std::string_view name) const noexcept {
  for (const RegisteredTask& t : tasks_) {
    if (t.declaration->name == name) return &t;
  }
  return nullptr;
}

TaskRegistry production_tasks() {
  TaskRegistry registry;
  registry.add<SenseTask>();
  registry.add<SenseNoGpsTask>();
  registry.add<BallSensorTask>();
  registry.add<GoalsTask>();
  registry.add<VisionTask>();
  registry.add<LocalizationTask>();
  registry.add<PlannerTask>();
  registry.add<ArbiterTask>();
  registry.add<FsmTask>();
  registry.add<ActuateTask>();
  registry.add<TelemetryTask>();
  registry.add<PlanRecordTask>();
  registry.add<PddlTask>();
  registry.add<PddlRecordTask>();
  registry.add<WhiteboardTask>();
  return registry;
}

}  // namespace ringlet::firmware
