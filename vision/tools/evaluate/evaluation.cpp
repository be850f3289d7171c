#include "evaluation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <numeric>
#include <optional>

#include <opencv2/core.hpp>

#include "dataset_frame.hpp"
#include "frame_identity.hpp"
#include "ringlet/hal/monotonic_clock.hpp"
#include "ringlet/vision/cost_model.hpp"
#include "ringlet/vision/horizon.hpp"
#include "ringlet/vision/pitch_check.hpp"
#include "ringlet/vision/stages.hpp"
#include "vision_io.hpp"

namespace ringlet::vision::evaluate {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const double rank = std::ceil(p / 100.0 * static_cast<double>(values.size()));
  const auto i = static_cast<std::size_t>(std::clamp(rank, 1.0, static_cast<double>(values.size()))) - 1U;
  return values[i];
}

std::size_t DetectorReport::arc_false_positives() const {
  return std::accumulate(per_frame_arcs.begin(), per_frame_arcs.end(), std::size_t{0});
}
std::size_t DetectorReport::frames_with_arc_false_positives() const {
  return static_cast<std::size_t>(std::count_if(per_frame_arcs.begin(), per_frame_arcs.end(), [](std::size_t n) { return n > 0; }));
}
double DetectorReport::median_ms() const { return percentile(time_ms, 50.0); }
double DetectorReport::p99_ms() const { return percentile(time_ms, 99.0); }
double DetectorReport::mean_ms() const {
  if (time_ms.empty()) return 0.0;
  return std::accumulate(time_ms.begin(), time_ms.end(), 0.0) / static_cast<double>(time_ms.size());
}

double EvalReport::measured_over_modelled(double p) const {
  std::vector<double> ratio;
  for (std::size_t i = 0; i < model_host_ms.size() && i < ringlet.time_ms.size(); ++i) {
    if (model_host_ms[i] > 0.0) ratio.push_back(ringlet.time_ms[i] / model_host_ms[i]);
  }
  return percentile(ratio, p);
}

double EvalReport::speed_ratio() const {
  const double r = ringlet.median_ms();
  return r > 0.0 ? baseline.median_ms() / r : 0.0;
}

namespace {

double elapsed_ms(Clock::time_point since) {
  return std::chrono::duration<double, std::milli>(Clock::now() - since).count();
}

bool same_camera(const VisionConfig& c, const DatasetFrame& f) {
  const auto& a = c.intrinsics;
  const auto& b = f.intrinsics;
  return a.width == b.width && a.height == b.height && a.fx == b.fx && a.fy == b.fy && a.cx == b.cx && a.cy == b.cy &&
         c.mount.pivot_height == f.mount.pivot_height && c.mount.forward == f.mount.forward && c.mount.up == f.mount.up &&
         c.mount.pitch == f.mount.pitch;
}

/// The horizon mask the pipeline itself uses (same margin), as the first usable row per column.
std::vector<int> horizon_mask(const DatasetFrame& f, int margin_px) {
  std::vector<int> rows(static_cast<std::size_t>(f.intrinsics.width));
  (void)horizon_rows(f.intrinsics, hal::CameraPose::from_head(f.mount, f.head), margin_px, rows);
  return rows;
}

struct HoughRun {
  std::vector<Segment2> segments;
  double ms = 0.0;
};

/// The frame's modelled host time, whole and by stage, beside the stages' measured times.
void record_model(const VisionResult& result, EvalReport& report) {
  const HostCost c = host_cost(result.work);
  report.model_host_ms.push_back(c.total() / 1e6);
  const std::array<double, kStageCount> modelled_ns = host_cost_by_stage(c);
  for (std::size_t s = 0; s < kStageCount; ++s) {
    report.stage_times[s].measured_ms.push_back(hal::to_seconds(result.stage_time[s]) * 1e3);
    report.stage_times[s].modelled_ms.push_back(modelled_ns[s] / 1e6);
  }
}

HoughRun run_hough(const LoadedFrame& f, const HoughParams& p, int margin_px) {
  // Timed from the horizon on, as the pipeline's time includes its own horizon computation.
  const auto start = Clock::now();
  const std::vector<int> mask = horizon_mask(f.meta, margin_px);
  HoughRun r{detect_hough(f.bgr, mask, p), 0.0};
  r.ms = elapsed_ms(start);
  return r;
}

/// The identity of every frame of a set: its record's seed and index, and its pixels' hash.
FrameSet identify(const std::vector<fs::path>& jsons, const char* role, const fs::path& folder,
                  const std::function<void(const char*, std::size_t, std::size_t)>& progress) {
  FrameSet set{role, folder.string(), {}};
  const std::string stage = std::string("identifying ") + role + " frames";
  for (std::size_t i = 0; i < jsons.size(); ++i) {
    const DatasetFrame meta = load_dataset_frame(jsons[i]);
    set.frames.push_back(frame_id(meta, tools::load_bgr(meta.picture, meta.intrinsics.width, meta.intrinsics.height)));
    if (progress) progress(stage.c_str(), i + 1, jsons.size());
  }
  return set;
}

}  // namespace

EvalReport run_evaluation(const EvalOptions& o) {
  // One thread for OpenCV too: the comparison is per core, as the robot's vision task runs.
  cv::setNumThreads(1);
  EvalReport report;
  report.dataset = o.dataset.string();
  report.lut = o.lut.empty() ? "default thresholds" : o.lut.string();
  report.ransac_seed = o.vision.ransac.seed;
  report.pitch_error_deg = o.pitch_error_deg;
  report.auto_pitch = o.auto_pitch;
  report.match = o.match;
  report.circle_match = o.circle_match;
  report.mark_match = o.mark_match;
  report.ringlet.name = "Ringlet (LUT + scan lines + RANSAC)";
  report.baseline.name = "OpenCV Canny + HoughLinesP";

  std::vector<fs::path> test = list_dataset_frames(o.dataset);
  if (o.max_frames > 0 && test.size() > static_cast<std::size_t>(o.max_frames)) test.resize(static_cast<std::size_t>(o.max_frames));
  std::vector<fs::path> tune;
  const auto wanted = static_cast<std::size_t>(std::max(o.tune_frames, 0));
  if (!o.tune_set.empty()) {
    tune = list_dataset_frames(o.tune_set);
    if (wanted > tune.size()) {
      throw tools::ToolError(o.tune_set.string() + ": " + std::to_string(tune.size()) + " frames, but --tune " +
                             std::to_string(wanted) + " asks for more");
    }
    if (wanted > 0) tune.resize(wanted);
  } else {
    if (wanted >= test.size()) {
      throw tools::ToolError(o.dataset.string() + ": " + std::to_string(test.size()) + " frames, but --tune " +
                             std::to_string(wanted) +
                             " needs more: the frames after the tuning subset are the ones reported on");
    }
    tune.assign(test.begin(), test.begin() + static_cast<std::ptrdiff_t>(wanted));
    test.erase(test.begin(), test.begin() + static_cast<std::ptrdiff_t>(wanted));
  }
  report.tune_frames = tune.size();
  report.report_frames = test.size();
  for (const fs::path& p : test) report.test_frames.push_back(p.filename().string());
  report.frames_total = tune.size() + test.size();
  const ColourTable table = tools::load_table(o.lut);
  std::optional<HogSvm> ball_model, robot_model;
  if (!o.ball_model.empty()) ball_model = tools::load_hog_model(o.ball_model, HogTarget::kBall, "--ball-model");
  if (!o.robot_model.empty()) robot_model = tools::load_hog_model(o.robot_model, HogTarget::kRobot, "--robot-model");
  report.ball_mode = o.vision.ball.mode == BallMode::kBlackWhite ? "bw" : "orange";
  report.ball_model = o.ball_model.empty() ? "none" : o.ball_model.string();
  report.robot_model = o.robot_model.empty() ? "none" : o.robot_model.string();
  report.ball_match = o.ball_match;
  report.robot_match = o.robot_match;
  const int margin = o.vision.horizon_margin_px;

  // Which frames are which, checked before anything is scored.
  std::vector<LoadedFrame> tuning;
  FrameSet tuning_ids{"tuning set", (o.tune_set.empty() ? o.dataset : o.tune_set).string(), {}};
  for (std::size_t i = 0; i < tune.size(); ++i) {
    tuning.push_back(load_frame(tune[i]));
    tuning_ids.frames.push_back(frame_id(tuning.back().meta, tuning.back().bgr));
    if (o.progress) o.progress("loading tuning frames", i + 1, tune.size());
  }
  const FrameSet test_ids = identify(test, "test set", o.dataset, o.progress);
  report.test_set = test_ids.describe();
  std::string checked;
  if (!tuning.empty()) {
    require_disjoint(tuning_ids, test_ids);
    report.tuning_set = tuning_ids.describe();
    checked = "the tuning set";
  }
  for (const fs::path& dir : o.disjoint_from) {
    const FrameSet excluded = identify(list_dataset_frames(dir), "excluded set", dir, o.progress);
    require_disjoint(excluded, test_ids);
    report.excluded_sets.push_back(excluded.describe());
    checked += std::string(checked.empty() ? "" : " and ") + "the excluded set " + dir.string();
  }
  report.disjointness = checked.empty() ? "nothing to check (no tuning, no excluded sets)"
                                        : "the test set shares no frame with " + checked +
                                              " (no equal generator, seed and index; no identical pixels)";

  // Tuning: every candidate on the tuning set (kept in memory: it is read once per candidate).
  if (!tuning.empty()) {
    const std::vector<HoughParams> candidates = HoughParams::candidates();
    for (std::size_t c = 0; c < candidates.size(); ++c) {
      TuningResult t{candidates[c], {}};
      for (const LoadedFrame& f : tuning) {
        const HoughRun r = run_hough(f, t.params, margin);
        t.counts += match_segments(r.segments, f.meta.lines, o.match);
      }
      // Strictly better only: ties keep the earlier (closer to OpenCV's usual) candidate.
      if (report.tuning.empty() || t.counts.f1() > report.tuning[report.chosen].counts.f1()) report.chosen = c;
      report.tuning.push_back(t);
      if (o.progress) o.progress("tuning Hough", c + 1, candidates.size());
    }
    report.hough = report.tuning[report.chosen].params;
  }
  tuning.clear();

  std::unique_ptr<VisionPipeline> pipeline;
  const hal::ThreadStopwatch stopwatch;
  std::vector<Segment2> segments;
  for (std::size_t i = 0; i < test.size(); ++i) {
    const LoadedFrame f = load_frame(test[i]);
    if (!pipeline || !same_camera(pipeline->config(), f.meta)) {
      VisionConfig config = o.vision;
      config.intrinsics = f.meta.intrinsics;
      config.mount = f.meta.mount;
      pipeline = std::make_unique<VisionPipeline>(config, table);
      for (const std::optional<HogSvm>* m : {&ball_model, &robot_model}) {
        if (!*m) continue;
        const std::string why = pipeline->set_classifier(**m);
        if (!why.empty()) throw tools::ToolError((m == &ball_model ? o.ball_model : o.robot_model).string() + ": " + why);
      }
    }
    const hal::FrameView view = yuyv_view(f);
    pipeline->forget_history();  // the test frames are unrelated pictures, not a video
    // A deadline that never comes, on the real clock: it only makes the pipeline time its stages.
    const Deadline laps{&stopwatch, hal::Nanos::max(), false};
    const auto start = Clock::now();
    hal::CameraPosture posture{hal::BodyTilt{}, f.meta.head};
    posture.head.pitch += hal::deg_to_rad(o.pitch_error_deg);
    if (o.auto_pitch) {
      const double given = posture.head.pitch;
      const PitchCorrection c = correct_head_pitch(*pipeline, view, posture);
      posture = c.posture;
      pipeline->forget_history();
      if (c.corrected()) {
        ++report.pitch_corrected;
        report.pitch_abs_error_deg.push_back(std::abs(hal::rad_to_deg(posture.head.pitch - f.meta.head.pitch)));
        report.pitch_correction_deg.push_back(hal::rad_to_deg(posture.head.pitch - given));
      }
    }
    const VisionResult& result = pipeline->process(view, posture, laps);
    report.ringlet.time_ms.push_back(elapsed_ms(start));
    record_model(result, report);
    if (result.status != VisionStatus::kOk) throw tools::ToolError(test[i].string() + ": the pipeline refused the frame");
    segments.clear();
    for (std::size_t l = 0; l < result.line_count; ++l) {
      const FieldLine& line = result.lines[l];
      segments.push_back({line.image_start.u, line.image_start.v, line.image_end.u, line.image_end.v});
    }
    // A cross's bars are painted lines too (the truth lists them): scored as its two bars.
    const hal::CameraPose pose = hal::CameraPose::from_posture(f.meta.mount, posture);  // where the pipeline put them
    for (std::size_t m = 0; m < result.marks.count; ++m) {
      for (const auto& bar : FieldMarkFinder::bars(result.marks.marks[m], o.vision.marks.bar_length_m)) {
        const auto a = hal::project(f.meta.intrinsics, pose, {bar[0].x, bar[0].y, 0.0});
        const auto b = hal::project(f.meta.intrinsics, pose, {bar[1].x, bar[1].y, 0.0});
        if (a && b) segments.push_back({a->u, a->v, b->u, b->v});
      }
    }
    report.ringlet.raw_detections += segments.size();
    report.ringlet.per_frame.push_back(match_segments(segments, f.meta.lines, o.match));
    report.ringlet.segments.push_back(segments);
    report.ringlet.counts += report.ringlet.per_frame.back();
    const CircleCounts frame_circle =
        score_circle({result.circle.seen, result.circle.centre, result.circle.radius_m}, f.meta.rings, o.circle_match);
    report.circle += frame_circle;
    std::vector<hal::RobotPoint> marks;
    for (std::size_t m = 0; m < result.marks.count; ++m) marks.push_back(result.marks.marks[m].centre);
    report.marks += score_marks(marks, f.meta.marks, o.mark_match);
    std::vector<RingImage> rings;
    for (const TruthRing& ring : f.meta.rings) {
      if (ring.visible) rings.push_back(project_ring(ring, f.meta.intrinsics, pose));
    }
    report.rings_visible += rings.empty() ? 0U : 1U;
    if (f.meta.has_objects) {
      ++report.object_frames;
      std::vector<FoundBall> balls;
      for (std::size_t b = 0; b < result.balls.count; ++b) {
        const BallDetection& d = result.balls.balls[b];
        balls.push_back({d.centre.u, d.centre.v, d.ground_valid, d.distance_m});
      }
      report.balls += score_balls(balls, f.meta.balls, o.ball_match);
      std::vector<FoundBall> proposals;
      if (o.vision.ball.mode == BallMode::kBlackWhite) {
        for (const BallCandidate& c : pipeline->ball_candidates()) proposals.push_back({c.centre.u, c.centre.v, false, 0.0});
      }
      report.ball_proposals += score_balls(proposals, f.meta.balls, o.ball_match);
      std::vector<FoundRobot> robots;
      for (std::size_t r = 0; r < result.robots.count; ++r) {
        const RobotDetection& d = result.robots.robots[r];
        robots.push_back({d.left, d.top, d.width, d.height, d.foot.u, d.foot.v, d.distance_m});
      }
      std::vector<RobotMatch> matched;
      report.robots += score_robots(robots, f.meta.robots, f.meta.intrinsics.width, f.meta.intrinsics.height,
                                    o.robot_match, &matched);
      for (const RobotMatch& m : matched) report.robot_matches.push_back({test[i].filename().string(), m});
      std::vector<FoundRobot> robot_proposals;
      if (result.robots.candidates > 0) {
        for (const RobotCandidate& c : pipeline->robot_candidates()) {
          const RobotBox b = robot_box(c, pipeline->robot_candidate_step(), o.vision.robot);
          robot_proposals.push_back({b.left, b.top, b.width, b.height, b.foot.u, b.foot.v, 0.0});
        }
      }
      report.robot_proposals += score_robots(robot_proposals, f.meta.robots, f.meta.intrinsics.width,
                                             f.meta.intrinsics.height, o.robot_match);
    }
    const auto count_arcs = [&](DetectorReport& d, const std::vector<Segment2>& found) {
      d.per_frame_arcs.push_back(count_arc_false_positives(found, f.meta.lines, rings, o.match));
    };
    count_arcs(report.ringlet, segments);
    if (report.ringlet.per_frame_arcs.back() > 0 && frame_circle.recalled < frame_circle.truths) {
      ++report.arc_frames_circle_missed;
    }

    const HoughRun h = run_hough(f, report.hough, margin);
    report.baseline.time_ms.push_back(h.ms);
    report.baseline.raw_detections += h.segments.size();
    report.baseline.per_frame.push_back(match_segments(h.segments, f.meta.lines, o.match));
    report.baseline.segments.push_back(h.segments);
    report.baseline.counts += report.baseline.per_frame.back();
    count_arcs(report.baseline, h.segments);
    if (o.progress) o.progress("evaluating", i + 1, report.report_frames);
  }
  return report;
}

}  // namespace ringlet::vision::evaluate
