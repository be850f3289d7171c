#include "ringlet/vision/pipeline.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "ringlet/vision/cost_model.hpp"
#include "ringlet/vision/horizon.hpp"

namespace ringlet::vision {
namespace {

// Within max_slant (horizontal px per vertical px) of the image's vertical: a line running away
// from the camera, or something standing.
bool upright(const FieldLine& f, double max_slant) noexcept {
  return std::abs(f.image_end.u - f.image_start.u) <= max_slant * std::abs(f.image_end.v - f.image_start.v);
}

// How many classifier windows fit in the modelled budget after the work counted in `spent` (at
// most `wanted`), the windows counted in `spent.*windows` (its ball or robot windows). The
// model's own sum, so the frame's modelled cost never exceeds the budget on their account; with
// no budget (the default) every wanted window fits.
int windows_within(WorkCount spent, std::int64_t WorkCount::*windows, hal::Nanos model_budget, int wanted) noexcept {
  int fit = 0;
  while (fit < wanted) {
    spent.*windows = fit + 1;
    if (modelled_cost(spent) > model_budget) break;
    ++fit;
  }
  return fit;
}

// How many more point tests the modelled budget leaves after `spent` (the marks' share).
std::int64_t point_tests_within(const WorkCount& spent, hal::Nanos model_budget) noexcept {
  if (model_budget == hal::Nanos::max()) return std::numeric_limits<std::int64_t>::max();
  const CostModel model = default_cost_model();
  const double left_ns = static_cast<double>((model_budget - modelled_cost(spent)).count()) - 2.0;  // rounding
  const double per_test_ns = model.per_point_test_ns * model.board_slowdown;
  return left_ns <= 0.0 ? 0 : static_cast<std::int64_t>(std::floor(left_ns / per_test_ns));
}

}  // namespace

std::size_t drop_robot_legs(std::span<FieldLine> lines, std::size_t count, const RobotList& robots,
                            double max_slant) noexcept {
  if (max_slant < 0.0) return count;
  const auto inside = [](const hal::Pixel& p, const RobotDetection& d) {
    return p.u >= d.left && p.u <= d.left + d.width && p.v >= d.top && p.v <= d.top + d.height;
  };
  return drop_lines(lines, count, [&](const FieldLine& f) {
    if (!upright(f, max_slant)) return false;
    for (std::size_t j = 0; j < robots.count; ++j) {
      const RobotDetection& d = robots.robots[j];
      if (d.verified && inside(f.image_start, d) && inside(f.image_end, d)) return true;
    }
    return false;
  });
}

std::size_t drop_standing_objects(std::span<FieldLine> lines, std::size_t count, const hal::FrameView& frame,
                                  double max_slant, int reach_px) noexcept {
  if (reach_px <= 0 || max_slant < 0.0 || frame.data == nullptr) return count;
  constexpr int kStep = 6;       // px between the samples above the top end
  constexpr int kDarker = 25;    // a sample this much darker than the piece's middle is not its band
  const auto luma = [&](double u, double v, int& y) {
    const int x = static_cast<int>(std::floor(u)), r = static_cast<int>(std::floor(v));
    if (x < 0 || x >= frame.width || r < 0 || r >= frame.height) return false;
    y = luma_at(frame, x, r);
    return true;
  };
  return drop_lines(lines, count, [&](const FieldLine& f) {
    const double du = f.image_end.u - f.image_start.u, dv = f.image_end.v - f.image_start.v;
    const double len = std::sqrt(du * du + dv * dv);
    int y_mid = 0;
    if (!upright(f, max_slant) || len < 1.0 ||
        !luma((f.image_start.u + f.image_end.u) / 2.0, (f.image_start.v + f.image_end.v) / 2.0, y_mid)) {
      return false;
    }
    const hal::Pixel& top = dv < 0.0 ? f.image_end : f.image_start;  // the smaller row
    const double uu = (dv < 0.0 ? du : -du) / len, uv = (dv < 0.0 ? dv : -dv) / len;  // upwards
    int samples = 0, bright = 0;
    for (int d = kStep; d <= reach_px; d += kStep) {
      int y = 0;
      if (!luma(top.u + uu * d, top.v + uv * d, y)) break;
      ++samples;
      bright += y >= y_mid - kDarker ? 1 : 0;
    }
    return samples >= 2 && bright == samples;
  });
}

VisionPipeline::VisionPipeline(const VisionConfig& config, ColourTable table)
    : config_(config),
      table_(std::move(table)),
      field_colour_(config.adaptive),
      adaptive_(config.adaptive),
      classes_(config.intrinsics.width, config.intrinsics.height),
      first_row_(static_cast<std::size_t>(std::max(config.intrinsics.width, 0)), 0),
      scanner_(config.intrinsics.width),
      candidates_(config.max_candidates),
      ransac_(config.ransac, config.max_candidates),
      circle_(config.ransac.circle, config.max_candidates),
      marks_(config.marks, config.max_candidates),
      ball_(config.ball, config.intrinsics.width, config.intrinsics.height),
      bw_ball_(config.bw_ball),
      robots_(config.robot) {}

std::string VisionPipeline::set_classifier(HogSvm model) {
  if (std::string e = model.validate(); !e.empty()) return std::string("hog model: ") + e;
  if (model.target() == HogTarget::kBall) {
    ball_svm_.emplace(std::move(model));
  } else {
    robot_svm_.emplace(std::move(model));
  }
  return {};
}

const VisionResult& VisionPipeline::process(const hal::FrameView& frame, const hal::CameraPosture& posture,
                                            const Deadline& deadline, int degrade_level) noexcept {
  VisionResult& r = result_;
  r = VisionResult{};
  r.sequence = frame.sequence;
  r.capture_time = frame.capture_time;
  r.posture = posture;
  r.degrade_level = std::clamp(degrade_level, 0, kDegradeLevels - 1);
  const DegradeProfile& level = config_.degrade[static_cast<std::size_t>(r.degrade_level)];
  const hal::CameraIntrinsics& k = config_.intrinsics;
  if (frame.width != k.width || frame.height != k.height || frame.data == nullptr) {
    r.status = VisionStatus::kBadFrame;
    return r;
  }

  const hal::Nanos start = deadline.now();
  hal::Nanos mark = start;
  const auto lap = [&](Stage stage) {
    const hal::Nanos now = deadline.now();
    r.stage_time[static_cast<std::size_t>(stage)] = now - mark;
    mark = now;
  };
  // True when the stage may run; otherwise records it as skipped.
  const auto may_run = [&](Stage stage) {
    if (!deadline.expired()) return true;
    r.cut.deadline_hit = true;
    r.cut.stages_skipped = static_cast<std::uint8_t>(r.cut.stages_skipped | (1U << static_cast<unsigned>(stage)));
    return false;
  };

  const hal::CameraPose pose = hal::CameraPose::from_posture(config_.mount, posture);
  r.horizon_row = horizon_rows(k, pose, config_.horizon_margin_px, first_row_);
  lap(Stage::kHorizon);

  // Work is counted from the frame's geometry and the levels, so the count (and the modelled
  // cost) is the same whichever clock is running.
  const std::int64_t ground_pixels =
      static_cast<std::int64_t>(k.width) * std::max<std::int64_t>(0, k.height - r.horizon_row);
  bool classified = false;
  if (may_run(Stage::kClassify)) {
    // Adaptive: the field colour from this frame's samples below the horizon (smoothed over frames),
    // then the small per-frame tables; the static table when no field colour is known.
    if (config_.colour_mode == ColourMode::kAdaptive) {
      r.field_colour = field_colour_.update(frame, first_row_);
      r.work.colour_samples = r.field_colour.samples;
      if (r.field_colour.valid) {
        adaptive_.build(r.field_colour, k.width, k.height);
        r.work.colour_rebuilds = 1;
      }
    }
    classified = r.field_colour.valid ? classes_.classify(frame, adaptive_, r.horizon_row, level.class_step)
                                      : classes_.classify(frame, table_, r.horizon_row, level.class_step);
    if (classified) r.work.classified_pixels = ground_pixels / (level.class_step * level.class_step);
    lap(Stage::kClassify);
  }
  // The black-and-white ball's candidates here; their classification comes after the lines.
  bool balls_to_verify = false;
  if (classified && may_run(Stage::kBall)) {
    if (config_.ball.mode == BallMode::kBlackWhite) {
      balls_to_verify = ball_svm_.has_value() && level.ball_classify > 0;
      bw_ball_.propose(classes_, frame, k, pose, level.ball_stride, balls_to_verify, r.balls);
      if (r.balls.count > 0) r.ball = r.balls.balls[0];
    } else {
      r.ball = ball_.detect(classes_, k, pose, level.ball_stride);
      if (r.ball.seen) {
        r.balls.balls[0] = r.ball;
        r.balls.count = 1;
      }
    }
    // The seeds, plus what the black-and-white ball's outlines and contrasts read.
    r.work.ball_samples = ground_pixels / (level.ball_stride * level.ball_stride) + r.balls.refine_samples;
    lap(Stage::kBall);
  }
  // The robot stage needs its classifier: unverified candidates (tall non-field runs) were robots
  // at precision 0.089 on the seed-303 test set, not worth their ~0.2 ms on the board. Here the
  // candidates; their classification comes last (below).
  bool robots_proposed = false;
  if (classified && config_.robots && robot_svm_ && may_run(Stage::kRobots)) {
    // Robot columns twice as far apart as the ball's seeds: a NAO is ~27 px wide even 6 m away,
    // so 8 px columns still cross it three times, at half the scan's cost.
    const int robot_stride = 2 * level.ball_stride;
    robots_.propose(classes_, k, pose, robot_stride, r.robots);
    // Columns every robot stride (rounded to the class step), every classified row.
    const int step = level.class_step;
    const int columns_stride = std::max(step, (std::max(robot_stride, 1) + step - 1) / step * step);
    r.work.robot_samples = ground_pixels / (static_cast<std::int64_t>(columns_stride) * step);
    robots_proposed = true;
    lap(Stage::kRobots);
  }
  bool scanned = false;
  bool ransac_ran = false;
  if (classified && may_run(Stage::kScan)) {
    ScanParams scan = config_.scan;
    scan.stride = level.scan_stride;
    r.scan = scanner_.scan(classes_, frame, k, pose, first_row_, scan, candidates_);
    r.candidates = static_cast<int>(candidates_.size());
    r.candidates_dropped = static_cast<int>(candidates_.dropped());
    r.work.scanned_pixels = 2 * ground_pixels / level.scan_stride;  // vertical and horizontal lines
    r.work.candidates = r.candidates;
    scanned = true;
    lap(Stage::kScan);
  }
  // The centre circle first, on every candidate: its arcs would otherwise become short lines.
  if (scanned && may_run(Stage::kCircle)) {
    r.circle = circle_.find(candidates_.points(), frame.sequence, config_.ransac.seed, deadline, r.circle_stats,
                            level.circle_trials);
    // Each trial walks its sample three times (one to pick the second point, one per centre).
    r.work.circle_tests = 3 * static_cast<std::int64_t>(r.circle_stats.trials_run) * r.circle_stats.points_used;
    if (r.circle_stats.trials_skipped > 0) r.cut.deadline_hit = true;
    lap(Stage::kCircle);
  }
  if (scanned && may_run(Stage::kRansac)) {
    LineSet lines;
    const CentreCircle known = r.circle;
    const LineCheck check(classes_, k, pose, config_.line_check);
    ransac_.find(candidates_.points(), frame.sequence, k, pose, deadline, lines, level.max_trials, level.max_lines,
                 level.ransac_skip, level.scan_stride, &known, &check, point_tests_within(r.work, deadline.model_budget));
    r.lines = lines.lines;
    r.line_count = lines.count;
    r.circle = lines.circle;
    r.ransac = lines.stats;
    // Each trial tests its sample's points, after drawing its second point (a draw tests one).
    r.work.point_tests +=
        static_cast<std::int64_t>(lines.stats.trials_run) * lines.stats.points_used + lines.stats.partner_draws;
    r.cut.trials_skipped = lines.stats.trials_skipped;
    r.cut.lines_not_extracted = lines.stats.stopped_early;
    r.cut.points_left = lines.stats.points_left;
    if (lines.stats.stopped_early) r.cut.deadline_hit = true;
    const std::size_t kept = r.line_count;
    r.line_count = drop_standing_objects(r.lines, r.line_count, frame, config_.robot_leg_max_slant, config_.standing_reach_px);
    r.standing_dropped = static_cast<int>(kept - r.line_count);
    ransac_ran = true;
    lap(Stage::kRansac);
  }
  // The classifiers after the lines, so that a short frame gives them up first, whether the clock
  // runs out (the deadline is checked before each window) or, in lockstep, the modelled budget,
  // which everything before has been counted against. The ball's first: the marks keep clear of
  // the verified balls.
  if (balls_to_verify) {
    const hal::Nanos started = deadline.now();
    const int windows = windows_within(r.work, &WorkCount::ball_windows, deadline.model_budget, level.ball_classify);
    bw_ball_.verify(frame, k, pose, *ball_svm_, level.ball_classify, windows, deadline, r.balls);
    r.ball = r.balls.count > 0 ? r.balls.balls[0] : BallDetection{};
    r.cut.classifications_cut += r.balls.classifications_cut;
    if (r.balls.classifications_cut > 0) r.cut.deadline_hit = true;
    r.work.ball_windows = r.balls.classified;
    r.stage_time[static_cast<std::size_t>(Stage::kBall)] += deadline.now() - started;
  }
  // The crosses from what the lines, the circle and the balls leave over (bounded, no trials),
  // within what the modelled budget leaves them.
  if (ransac_ran) {
    const hal::Nanos started = deadline.now();
    marks_.find(candidates_.points(), std::span<const FieldLine>(r.lines.data(), r.line_count), r.circle,
                std::span<const BallDetection>(r.balls.balls.data(), r.balls.count), classes_, k, pose, deadline,
                r.marks, point_tests_within(r.work, deadline.model_budget));
    r.work.point_tests += r.marks.tests;
    if (r.marks.stopped_early) r.cut.deadline_hit = true;
    r.stage_time[static_cast<std::size_t>(Stage::kRansac)] += deadline.now() - started;
  }
  // The robot classifications last: they are what a short frame gives up first, whether the clock
  // runs out (the deadline is checked before each window) or, in lockstep, the modelled budget,
  // which everything else has already been counted against. Then the legs of the robots found
  // are taken out of the lines (a filter of each line on its own: its place after the marks
  // changes which lines remain only in that the marks still saw them).
  if (robots_proposed) {
    const hal::Nanos started = deadline.now();
    const int windows = windows_within(r.work, &WorkCount::robot_windows, deadline.model_budget, level.robot_classify);
    robots_.report(frame, k, pose, &*robot_svm_, level.robot_classify, windows, deadline, r.robots);
    r.cut.classifications_cut += r.robots.classifications_cut;
    if (r.robots.classifications_cut > 0) r.cut.deadline_hit = true;
    r.work.robot_windows = r.robots.classified;
    const std::size_t reported = r.line_count;
    r.line_count = drop_robot_legs(r.lines, r.line_count, r.robots, config_.robot_leg_max_slant);
    r.robot_legs_dropped = static_cast<int>(reported - r.line_count);
    r.stage_time[static_cast<std::size_t>(Stage::kRobots)] += deadline.now() - started;
  }
  if (!classified) {  // later stages depend on the classes
    for (const Stage s : {Stage::kBall, Stage::kRobots, Stage::kScan, Stage::kCircle, Stage::kRansac}) {
      r.cut.stages_skipped = static_cast<std::uint8_t>(r.cut.stages_skipped | (1U << static_cast<unsigned>(s)));
    }
  } else if (!scanned) {
    for (const Stage s : {Stage::kCircle, Stage::kRansac}) {
      r.cut.stages_skipped = static_cast<std::uint8_t>(r.cut.stages_skipped | (1U << static_cast<unsigned>(s)));
    }
  }
  r.total_time = deadline.now() - start;
  return r;
}

}  // namespace ringlet::vision
