#include "ringlet/vision/cost_model.hpp"

#include <cmath>

namespace ringlet::vision {

CostModel default_cost_model() noexcept {
  // Per unit of work on the development host (2-core x86-64 VM, -O2), from ringlet_bench_vision's
  // stage benchmarks (CPU time) on the synthetic 640x480 field frame: classification 184 us for
  // 291k pixels below the horizon, scan lines 145 us for 145k walked pixels (stride 4), the ball
  // 51 us for 18k samples, RANSAC 89 us for 90 trials over 78 sampled points of 779 candidates.
  // BM_Pipeline prints model_host_us beside the measured time, so a drift shows in every bench run.
  // Issue 10's stages (dev build, RelWithDebInfo -O2, the same host shared at load average 7-9;
  // each divided by that run's BM_Ball over its calibrated 51 us, 1.27, to put it on the footing
  // of the figures above): the field-colour estimate 40 us for 4560 samples, the adaptive table
  // rebuild 39 us, the robot candidate scan 119 us for 72.8k samples (columns every 4 px, every
  // row). The HOG windows varied most with the load (ball 30-50 us, robot 93-155 us for the
  // bench's 32x64 window at scale 2.7): the quieter run's 30 and 100 us were taken uncorrected.
  // Since the window's taps are computed once per row and column (resample.cpp) they measure
  // 24.7 and 66.7 us on an idle host (load 0.8, BM_HogClassify, median of 3; before: 29.5 and
  // 99.6 us in the same conditions), taken as 25 and 67 us. Each candidate's paint direction (four
  // Sobels across its run's edges, one back-projection; scan_points.cpp) added 8 us for the 779
  // candidates (BM_ScanPoints/2/1 354 -> 362 us, idle host, median of 3): 10 ns more per
  // candidate. RANSAC's direction gate did not cost more (BM_Ransac 106 -> 103 us: its per-point
  // tests are inlined now). The centre circle has its own row since its stage became twice as fast
  // (its trials' distances from their squares, its bins counted once; BM_CentreCircle 210 -> 111
  // us): before, a circle trial counted 4 walks of its sample at the point test's 10 ns, which
  // modelled the stage below its measured time (139 us against 185 us on the ball's footing), and
  // that relation is kept, scaled by the stage's measured speed-up (against BM_Ball in the same
  // run: 3.58 -> 1.9-2.1 times its time, ×0.56): 4 × 10 ns × 0.56 over the 3 walks it makes now.
  // RANSAC draws a trial's second point along the first one's paint (up to 8 draws); each draw is
  // counted as a point test. In BM_Ransac (same run, BM_Ball 59-60 us) one draw a trial took
  // 92.7 us; up to 8, 114 us, but the frame then gave 3 lines in 120 trials (2 in 90 before) and
  // 312 draws (90): most of the time went to the extra round, whose trials are counted as before;
  // the draws are counted as point tests.
  // The HOG descriptor since its gradient pass is vectorised and its blocks are built from row
  // histograms (hog.cpp): a window (resample + descriptor) takes 0.653 (ball, 32x32 at scale 1)
  // and 0.698 (robot, 32x64 at scale 2.7) of the time the old descriptor took, both timed in one
  // program on the same windows (thread CPU time, best of 300 rounds of 16 windows; the dot
  // product, under 1 us, not in either): 25 and 67 us become 16.5 and 47 us.
  CostModel m;
  m.fixed_ns = 10'000.0;
  m.per_classified_pixel_ns = 0.63;
  m.per_ball_sample_ns = 2.8;
  m.per_scanned_pixel_ns = 0.95;
  m.per_candidate_ns = 35.0;
  m.per_point_test_ns = 10.0;
  m.per_colour_sample_ns = 7.0;
  m.per_colour_rebuild_ns = 31'000.0;
  m.per_robot_sample_ns = 1.3;
  m.per_ball_window_ns = 16'500.0;
  m.per_robot_window_ns = 47'000.0;
  m.per_circle_test_ns = 7.5;
  return m;
}

HostCost host_cost(const WorkCount& work, const CostModel& model) noexcept {
  const auto ns = [](double per_unit, std::int64_t units) { return per_unit * static_cast<double>(units); };
  HostCost c;
  c.fixed = model.fixed_ns;
  c.classified_pixels = ns(model.per_classified_pixel_ns, work.classified_pixels);
  c.ball_samples = ns(model.per_ball_sample_ns, work.ball_samples);
  c.scanned_pixels = ns(model.per_scanned_pixel_ns, work.scanned_pixels);
  c.candidates = ns(model.per_candidate_ns, work.candidates);
  c.point_tests = ns(model.per_point_test_ns, work.point_tests);
  c.colour_samples = ns(model.per_colour_sample_ns, work.colour_samples);
  c.colour_rebuilds = ns(model.per_colour_rebuild_ns, work.colour_rebuilds);
  c.robot_samples = ns(model.per_robot_sample_ns, work.robot_samples);
  c.ball_windows = ns(model.per_ball_window_ns, work.ball_windows);
  c.robot_windows = ns(model.per_robot_window_ns, work.robot_windows);
  c.circle_tests = ns(model.per_circle_test_ns, work.circle_tests);
  return c;
}

hal::Nanos modelled_cost(const WorkCount& work, const CostModel& model) noexcept {
  // Integer work times double coefficients, summed in one fixed order (HostCost::total): the same
  // IEEE operations on every target (the build has -ffp-contract=off), so the same frame gets the
  // same cost everywhere.
  return hal::Nanos{static_cast<std::int64_t>(std::llround(host_cost(work, model).total() * model.board_slowdown))};
}

}  // namespace ringlet::vision
