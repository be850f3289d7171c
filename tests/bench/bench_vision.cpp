// Vision costs on a synthetic 640×480 field frame (halfway line, touch line, centre circle, ball,
// pixel noise): classification (YUYV and BGR, full and every-other pixel), scan-line candidates,
// RANSAC, the ball, and the whole pipeline at each degrade level. Target: the whole frame within
// the 3 ms budget, classification under 0.5 ms.
#include <benchmark/benchmark.h>

#include <vector>

#include "ringlet/vision/ball.hpp"
#include "ringlet/vision/bw_ball.hpp"
#include "ringlet/vision/cost_model.hpp"
#include "ringlet/vision/hog_svm.hpp"
#include "ringlet/vision/horizon.hpp"
#include "ringlet/vision/pipeline.hpp"
#include "classify_everything.hpp"
#include "synthetic_field.hpp"

namespace {

using namespace ringlet;
using namespace ringlet::vision;

struct Fixture {
  testing::Camera cam;
  testing::Frame yuyv = testing::render(testing::field_scene(), cam, hal::PixelFormat::kYuyv);
  testing::Frame bgr = testing::render(testing::field_scene(), cam, hal::PixelFormat::kBgr8);
  ColourTable table = ColourTable::from_thresholds({});
  hal::CameraPose pose = cam.pose();
  std::vector<int> rows = std::vector<int>(640);
  int first = horizon_rows(cam.k, pose, 2, rows);
};

const Fixture& fixture() {
  static const Fixture f;
  return f;
}

void BM_ClassifyYuyv(benchmark::State& state) {
  const Fixture& f = fixture();
  ClassImage classes(640, 480);
  const int step = static_cast<int>(state.range(0));
  const int first = state.range(1) != 0 ? f.first : 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(classes.classify(f.yuyv.view, f.table, first, step));
    benchmark::ClobberMemory();
  }
  state.SetLabel(first == 0 ? "whole frame" : "below horizon");
}
BENCHMARK(BM_ClassifyYuyv)->Args({1, 0})->Args({1, 1})->Args({2, 1})->Unit(benchmark::kMicrosecond);

void BM_ClassifyBgr(benchmark::State& state) {
  const Fixture& f = fixture();
  ClassImage classes(640, 480);
  const int step = static_cast<int>(state.range(0));
  for (auto _ : state) {
    benchmark::DoNotOptimize(classes.classify(f.bgr.view, f.table, f.first, step));
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_ClassifyBgr)->Arg(1)->Arg(2)->Unit(benchmark::kMicrosecond);

// Adaptive colour: the per-frame estimate (sampling below the horizon), the tables it builds, and
// classification with them, against the same rule as plain comparisons per pixel.
void BM_FieldColourEstimate(benchmark::State& state) {
  const Fixture& f = fixture();
  FieldColourEstimator estimator;
  const hal::FrameView& view = state.range(0) != 0 ? f.bgr.view : f.yuyv.view;
  for (auto _ : state) benchmark::DoNotOptimize(estimator.update(view, f.rows).y);
  state.SetLabel(state.range(0) != 0 ? "BGR" : "YUYV");
  state.counters["samples"] = estimator.estimate().samples;  // per_colour_sample_ns: the time over this
}
BENCHMARK(BM_FieldColourEstimate)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

void BM_AdaptiveBuild(benchmark::State& state) {
  const Fixture& f = fixture();
  const FieldColourEstimate e = FieldColourEstimator::measure(f.yuyv.view, f.rows, {});
  AdaptiveClassifier adaptive;
  for (auto _ : state) {
    adaptive.build(e, 640, 480);
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_AdaptiveBuild)->Unit(benchmark::kMicrosecond);

void BM_ClassifyAdaptive(benchmark::State& state) {
  const Fixture& f = fixture();
  AdaptiveClassifier adaptive;
  adaptive.build(FieldColourEstimator::measure(f.yuyv.view, f.rows, {}), 640, 480);
  ClassImage classes(640, 480);
  const int step = static_cast<int>(state.range(0));
  for (auto _ : state) {
    benchmark::DoNotOptimize(classes.classify(f.yuyv.view, adaptive, f.first, step));
    benchmark::ClobberMemory();
  }
  state.SetLabel("tables, YUYV below horizon");
}
BENCHMARK(BM_ClassifyAdaptive)->Arg(1)->Arg(2)->Unit(benchmark::kMicrosecond);

// The alternative that was measured and not kept: the rule's comparisons for every pixel.
void BM_ClassifyAdaptiveByComparison(benchmark::State& state) {
  const Fixture& f = fixture();
  AdaptiveClassifier adaptive;
  adaptive.build(FieldColourEstimator::measure(f.yuyv.view, f.rows, {}), 640, 480);
  std::vector<std::uint8_t> out(640 * 480);
  for (auto _ : state) {
    for (int y = f.first; y < 480; ++y) {
      const std::uint8_t* in = f.yuyv.view.data + static_cast<std::size_t>(y) * 1280U;
      std::uint8_t* o = out.data() + static_cast<std::size_t>(y) * 640U;
      const int cell_row = (y * kColourCellsY / 480) * kColourCellsX;
      for (int x = 0; x < 640; x += 2) {
        const std::uint8_t* p = in + 2 * x;
        const int cell = cell_row + x * kColourCellsX / 640;
        o[x] = static_cast<std::uint8_t>(adaptive.classify_by_comparison(p[0], p[1], p[3], cell));
        o[x + 1] = static_cast<std::uint8_t>(adaptive.classify_by_comparison(p[2], p[1], p[3], cell));
      }
    }
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetLabel("comparisons, YUYV below horizon");
}
BENCHMARK(BM_ClassifyAdaptiveByComparison)->Unit(benchmark::kMicrosecond);

void BM_ScanPoints(benchmark::State& state) {
  const Fixture& f = fixture();
  ClassImage classes(640, 480);
  classes.classify(f.yuyv.view, f.table, f.first, 1);
  CandidateBuffer out(4096);
  ScanParams params;
  params.stride = static_cast<int>(state.range(0));
  params.horizontal = state.range(1) != 0;
  LineScanner scanner(640);
  for (auto _ : state) {
    benchmark::DoNotOptimize(scanner.scan(classes, f.yuyv.view, f.cam.k, f.pose, f.rows, params, out));
  }
  state.counters["candidates"] = static_cast<double>(out.size());
  state.SetLabel(params.horizontal ? "vertical + horizontal" : "vertical only");
}
BENCHMARK(BM_ScanPoints)->Args({2, 1})->Args({2, 0})->Args({4, 1})->Args({8, 1})->Unit(benchmark::kMicrosecond);

/// The fixture's scan-line candidates (default scan), for the stages that start from them.
const CandidateBuffer& fixture_candidates() {
  static const CandidateBuffer cands = [] {
    const Fixture& f = fixture();
    ClassImage classes(640, 480);
    classes.classify(f.yuyv.view, f.table, f.first, 1);
    CandidateBuffer out(4096);
    LineScanner scanner(640);
    scanner.scan(classes, f.yuyv.view, f.cam.k, f.pose, f.rows, {}, out);
    return out;
  }();
  return cands;
}

void BM_Ransac(benchmark::State& state) {
  const Fixture& f = fixture();
  const CandidateBuffer& cands = fixture_candidates();
  RansacLineFinder finder({}, 4096);
  LineSet out;
  std::uint64_t frame = 0;
  for (auto _ : state) {
    finder.find(cands.points(), ++frame, f.cam.k, f.pose, {}, out);
    benchmark::DoNotOptimize(out.count);
  }
  state.counters["lines"] = static_cast<double>(out.count);
  state.counters["trials"] = out.stats.trials_run;
  state.counters["draws"] = out.stats.partner_draws;  // second points drawn along the first's paint
}
BENCHMARK(BM_Ransac)->Unit(benchmark::kMicrosecond);

// The centre circle's stage alone on the fixture's candidates: its two-point trials and the
// judgement of the best hypotheses. Arg: trials (40, the default; 80 and 1 tell the trials' share
// from the judgement's). The `tests` counter is what the cost model counts (each trial walks the
// sample three times: the second point's candidates, then one walk per centre); its
// per_circle_test_ns comes from this benchmark's speed-up (cost_model.cpp).
void BM_CentreCircle(benchmark::State& state) {
  const CandidateBuffer& cands = fixture_candidates();
  CentreCircleFinder finder({}, 4096);
  CircleStats stats;
  std::uint64_t frame = 0;
  const int trials = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(finder.find(cands.points(), ++frame, 1, {}, stats, trials).seen);
  state.counters["tests"] = 3.0 * stats.trials_run * stats.points_used;
  state.counters["seen"] = finder.find(cands.points(), frame, 1, {}, stats).seen ? 1.0 : 0.0;
}
BENCHMARK(BM_CentreCircle)->Arg(40)->Arg(80)->Arg(1)->Unit(benchmark::kMicrosecond);

void BM_Ball(benchmark::State& state) {
  const Fixture& f = fixture();
  ClassImage classes(640, 480);
  classes.classify(f.yuyv.view, f.table, f.first, 1);
  BallDetector detector({}, 640, 480);
  for (auto _ : state) benchmark::DoNotOptimize(detector.detect(classes, f.cam.k, f.pose));
}
BENCHMARK(BM_Ball)->Unit(benchmark::kMicrosecond);

// The black-and-white ball's candidates (seeds every 4 px, the runs' extents, inner contrasts and
// outlines; no classifier) on the same field with the SPL ball. `samples` is what the pipeline
// counts as ball samples (the seeds plus the refinement's reads): the cost model's per-sample
// row was measured on the orange ball (BM_Ball), and this shows whether it holds here.
void BM_BwBall(benchmark::State& state) {
  const Fixture& f = fixture();
  testing::Scene scene = testing::field_scene();
  scene.ball_black_white = true;
  static const testing::Frame frame = testing::render(scene, f.cam, hal::PixelFormat::kYuyv);
  ClassImage classes(640, 480);
  classes.classify(frame.view, f.table, f.first, 1);
  BwBallDetector detector({});
  BallList out;
  for (auto _ : state) {
    detector.detect(classes, frame.view, f.cam.k, f.pose, 4, nullptr, 0, {}, out);
    benchmark::DoNotOptimize(out.count);
  }
  state.counters["samples"] = static_cast<double>(640 * (480 - f.first) / 16 + out.refine_samples);
  state.counters["candidates"] = out.candidates;
}
BENCHMARK(BM_BwBall)->Unit(benchmark::kMicrosecond);

// One expected ball radius (a pixel's ray to the ball's height above the ground): the black-and-
// white ball's detector takes one at every non-field run's end and two or three per candidate it
// considers. The cost model counts each as kRadiusSamples ball samples (bw_ball.hpp): this time
// over BM_Ball's per sample (51 us / 18k) in the same run.
void BM_BallRadius(benchmark::State& state) {
  const Fixture& f = fixture();
  const BallPlane plane(f.cam.k, f.pose, BwBallParams{}.radius_m);  // once per frame in the detector
  double sum = 0.0;
  for (auto _ : state) {
    for (int i = 0; i < 1000; ++i) {
      sum += plane.radius_px({static_cast<double>(i % 640), 300.0 + static_cast<double>(i % 150)});
    }
    benchmark::DoNotOptimize(sum);
  }
  state.counters["calls"] = 1000;
}
BENCHMARK(BM_BallRadius)->Unit(benchmark::kMicrosecond);

// The robot candidate scan alone (no classifier): columns every 4 px, every classified row. The
// cost model's per_robot_sample_ns is this time over the samples counter.
void BM_RobotScan(benchmark::State& state) {
  const Fixture& f = fixture();
  ClassImage classes(640, 480);
  classes.classify(f.yuyv.view, f.table, f.first, 1);
  RobotDetector detector({});
  RobotList out;
  for (auto _ : state) {
    detector.detect(classes, f.yuyv.view, f.cam.k, f.pose, 4, nullptr, 0, {}, out);
    benchmark::DoNotOptimize(out.count);
  }
  state.counters["samples"] = static_cast<double>(640 / 4 * (480 - f.first));
}
BENCHMARK(BM_RobotScan)->Unit(benchmark::kMicrosecond);


// One HOG/SVM classification: resample a window (a ball 20 px across, a robot 150 px tall), HOG,
// dot product. Arg 0: the ball's 32×32 window, 1: the robot's 32×64.
void BM_HogClassify(benchmark::State& state) {
  const Fixture& f = fixture();
  const HogParams p = state.range(0) == 0 ? HogParams::ball() : HogParams::robot();
  HogClassifier c(HogSvm(state.range(0) == 0 ? HogTarget::kBall : HogTarget::kRobot, p,
                         std::vector<float>(static_cast<std::size_t>(p.feature_length()), 0.01f), 0.0, 0.0));
  const double scale = state.range(0) == 0 ? 1.0 : 2.7;
  for (auto _ : state) benchmark::DoNotOptimize(c.score_window(f.yuyv.view, 300, 250, scale));
}
BENCHMARK(BM_HogClassify)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// The whole pipeline with the black-and-white ball detector and both classifiers installed
// (weights that accept every window, so every candidate the level allows is classified).
void BM_PipelineHog(benchmark::State& state) {
  const Fixture& f = fixture();
  const auto classifying = testing::pipeline_classifying_everything();
  VisionPipeline& pipeline = *classifying;
  const int level = static_cast<int>(state.range(0));
  hal::FrameView view = f.yuyv.view;
  for (auto _ : state) {
    ++view.sequence;
    benchmark::DoNotOptimize(pipeline.process(view, f.cam.head, {}, level).line_count);
  }
  const VisionResult& r = pipeline.result();
  state.counters["classified"] = r.balls.classified + r.robots.classified;
  const CostModel model = default_cost_model();  // as in BM_Pipeline: the model beside the measurement
  state.counters["model_host_us"] =
      static_cast<double>(modelled_cost(r.work, model).count()) / model.board_slowdown / 1000.0;
}
BENCHMARK(BM_PipelineHog)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMicrosecond);

void BM_Pipeline(benchmark::State& state) {
  const Fixture& f = fixture();
  VisionConfig config;
  config.colour_mode = state.range(1) != 0 ? ColourMode::kTable : ColourMode::kAdaptive;
  VisionPipeline pipeline(config, f.table);
  const int level = static_cast<int>(state.range(0));
  hal::FrameView view = f.yuyv.view;
  for (auto _ : state) {
    ++view.sequence;
    benchmark::DoNotOptimize(pipeline.process(view, f.cam.head, {}, level).line_count);
  }
  state.counters["lines"] = static_cast<double>(pipeline.result().line_count);
  state.SetLabel(to_string(config.colour_mode));
  // The cost model (cost_model.hpp) against this host: model_host_us is the modelled cost without
  // the board factor, to set beside the measured time per frame; a drift of the model shows here.
  const CostModel model = default_cost_model();
  state.counters["model_host_us"] =
      static_cast<double>(modelled_cost(pipeline.result().work, model).count()) / model.board_slowdown / 1000.0;
}
BENCHMARK(BM_Pipeline)->Args({0, 0})->Args({1, 0})->Args({2, 0})->Args({0, 1})->Args({1, 1})->Args({2, 1})->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
