#include "ringlet/firmware/tasks.hpp"

#include <cmath>
#include <limits>

#include "ringlet/executive/executive.hpp"
#include "ringlet/vision/messages.hpp"

namespace ringlet::firmware {
namespace {

// The nearest valid return of a scan, bearing in the robot frame (left positive, like
// hal::RobotPoint; the laser's own angles are positive to the right).
wb::LaserSummary summarize(const hal::LaserScan& scan) noexcept {
  wb::LaserSummary s{};
  s.nearest_range = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < scan.beam_count; ++i) {
    if (!scan.valid[i]) continue;
    ++s.valid_beams;
    const double range = static_cast<double>(scan.range[i]);
    if (range < s.nearest_range) {
      s.nearest_range = range;
      s.nearest_bearing = -scan.beam_angle(i);
    }
  }
  if (s.valid_beams == 0) s.nearest_range = scan.max_range;  // nothing within range
  return s;
}

}  // namespace

void SenseTask::run(const executive::TaskContext& /*ctx*/) noexcept {
  state_.sensors_ok = sensors_.read(state_.sensors);
  const auto& frame = state_.sensors;
  board_.post(wb::Pose{frame.pose.pose.x, frame.pose.pose.y, frame.pose.pose.theta,
                       state_.sensors_ok && frame.pose.valid});
  board_.post(summarize(frame.laser));
  state_.head_history.record(frame.stamp, frame.head);
  if (truth_ != nullptr) state_.true_ball = truth_->true_ball_in_robot_frame();
  if (post_true_ball_) {
    wb::BallBelief ball{};
    ball.visible = state_.true_ball.has_value();
    if (state_.true_ball) {
      ball.x = state_.true_ball->x;
      ball.y = state_.true_ball->y;
      ball.confidence = 1.0;
    }
    ball.simulated = true;  // ground truth, not a detection
    board_.post(ball);
  }
}

void VisionTask::run(const executive::TaskContext& ctx) noexcept {
  hal::FrameView frame;
  cost_ = task_costs::kVisionNoFrame;
  if (!camera_.grab_latest(frame) || (have_frame_ && frame.sequence == last_sequence_)) return;
  if (have_frame_ && frame.sequence > last_sequence_ + 1) stats_.missed_frames += frame.sequence - last_sequence_ - 1;
  have_frame_ = true;
  last_sequence_ = frame.sequence;
  const vision::Deadline deadline =
      deadline_ == VisionDeadline::kNone
          ? vision::Deadline{}
          : vision::Deadline::after(*ctx.stopwatch, ctx.time_left(), deadline_ == VisionDeadline::kCpu);
  const vision::VisionResult& r =
      pipeline_.process(frame, state_.head_history.at(frame.capture_time), deadline, ctx.degrade_level);
  ++stats_.frames;
  cost_ = task_costs::kVisionNoFrame + vision::modelled_cost(r.work);
  if (r.status != vision::VisionStatus::kOk) {
    ++stats_.bad_frames;
    return;
  }
  stats_.lines += r.line_count;
  if (r.line_count > 0) ++stats_.with_lines;
  if (r.ball.seen) ++stats_.with_ball;
  if (r.cut.deadline_hit) ++stats_.cut;
  if (r.degrade_level > 0) ++stats_.degraded;
  board_.post(vision::to_field_lines(r));
  board_.post(vision::to_ball_belief(r));
}

void FsmTask::run(const executive::TaskContext& ctx) noexcept { schedule_.run_turn(ctx.now); }

Nanos FsmTask::modelled_cost() const noexcept {
  std::int64_t ringlets = 0;
  for (std::size_t i = 0; i < schedule_.size(); ++i) ringlets += schedule_.ringlets_per_turn(i);
  return task_costs::kFsmTurn + ringlets * task_costs::kFsmPerRinglet;
}

void ActuateTask::run(const executive::TaskContext& /*ctx*/) noexcept {
  const auto motion = board_.get<wb::MotionCommand>();
  const auto head = board_.get<wb::HeadCommand>();
  hal::ActuatorCommand cmd;
  cmd.drive = {motion.curvature, motion.stop ? 0.0 : motion.velocity};
  cmd.head = {head.yaw, head.pitch};
  actuators_.write(cmd);
}

void TelemetryTask::run(const executive::TaskContext& ctx) noexcept {
  const auto& pose = state_.sensors.pose.pose;
  if (state_.sensors.pose.valid && ctx.frame % every_ == 0) telemetry_.record_pose(pose);
  if (state_.sensors.collided && !was_colliding_) telemetry_.record_collision(pose);
  was_colliding_ = state_.sensors.collided;
  telemetry_.record_goal(mission_.goals_reached(), state_.sensors.stamp);
  if (state_.true_ball) telemetry_.record_head(state_.sensors.head, *state_.true_ball, ctx.frame_start);
  if (machine_.current_state() == behaviour::machines::Mission::kStateDone) {
    telemetry_.record_pose(pose);  // end the trajectory where the mission ended
    ctx.request_stop();
  }
}

void WhiteboardTask::run(const executive::TaskContext& ctx) noexcept {
  board_.dispatch();
  const auto per_second = static_cast<std::uint64_t>(std::chrono::seconds{1} / ctx.period);
  if (executive_ == nullptr || per_second == 0 || ctx.frame % per_second != 0) return;
  wb::ExecutiveTiming t{};
  const auto& frames = executive_->frame_stats();
  t.frames = frames.frames;
  t.frame_overruns = frames.frame_overruns;
  t.slips = frames.slips;
  const auto stats = executive_->task_stats();
  t.task_count = static_cast<std::uint16_t>(std::min(stats.size(), t.task_worst_ns.size()));
  for (std::size_t i = 0; i < t.task_count; ++i) t.task_worst_ns[i] = stats[i].wall.max().count();
  board_.post(t);
}

}  // namespace ringlet::firmware
