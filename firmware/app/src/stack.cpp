#include "ringlet/firmware/stack.hpp"

#include <cmath>

#include "ringlet/behaviour/llfsm/providers.hpp"

namespace ringlet::firmware {
namespace {

std::vector<executive::TaskBinding> bind_tasks(const std::vector<executive::TaskSpec>& table,
                                         const std::vector<std::pair<const char*, executive::Task*>>& provided,
                                         const ConfigPositions& at) {
  std::vector<executive::TaskBinding> bound;
  std::vector<std::string> problems;
  for (std::size_t i = 0; i < table.size(); ++i) {
    const auto& spec = table[i];
    executive::Task* task = nullptr;
    for (const auto& [name, impl] : provided) {
      if (spec.name == name) task = impl;
    }
    if (task == nullptr) {
      std::string names;
      for (const auto& p : provided) names += (names.empty() ? "" : ", ") + std::string(p.first);
      const std::string key = "executive.tasks[" + std::to_string(i) + "].name";
      problems.push_back(at.at(key) + ": " + key + ": task '" + spec.name + "' is not a task this firmware provides (" + names + ")");
    }
    bound.push_back({spec, task});
  }
  for (const auto& [name, impl] : provided) {
    bool listed = false;
    for (const auto& spec : table) listed = listed || spec.name == name;
    if (!listed) problems.push_back("task '" + std::string(name) + "' is missing from the table: every task must be scheduled");
  }
  if (!problems.empty()) {
    throw ConfigError(at.at("executive.tasks") + ": executive.tasks: the table does not match the firmware's tasks:" +
                      executive::list_problems(problems));
  }
  return bound;
}

// Deep enough that a tool polling every few milliseconds sees every FsmStatus of a frame.
constexpr std::size_t kWhiteboardGenerations = 64;

}  // namespace

FirmwareStack::FirmwareStack(const FirmwareConfig& config)
    : config_(config),
      robot_(make_robot(config_)),
      sim_(dynamic_cast<const sim_hal::SimRobot*>(robot_.get())),
      board_(kWhiteboardGenerations),
      fsm_status_log_(std::make_unique<FsmStatusLog>()),
      mission_(mission_goals(*robot_), config_.goal_tolerance, config_.follower),
      telemetry_(static_cast<std::size_t>(trajectory_samples(config_, config_.timeout_s)), 1024, mission_.goal_count()),
      ball_tracker_(board_),
      mission_machine_(board_, mission_),
      safety_(board_, config_.safety.stop_range, config_.safety.release_range, config_.safety.hold_ms),
      fsm_bus_(board_),
      schedule_(stopwatch_, &fsm_bus_),
      camera_(robot_->camera()),
      owned_camera_(make_camera(config_, clock())),
      sense_(robot_->sensors(), state_, board_, sim_, !config_.camera.enabled),
      fsm_(schedule_),
      actuate_(robot_->actuators(), board_),
      telemetry_task_(telemetry_, mission_, mission_machine_, state_, config_.trajectory_every),
      whiteboard_task_(board_) {
  // Schedule order is the order of the machines' writes within a turn: Safety runs last, twice,
  // so that the turn that sees an obstacle also posts the stop that stands (safety.machine).
  schedule_.add(ball_tracker_);
  schedule_.add(mission_machine_);
  schedule_.add(safety_, 2);
  if (const auto report = behaviour::llfsm::check_providers(schedule_, kTaskProvidedTypes); !report.ok()) {
    throw ConfigError(config_.source.string() + ": machines: " + report.describe());
  }
  board_.subscribe<wb::FsmStatus>([this](const wb::FsmStatus& status) {
    ++fsm_status_seen_;
    (void)fsm_status_log_->push(status);
  });
  schedule_.start();

  std::vector<std::pair<const char*, executive::Task*>> provided{{"sense", &sense_},
                                                                  {"fsm", &fsm_},
                                                                  {"actuate", &actuate_},
                                                                  {"telemetry", &telemetry_task_},
                                                                  {"whiteboard", &whiteboard_task_}};
  if (config_.camera.enabled) {
    if (owned_camera_) camera_ = owned_camera_.get();
    if (camera_ == nullptr) throw ConfigError(config_.positions.at("camera.enabled") + ": camera.enabled: the backend has no camera");
    pipeline_ = make_vision(config_);
    const VisionDeadline deadline = config_.clock == ClockMode::kLockstep ? VisionDeadline::kNone
                                    : config_.executive.overrun_on_cpu_time ? VisionDeadline::kCpu
                                                                            : VisionDeadline::kWall;
    vision_task_.emplace(*camera_, *pipeline_, state_, board_, deadline);
    provided.emplace_back("vision", &*vision_task_);
  }
  auto tasks = bind_tasks(config_.tasks, provided, config_.positions);
  // Lockstep is a pure function of seed and configuration: there the policies act on the tasks'
  // modelled costs, and what the host measured is reported beside them.
  executive::ExecutiveConfig exec_config = config_.executive;
  exec_config.judge_on_model = config_.clock == ClockMode::kLockstep;
  executive_ = std::make_unique<executive::Executive>(exec_config, std::move(tasks), clock(), stopwatch_,
                                                      robot_->actuators(), &events_);
  whiteboard_task_.attach(*executive_);
}

FirmwareStack::~FirmwareStack() = default;

hal::Clock& FirmwareStack::clock() noexcept {
  if (config_.clock == ClockMode::kRealtime) return monotonic_clock_;
  return virtual_clock_;
}

std::uint64_t FirmwareStack::frames_for(double seconds) const noexcept {
  return static_cast<std::uint64_t>(std::ceil(seconds * 1e9 / static_cast<double>(config_.executive.period.count())));
}

}  // namespace ringlet::firmware
