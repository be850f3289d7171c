#include "ringlet/firmware/stack.hpp"

#include <cmath>
#include <iostream>
#include <utility>

#include "ringlet/firmware/backend_factory.hpp"
#include "ringlet/firmware/contract_check.hpp"

namespace ringlet::firmware {
namespace {

// Deep enough that a tool polling every few milliseconds sees every FsmStatus of a frame, and
// that vision finds the head posture of a frame captured a few periods ago.
constexpr std::size_t kWhiteboardGenerations = 64;

// The registered task of every table row, in table order; a name the registry does not know is
// refused with the row's place and the names it does know.
std::vector<const RegisteredTask*> tasks_of_table(const FirmwareConfig& config, const TaskRegistry& registry) {
  std::vector<const RegisteredTask*> out;
  std::vector<std::string> problems;
  for (std::size_t i = 0; i < config.tasks.size(); ++i) {
    const RegisteredTask* task = registry.find(config.tasks[i].name);
    if (task == nullptr) {
      std::string names;
      for (const auto& t : registry.tasks()) names += (names.empty() ? "" : ", ") + std::string(t.declaration->name);
      const std::string key = "executive.tasks[" + std::to_string(i) + "].name";
      problems.push_back(config.positions.at(key) + ": " + key + ": task '" + config.tasks[i].name +
                         "' is not a task this firmware has (" + names + ")");
    }
    out.push_back(task);
  }
  if (!problems.empty()) {
    throw ConfigError(config.positions.at("executive.tasks") + ": executive.tasks: the table names unknown tasks:" +
                      executive::list_problems(problems));
  }
  return out;
}

// --record: the robot's HAL inputs to a log. In lockstep nothing is lost (the cycle waits for the
// writer, which only costs host time); on the real clock a full queue drops and counts.
std::unique_ptr<hal::RecordingRobot> make_recorder(const FirmwareConfig& config, hal::Robot& robot) {
  if (config.record_log.empty()) return nullptr;
  if (config.task("vision") != nullptr && config.camera.backend != "robot") {
    throw ConfigError("--record: records the robot's own camera only; camera.backend is \"" + config.camera.backend +
                      "\" (" + config.positions.at("camera.backend") + ")");
  }
  hal::RecordingOptions options;
  options.mode = config.clock == ClockMode::kLockstep ? hal::RecordMode::kLossless : hal::RecordMode::kDropOnFull;
  options.period = config.executive.period;
  options.note = "ringlet --config " + config.source.string();
  if (robot.camera() != nullptr) {
    options.max_camera_frame_bytes =
        hal::camera_frame_bytes(config.camera.format, static_cast<std::size_t>(config.camera.intrinsics.width),
                                static_cast<std::size_t>(config.camera.intrinsics.height));
  }
  try {
    return std::make_unique<hal::RecordingRobot>(robot, config.record_log, options);
  } catch (const hal::LogError& e) {
    throw ConfigError(std::string("--record: ") + e.what());
  }
}

std::unique_ptr<wb::MessageLogger> make_message_log(const FirmwareConfig& config, wb::Whiteboard& board) {
  if (config.whiteboard_log.empty()) return nullptr;
  const auto mode = config.clock == ClockMode::kLockstep ? wb::MessageLogMode::kLossless : wb::MessageLogMode::kDropOnFull;
  try {
    return std::make_unique<wb::MessageLogger>(board, config.whiteboard_log, wb::MessageLogOptions{mode});
  } catch (const std::runtime_error& e) {
    throw ConfigError(std::string("--wb-log: ") + e.what());
  }
}

}  // namespace

FirmwareStack::FirmwareStack(const FirmwareConfig& config, const TaskRegistry& registry,
                             OpenCvCameraMaker opencv_camera)
    : FirmwareStack(config, make_robot(config), registry, opencv_camera) {}

FirmwareStack::FirmwareStack(const FirmwareConfig& config, std::unique_ptr<hal::Robot> backend,
                             const TaskRegistry& registry, OpenCvCameraMaker opencv_camera)
    : config_(config),
      robot_(std::move(backend)),
      recorder_(make_recorder(config_, *robot_)),
      board_(kWhiteboardGenerations),
      fsm_status_log_(std::make_unique<FsmStatusLog>()),
      message_log_(make_message_log(config_, board_)),
      telemetry_(static_cast<std::size_t>(trajectory_samples(config_, config_.mission.timeout_s)), 1024),
      ball_tracker_(board_),
      mission_machine_(board_, config_.follower),
      navigate_machine_(board_),
      plan_execute_(board_, config_.pddl.machine),
      safety_(board_, config_.safety.stop_range, config_.safety.release_range, config_.safety.hold_ms),
      fsm_bus_(board_),
      schedule_(stopwatch_, &fsm_bus_),
      owned_camera_(make_camera(config_, clock(), opencv_camera)) {
  // Schedule order is the order of the machines' writes within a turn: Safety runs last, twice,
  // so that the turn that sees an obstacle also posts the stop that stands (safety.machine).
  // The mission is driven by one machine: straight at the goals (Mission), or through the planner
  // and the arbiter (Navigate); no task writes MotionCommand, so Safety's word is the last.
  // A robot without a head camera has no ball to follow: no BallTracker, so nothing need provide
  // BallBelief and the head is not commanded.
  if (config_.mission.ball_tracking) schedule_.add(ball_tracker_);
  if (config_.mission.drive == DriveMode::kNavigate) {
    schedule_.add(navigate_machine_);
  } else if (config_.mission.drive == DriveMode::kPddl) {
    schedule_.add(plan_execute_);
  } else {
    schedule_.add(mission_machine_);
  }
  schedule_.add(safety_, 2);

  const std::vector<const RegisteredTask*> table = tasks_of_table(config_, registry);
  std::vector<const TaskDeclaration*> declarations;
  for (const RegisteredTask* t : table) declarations.push_back(t->declaration);
  check_contracts(config_, declarations, schedule_);

  if (config_.remote.enabled) {
    check_remote_writers(config_, declarations, schedule_);
    std::vector<std::string> machines;
    for (std::size_t i = 0; i < schedule_.size(); ++i) machines.emplace_back(schedule_.machine(i).name());
    remote_ = std::make_unique<RemoteLink>(config_, board_, std::move(machines), std::cerr);
  }
  board_.subscribe<wb::FsmStatus>([this](const wb::FsmStatus& status) {
    ++fsm_status_seen_;
    (void)fsm_status_log_->push(status);
  });
  hal::Robot& robot = this->robot();
  hal::Camera* camera = owned_camera_ ? owned_camera_.get() : robot.camera();
  if (config_.planner.records()) experiences_.reserve(static_cast<std::size_t>(config_.planner.capacity));
  TaskServices services{config_,         robot,           camera, board_, schedule_, telemetry_, executive_view_,
                        message_log_.get(), remote_ ? remote_->inbox() : nullptr, &experiences_};
  std::vector<executive::TaskBinding> bindings;
  for (std::size_t i = 0; i < table.size(); ++i) {
    tasks_.push_back(table[i]->make(services));
    bindings.push_back({config_.tasks[i], tasks_.back().get()});
  }
  schedule_.start();
  // Lockstep is a pure function of seed and configuration: there the policies act on the tasks'
  // modelled costs, and what the host measured is reported beside them.
  executive::ExecutiveConfig exec_config = config_.executive;
  exec_config.judge_on_model = config_.clock == ClockMode::kLockstep;
  executive_ = std::make_unique<executive::Executive>(exec_config, std::move(bindings), clock(), stopwatch_,
                                                      robot.actuators(), &events_);
  executive_view_ = executive_.get();
  if (const hal::GroundTruth* truth = robot_->ground_truth()) {
    truth_score_.emplace(*truth, board_, &telemetry_, config_.trajectory_every);
    executive_->set_observer(&*truth_score_);
  }
  if (remote_) {
    remote_->set_next(truth_score_ ? &*truth_score_ : nullptr);
    executive_->set_observer(remote_.get());
  }
}

FirmwareStack::~FirmwareStack() = default;

std::vector<std::string> FirmwareStack::finish_logs() noexcept {
  std::vector<std::string> problems;
  if (recorder_) {
    const hal::RecordingStatus s = recorder_->stop();
    if (!s.ok()) problems.push_back(s.error);
    if (s.dropped > 0) {
      problems.push_back("--record: " + std::to_string(s.dropped) + " records dropped (the writer fell behind)");
    }
  }
  if (message_log_) {
    const wb::MessageLogStatus s = message_log_->stop();
    if (!s.ok()) problems.push_back(s.error);
    if (s.dropped > 0) {
      problems.push_back("--wb-log: " + std::to_string(s.dropped) + " messages dropped (the writer fell behind)");
    }
  }
  return problems;
}

hal::Clock& FirmwareStack::clock() noexcept {
  if (config_.clock == ClockMode::kRealtime) return monotonic_clock_;
  return virtual_clock_;
}

std::uint64_t FirmwareStack::frames_for(double seconds) const noexcept {
  return static_cast<std::uint64_t>(std::ceil(seconds * 1e9 / static_cast<double>(config_.executive.period.count())));
}

}  // namespace ringlet::firmware
