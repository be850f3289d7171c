// The work count and the cost model: counted from the frame, the head and the level only (so the
// same frame costs the same on every host and under any stopwatch), smaller at higher degrade
// levels, and a plain weighted sum.
#include <gtest/gtest.h>

#include <memory>

#include <algorithm>
#include <cmath>
#include <string_view>
#include <vector>

#include "ringlet/vision/cost_model.hpp"
#include "ringlet/vision/pipeline.hpp"
#include "ringlet/vision/robots.hpp"
#include "ringlet/vision/stages.hpp"
#include "classify_everything.hpp"
#include "synthetic_field.hpp"

namespace ringlet::vision {
namespace {

/// A slow host: a millisecond passes at every read. The deadline is far away and decides nothing,
/// but every stage time differs from the plain run.
class SlowHostStopwatch final : public hal::Stopwatch {
 public:
  [[nodiscard]] hal::Nanos wall_now() const noexcept override { return hal::Nanos{now_ += 1'000'000}; }
  [[nodiscard]] hal::Nanos cpu_now() const noexcept override { return wall_now(); }

 private:
  mutable std::int64_t now_ = 0;
};

TEST(VisionCost, TheWorkCountDependsOnTheFrameNotOnTheClock) {
  testing::Camera cam;
  const auto frame = testing::render(testing::field_scene(), cam, hal::PixelFormat::kYuyv);
  VisionPipeline a(VisionConfig{}, ColourTable::from_thresholds({}));
  VisionPipeline b(VisionConfig{}, ColourTable::from_thresholds({}));
  const WorkCount plain = a.process(frame.view, cam.head).work;
  SlowHostStopwatch watch;
  const WorkCount timed = b.process(frame.view, cam.head, Deadline{&watch, hal::Nanos{std::int64_t{1} << 60}, false}).work;
  EXPECT_EQ(plain.classified_pixels, timed.classified_pixels);
  EXPECT_EQ(plain.ball_samples, timed.ball_samples);
  EXPECT_EQ(plain.scanned_pixels, timed.scanned_pixels);
  EXPECT_EQ(plain.candidates, timed.candidates);
  EXPECT_EQ(plain.point_tests, timed.point_tests);
  EXPECT_EQ(plain.colour_samples, timed.colour_samples);
  EXPECT_EQ(plain.colour_rebuilds, timed.colour_rebuilds);
  EXPECT_EQ(plain.robot_samples, timed.robot_samples);
  EXPECT_EQ(plain.circle_tests, timed.circle_tests);
  EXPECT_GT(plain.classified_pixels, 100'000);
  EXPECT_GT(plain.point_tests, 0);
  EXPECT_GT(plain.circle_tests, 0);
  EXPECT_EQ(modelled_cost(plain), modelled_cost(timed));
}

TEST(VisionCost, HigherDegradeLevelsCostLess) {
  testing::Camera cam;
  const auto frame = testing::render(testing::field_scene(), cam, hal::PixelFormat::kYuyv);
  VisionPipeline p(VisionConfig{}, ColourTable::from_thresholds({}));
  hal::Nanos previous = hal::Nanos::max();
  for (int level = 0; level < kDegradeLevels; ++level) {
    const hal::Nanos cost = modelled_cost(p.process(frame.view, cam.head, {}, level).work);
    EXPECT_LT(cost, previous) << "level " << level;
    previous = cost;
  }
  // The shipped model keeps a full frame inside the 3 ms budget the firmware gives vision.
  EXPECT_LT(modelled_cost(p.process(frame.view, cam.head, {}, 0).work), hal::Nanos{3'000'000});
}

// The adaptive colour estimate and table rebuild are counted when they run, not in table mode.
TEST(VisionCost, TheAdaptiveColourWorkIsCountedWhenItRuns) {
  testing::Camera cam;
  const auto frame = testing::render(testing::field_scene(), cam, hal::PixelFormat::kYuyv);
  VisionPipeline adaptive(VisionConfig{}, ColourTable::from_thresholds({}));
  VisionConfig table_config;
  table_config.colour_mode = ColourMode::kTable;
  VisionPipeline table(table_config, ColourTable::from_thresholds({}));
  const VisionResult& a = adaptive.process(frame.view, cam.head);
  ASSERT_TRUE(a.field_colour.valid);
  EXPECT_EQ(a.work.colour_samples, a.field_colour.samples);
  EXPECT_GT(a.work.colour_samples, 1000);
  EXPECT_EQ(a.work.colour_rebuilds, 1);
  const VisionResult& t = table.process(frame.view, cam.head);
  EXPECT_EQ(t.work.colour_samples, 0);
  EXPECT_EQ(t.work.colour_rebuilds, 0);
  EXPECT_EQ(t.work.classified_pixels, a.work.classified_pixels);
  EXPECT_GT(modelled_cost(a.work), modelled_cost(t.work)) << "the estimate and the rebuild cost something";
}

// Every HOG/SVM classification is counted, each window costs more than the whole candidate scan
// per sample, and the levels that drop the classifiers cost less: in lockstep the degrade policy
// sees the classifiers' cost.
TEST(VisionCost, HogClassificationsAreCountedAndDegradingDropsTheirCost) {
  testing::Camera cam;
  const auto frame = testing::render(testing::classifier_scene(), cam, hal::PixelFormat::kYuyv);
  VisionConfig config;
  config.ball.mode = BallMode::kBlackWhite;
  const auto with_classifiers = testing::pipeline_classifying_everything();
  VisionPipeline& with = *with_classifiers;
  VisionPipeline without(config, ColourTable::from_thresholds({}));
  const VisionResult& r = with.process(frame.view, cam.head);
  EXPECT_EQ(r.work.ball_windows, r.balls.classified);
  EXPECT_EQ(r.work.robot_windows, r.robots.classified);
  ASSERT_GT(r.work.ball_windows + r.work.robot_windows, 0);
  EXPECT_GT(r.work.robot_samples, 0);
  const WorkCount verified = r.work;
  const WorkCount unverified = without.process(frame.view, cam.head).work;
  EXPECT_EQ(unverified.ball_windows + unverified.robot_windows, 0);
  const CostModel m = default_cost_model();
  // Without a robot model the robot stage does not run at all, so its scan is in the difference too.
  EXPECT_EQ(unverified.robot_samples, 0);
  // The marks' search examines what the lines and the verified balls leave over, so its point
  // tests change with the classifications too.
  const hal::Nanos windows{std::llround(m.board_slowdown * (m.per_ball_window_ns * static_cast<double>(verified.ball_windows) +
                                                            m.per_robot_window_ns * static_cast<double>(verified.robot_windows) +
                                                            m.per_robot_sample_ns * static_cast<double>(verified.robot_samples) +
                                                            m.per_point_test_ns * static_cast<double>(verified.point_tests -
                                                                                                      unverified.point_tests)))};
  EXPECT_NEAR(static_cast<double>((modelled_cost(verified) - modelled_cost(unverified)).count()),
              static_cast<double>(windows.count()), 2.0)
      << "the same frame, the classifications (and the robot stage they need) the only difference";
  hal::Nanos previous = hal::Nanos::max();
  for (int level = 0; level < kDegradeLevels; ++level) {
    const VisionResult& at = with.process(frame.view, cam.head, {}, level);
    const hal::Nanos cost = modelled_cost(at.work);
    EXPECT_LT(cost, previous) << "level " << level;
    previous = cost;
    if (level == kDegradeLevels - 1) {
      EXPECT_EQ(at.work.ball_windows + at.work.robot_windows, 0) << "the classifiers are dropped";
    }
  }
  // Level 0 with every window classified may not fit on a busy frame (issue 10 is open on it: a
  // robot window costs ~0.19 ms on the board; in lockstep the modelled budget cuts the windows,
  // tests below); the degrade policy then runs level 1, which must fit in full.
  EXPECT_LT(modelled_cost(with.process(frame.view, cam.head, {}, 1).work), hal::Nanos{3'000'000})
      << "level 1 (fewer classifications) fits the 3 ms budget";
}

// In lockstep the executive judges the vision task on the modelled cost, so the pipeline fits its
// robot classifications, which run last, to the modelled budget: on a frame with a robot, a budget
// short of one window cuts the window and nothing else (the lines are the same), the frame's
// modelled cost stays inside it, and an unlimited budget classifies as before.
TEST(VisionCost, TheRobotClassificationsFitTheModelledBudget) {
  testing::Camera cam;
  const hal::CameraPose pose = cam.pose();
  const int w = cam.k.width, h = cam.k.height;
  // Gray8: grey 100 is field, 230 line (Gray8 classifies with U = V = 128).
  std::vector<std::uint8_t> img(static_cast<std::size_t>(w * h), 100);
  const auto paint = [&](int x0, int x1, int y0, int y1) {
    for (int y = std::max(0, y0); y < std::min(y1, h); ++y) {
      for (int x = std::max(0, x0); x < std::min(x1, w); ++x) img[static_cast<std::size_t>(y * w + x)] = 230;
    }
  };
  const RobotDetector probe(RobotParams{});
  const hal::RobotPoint at{1.4, 0.1};
  const auto foot = hal::project(cam.k, pose, {at.x, at.y, 0.0});
  ASSERT_TRUE(foot.has_value());
  const double tall = probe.expected_height_px(cam.k, pose, at);
  ASSERT_GT(tall, 60.0);
  paint(static_cast<int>(foot->u - 0.25 * tall), static_cast<int>(foot->u + 0.25 * tall),
        static_cast<int>(foot->v - tall), static_cast<int>(foot->v));  // the robot
  paint(0, w, static_cast<int>(foot->v) + 40, static_cast<int>(foot->v) + 47);  // a line across the field
  auto frame = testing::render(testing::Scene{}, cam, hal::PixelFormat::kGray8);
  hal::FrameView view = frame.view;
  view.data = img.data();
  view.stride = w;
  view.format = hal::PixelFormat::kGray8;

  ColourThresholds t;
  t.field = {50, 150, 100, 156, 100, 156};
  t.line = {200, 255, 100, 156, 100, 156};
  t.ball = {0, 0, 0, 0, 0, 0};
  VisionConfig config;
  config.colour_mode = ColourMode::kTable;
  VisionPipeline pipeline(config, ColourTable::from_thresholds(t));
  ASSERT_EQ(pipeline.set_classifier(testing::accept_all(HogTarget::kRobot, HogParams::robot())), "");

  const VisionResult full = pipeline.process(view, cam.posture());
  ASSERT_GE(full.robots.classified, 1) << "the robot is a candidate and is classified";
  ASSERT_GE(full.robots.count, 1U);
  EXPECT_TRUE(full.robots.robots[0].verified);
  ASSERT_GE(full.line_count, 1U);
  EXPECT_EQ(full.robots.classifications_cut, 0);
  EXPECT_FALSE(full.cut.deadline_hit);

  WorkCount without_windows = full.work;
  without_windows.robot_windows = 0;
  const hal::Nanos one_window = modelled_cost(full.work) - modelled_cost(without_windows);
  ASSERT_GT(one_window.count(), 0);
  Deadline short_of_one;
  short_of_one.model_budget = modelled_cost(without_windows) + one_window / 2;
  const VisionResult cut = pipeline.process(view, cam.posture(), short_of_one);
  EXPECT_EQ(cut.robots.classified, 0);
  EXPECT_EQ(cut.robots.classifications_cut, full.robots.classified);
  EXPECT_TRUE(cut.cut.deadline_hit);
  EXPECT_LE(modelled_cost(cut.work), short_of_one.model_budget);
  EXPECT_EQ(cut.work.robot_windows, 0);
  ASSERT_EQ(cut.line_count, full.line_count) << "the lines came first";
  for (std::size_t i = 0; i < cut.line_count; ++i) {
    EXPECT_EQ(cut.lines[i].image_start.u, full.lines[i].image_start.u);
    EXPECT_EQ(cut.lines[i].image_end.v, full.lines[i].image_end.v);
  }

  Deadline exactly_enough;
  exactly_enough.model_budget = modelled_cost(full.work);
  const VisionResult fits = pipeline.process(view, cam.posture(), exactly_enough);
  EXPECT_EQ(fits.robots.classified, full.robots.classified);
  EXPECT_EQ(fits.robots.count, full.robots.count);
  EXPECT_EQ(modelled_cost(fits.work), modelled_cost(full.work));
}

// The classifier scene, a pipeline classifying every window it may, and that pipeline's run with
// no budget (the two tests below cut it to budgets below that run's cost).
struct ClassifierFrame {
  testing::Camera cam;
  testing::Frame frame = testing::render(testing::classifier_scene(), cam, hal::PixelFormat::kYuyv);
  std::unique_ptr<VisionPipeline> classifying = testing::pipeline_classifying_everything();
  VisionResult full = classifying->process(frame.view, cam.head);
};

// The same for the ball's classifications and the marks, which also run after the lines: for any
// budget from what the uncuttable stages cost up to the whole frame, the frame's modelled cost
// stays inside it, the lines' trials are never cut, and the ball's windows come before the
// robots'.
TEST(VisionCost, TheBallClassificationsAndTheMarksFitTheModelledBudgetToo) {
  ClassifierFrame c;
  auto& [cam, frame, classifying, full] = c;
  VisionPipeline& pipeline = *classifying;
  ASSERT_GT(full.work.ball_windows, 0);
  WorkCount base = full.work;
  base.ball_windows = 0;
  base.robot_windows = 0;
  base.point_tests -= full.marks.tests;
  const hal::Nanos low = modelled_cost(base);
  const hal::Nanos high = modelled_cost(full.work);
  ASSERT_GT(high, low);
  int cut_frames = 0;
  for (int i = 0; i <= 20; ++i) {
    Deadline d;
    d.model_budget = low + (high - low) * i / 20;
    const VisionResult& r = pipeline.process(frame.view, cam.head, d);
    EXPECT_LE(modelled_cost(r.work), d.model_budget) << "step " << i;
    if (i > 0) {  // (at step 0 the model's rounding may leave RANSAC's last trial out)
      EXPECT_EQ(r.ransac.trials_run, full.ransac.trials_run) << "step " << i;
      EXPECT_EQ(r.ransac.stopped_early, false) << "step " << i;
    }
    if (r.work.robot_windows > 0) {
      EXPECT_EQ(r.work.ball_windows, full.work.ball_windows) << "step " << i;
    }
    cut_frames += r.cut.deadline_hit ? 1 : 0;
    if (i == 20) {
      EXPECT_EQ(r.work.ball_windows + r.work.robot_windows, full.work.ball_windows + full.work.robot_windows);
    }
  }
  EXPECT_GE(cut_frames, 10) << "most budgets below the whole frame cut something";
}

// Below what the frame's lines need, RANSAC's trials are cut to the modelled budget: the frame
// stays inside it, its line search is reported cut (the vision task is then overloaded), and the
// classifiers and the marks get nothing.
TEST(VisionCost, RansacsTrialsFitTheModelledBudgetWhenTheLinesNeedMore) {
  ClassifierFrame c;
  auto& [cam, frame, classifying, full] = c;
  VisionPipeline& pipeline = *classifying;
  ASSERT_GT(full.ransac.trials_run, 20);
  WorkCount before = full.work;  // the work before RANSAC's trials
  before.ball_windows = 0;
  before.robot_windows = 0;
  before.point_tests = 0;
  WorkCount lines = before;
  lines.point_tests = full.work.point_tests - full.marks.tests;
  const hal::Nanos low = modelled_cost(before);
  const hal::Nanos high = modelled_cost(lines);
  ASSERT_GT(high, low);
  int previous_trials = 0;
  for (int i = 1; i < 10; ++i) {
    Deadline d;
    d.model_budget = low + (high - low) * i / 10;
    const VisionResult& r = pipeline.process(frame.view, cam.head, d);
    EXPECT_LE(modelled_cost(r.work), d.model_budget) << "step " << i;
    EXPECT_TRUE(r.ransac.stopped_early) << "step " << i;
    EXPECT_TRUE(r.cut.lines_not_extracted) << "step " << i;
    EXPECT_LT(r.ransac.trials_run, full.ransac.trials_run) << "step " << i;
    EXPECT_GE(r.ransac.trials_run, previous_trials) << "a larger budget runs no fewer trials";
    previous_trials = r.ransac.trials_run;
    EXPECT_EQ(r.work.ball_windows + r.work.robot_windows, 0) << "step " << i;
  }
  EXPECT_GT(previous_trials, 0);
}

TEST(VisionCost, TheModelIsAWeightedSumTimesTheBoardFactor) {
  CostModel m;
  m.board_slowdown = 2.0;
  m.fixed_ns = 100.0;
  m.per_classified_pixel_ns = 1.0;
  m.per_ball_sample_ns = 2.0;
  m.per_scanned_pixel_ns = 3.0;
  m.per_candidate_ns = 4.0;
  m.per_point_test_ns = 5.0;
  m.per_colour_sample_ns = 6.0;
  m.per_colour_rebuild_ns = 7.0;
  m.per_robot_sample_ns = 8.0;
  m.per_ball_window_ns = 9.0;
  m.per_robot_window_ns = 10.0;
  m.per_circle_test_ns = 11.0;
  const WorkCount w{10, 20, 30, 40, 50, 60, 1, 80, 90, 100, 110};
  EXPECT_EQ(modelled_cost(w, m),
            hal::Nanos{2 * (100 + 10 + 40 + 90 + 160 + 250 + 360 + 7 + 640 + 810 + 1000 + 1210)});
  EXPECT_EQ(modelled_cost(WorkCount{}, m), hal::Nanos{200});
}

// The report's breakdown: every row of the model lands in exactly the stage that does that work,
// and the stages add up to the frame. A new WorkCount row left out of host_cost_by_stage fails here.
TEST(VisionStages, EveryRowOfTheModelBelongsToTheStageThatDoesTheWork) {
  const auto only = [](auto field) {
    WorkCount w;
    w.*field = 1000;
    return host_cost_by_stage(host_cost(w));
  };
  const auto stage_of = [&](auto field) {
    const auto by_stage = only(field);
    const auto base = host_cost_by_stage(host_cost(WorkCount{}));
    std::vector<std::string_view> grew;
    for (std::size_t s = 0; s < kStageCount; ++s) {
      if (by_stage[s] != base[s]) grew.push_back(stage_name(static_cast<Stage>(s)));
    }
    return grew;
  };
  using V = std::vector<std::string_view>;
  EXPECT_EQ(stage_of(&WorkCount::classified_pixels), V{"classify"});
  EXPECT_EQ(stage_of(&WorkCount::colour_samples), V{"classify"});
  EXPECT_EQ(stage_of(&WorkCount::colour_rebuilds), V{"classify"});
  EXPECT_EQ(stage_of(&WorkCount::ball_samples), V{"ball"});
  EXPECT_EQ(stage_of(&WorkCount::ball_windows), V{"ball"});
  EXPECT_EQ(stage_of(&WorkCount::scanned_pixels), V{"scan"});
  EXPECT_EQ(stage_of(&WorkCount::candidates), V{"scan"});
  EXPECT_EQ(stage_of(&WorkCount::point_tests), V{"ransac"});
  EXPECT_EQ(stage_of(&WorkCount::circle_tests), V{"circle"});
  EXPECT_EQ(stage_of(&WorkCount::robot_samples), V{"robots"});
  EXPECT_EQ(stage_of(&WorkCount::robot_windows), V{"robots"});
  EXPECT_EQ(host_cost_by_stage(host_cost(WorkCount{}))[static_cast<std::size_t>(Stage::kHorizon)], default_cost_model().fixed_ns);

  // A real frame's work: the stages add up to the frame, and every stage has its own name.
  const WorkCount w{123456, 2345, 34567, 4567, 56789, 6789, 1, 8901, 3, 4, 12345};
  const auto by_stage = host_cost_by_stage(host_cost(w));
  double sum = 0.0;
  for (const double ns : by_stage) sum += ns;
  EXPECT_NEAR(sum, host_cost(w).total(), 1e-9 * host_cost(w).total());
  std::vector<std::string_view> names;
  for (std::size_t s = 0; s < kStageCount; ++s) names.push_back(stage_name(static_cast<Stage>(s)));
  EXPECT_EQ(names, (V{"horizon", "classify", "ball", "scan", "ransac", "circle", "robots"}));
}

}  // namespace
}  // namespace ringlet::vision
