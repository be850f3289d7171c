#include "ringlet/firmware/tasks/vision_task.hpp"

#include <cmath>

#include "ringlet/vision/cost_model.hpp"
#include "ringlet/vision/messages.hpp"
#include "ringlet/vision/stages.hpp"

namespace ringlet::firmware {

namespace {

// Loads the HOG/SVM model `file` (when set) and installs it as the pipeline's `target` classifier;
// a missing, corrupt or wrong-target file is a ConfigError naming the key, where it was written,
// and the file (the loader's message names it).
void install_model(vision::VisionPipeline& pipeline, const FirmwareConfig& config, const std::string& key,
                   const std::filesystem::path& file, vision::HogTarget target) {
  if (file.empty()) return;
  const std::string at = config.positions.at(key) + ": " + key + ": ";
  vision::HogSvmLoad loaded = vision::HogSvm::load(file);
  if (!loaded.model) throw ConfigError(at + loaded.error);
  if (loaded.model->target() != target) {
    throw ConfigError(at + "hog model " + file.string() + ": is a " + vision::to_string(loaded.model->target()) +
                      " model, not a " + vision::to_string(target) + " model");
  }
  if (std::string why = pipeline.set_classifier(std::move(*loaded.model)); !why.empty()) {
    throw ConfigError(at + file.string() + ": " + why);
  }
}

}  // namespace

std::unique_ptr<vision::VisionPipeline> make_vision(const FirmwareConfig& config) {
  vision::ColourTable table = vision::ColourTable::from_thresholds(vision::ColourThresholds{});
  if (!config.vision.lut.empty()) {
    vision::ColourTableLoad loaded = vision::ColourTable::load(config.vision.lut);
    if (!loaded.table) throw ConfigError(config.positions.at("vision.lut") + ": vision.lut: " + loaded.error);
    table = std::move(*loaded.table);
  }
  vision::VisionConfig v;
  v.intrinsics = config.camera.intrinsics;
  v.mount = config.camera.mount;
  v.ransac.max_trials = config.vision.max_trials;
  v.ransac.skip = config.vision.skip;
  v.ransac.seed = config.vision.seed;
  v.colour_mode = config.vision.colour == "table" ? vision::ColourMode::kTable : vision::ColourMode::kAdaptive;
  v.ball.mode = config.vision.ball == "bw" ? vision::BallMode::kBlackWhite : vision::BallMode::kOrange;
  v.robots = config.vision.robots;
  auto pipeline = std::make_unique<vision::VisionPipeline>(v, std::move(table));
  install_model(*pipeline, config, "vision.ball_model", config.vision.ball_model, vision::HogTarget::kBall);
  install_model(*pipeline, config, "vision.robot_model", config.vision.robot_model, vision::HogTarget::kRobot);
  return pipeline;
}

std::unique_ptr<executive::Task> VisionTask::make(TaskServices& services) {
  const FirmwareConfig& config = services.config;
  if (services.camera == nullptr) {
    throw ConfigError(config.positions.at("executive.tasks") + ": task 'vision': the " +
                      std::string(services.robot.backend_name()) + " backend has no camera (see [camera])");
  }
  const VisionDeadline deadline = config.clock == ClockMode::kLockstep ? VisionDeadline::kNone
                                  : config.executive.overrun_on_cpu_time ? VisionDeadline::kCpu
                                                                          : VisionDeadline::kWall;
  return std::make_unique<VisionTask>(*services.camera, make_vision(config), services.board, deadline,
                                      services.telemetry.enable_vision());
}

VisionTask::VisionTask(hal::Camera& camera, std::unique_ptr<vision::VisionPipeline> pipeline, wb::Whiteboard& board,
                       VisionDeadline deadline, VisionStats& stats) noexcept
    : camera_(camera), pipeline_(std::move(pipeline)), board_(board), deadline_(deadline), stats_(stats) {}

hal::CameraPosture VisionTask::posture_at(hal::Nanos when) const noexcept {
  // The posture (head joints and torso tilt, sensed together) closest to `when`, among the
  // generations the whiteboard still holds (the newest when none is left).
  const std::uint64_t newest = board_.generation<wb::HeadPosture>();
  hal::CameraPosture best{};
  hal::Nanos best_gap = hal::Nanos::max();
  for (std::uint64_t g = newest; g > 0 && newest - g < board_.depth(); --g) {
    const auto r = board_.read<wb::HeadPosture>(g);
    if (!r.ok()) break;
    const hal::Nanos stamp{r.msg.stamp_ns};
    const hal::Nanos gap = stamp > when ? stamp - when : when - stamp;
    if (gap < best_gap) {
      best_gap = gap;
      best.head = {r.msg.yaw, r.msg.pitch};
      // No inertial reading: the torso is taken as upright.
      best.body = r.msg.body_valid ? hal::BodyTilt{r.msg.body_pitch, r.msg.body_roll} : hal::BodyTilt{};
    }
  }
  return best;
}

void VisionTask::record_stage_costs(const vision::WorkCount& work) noexcept {
  // The same model as cost_, row by row: a few multiplications, nothing the run depends on.
  const vision::CostModel model = vision::default_cost_model();
  const auto by_stage = vision::host_cost_by_stage(vision::host_cost(work, model));
  for (std::size_t s = 0; s < vision::kStageCount; ++s) {
    stats_.stage_model[s].record(hal::Nanos{static_cast<std::int64_t>(std::llround(by_stage[s] * model.board_slowdown))});
  }
}

void VisionTask::run(const executive::TaskContext& ctx) noexcept {
  hal::FrameView frame;
  cost_ = kNoFrameCost;
  overloaded_ = false;
  if (!camera_.grab_latest(frame) || (have_frame_ && frame.sequence == last_sequence_)) return;
  if (have_frame_ && frame.sequence > last_sequence_ + 1) stats_.missed_frames += frame.sequence - last_sequence_ - 1;
  have_frame_ = true;
  last_sequence_ = frame.sequence;
  vision::Deadline deadline =
      deadline_ == VisionDeadline::kNone
          ? vision::Deadline{}
          : vision::Deadline::after(*ctx.stopwatch, ctx.time_left(), deadline_ == VisionDeadline::kCpu);
  // Lockstep judges the budget on the modelled cost (run() reports it below): the pipeline fits
  // what it can cut (RANSAC's trials, then the classifications and the marks) to that instead of
  // to a clock. A frame whose line search was cut is no overrun, but the task reports itself
  // overloaded, so that the degrade policy still lowers the next frames' work.
  if (deadline_ == VisionDeadline::kNone) deadline.model_budget = ctx.budget - kNoFrameCost;
  const vision::VisionResult& r = pipeline_->process(frame, posture_at(frame.capture_time), deadline, ctx.degrade_level);
  ++stats_.frames;
  cost_ = kNoFrameCost + vision::modelled_cost(r.work);
  record_stage_costs(r.work);
  overloaded_ = r.cut.lines_cut();
  if (r.status != vision::VisionStatus::kOk) {
    ++stats_.bad_frames;
    return;
  }
  stats_.lines += r.line_count;
  if (r.line_count > 0) ++stats_.with_lines;
  if (r.ball.seen) ++stats_.with_ball;
  if (r.cut.deadline_hit) ++stats_.cut;
  if (r.cut.lines_cut()) ++stats_.lines_cut;
  if (r.degrade_level > 0) ++stats_.degraded;
  board_.post(vision::to_field_lines(r));
  // Black and white: r.ball is the best verified ball whenever the classifier ran (an unverified
  // candidate, confidence ≤ 0.3, only when no model is installed or the degrade level dropped it).
  board_.post(vision::to_ball_belief(r));
  if (pipeline_->config().robots) {
    stats_.robots += r.robots.count;
    board_.post(vision::to_robot_detections(r));
  }
}

}  // namespace ringlet::firmware
