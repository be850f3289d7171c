// RANSAC on synthetic ground points: known lines among outliers, determinism per seed, the
// trial and skip counts of Mi-Pal's MAX_TRIALS / RANSAC_SKIP, gap splitting, collinear merging,
// and the centre circle recognised rather than reported as short lines.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "ringlet/vision/prng.hpp"
#include "ringlet/vision/ransac.hpp"

namespace ringlet::vision {
namespace {

const auto kK = hal::CameraIntrinsics::nao();
const auto kPose = hal::CameraPose::from_head({}, {0.0, 0.35});

void add_line(std::vector<CandidatePoint>& pts, hal::RobotPoint a, hal::RobotPoint b, int n, SplitMix64& rng,
              double noise = 0.01) {
  for (int i = 0; i < n; ++i) {
    const double t = (i + 0.5) / n;
    const double e = (static_cast<double>(rng.below(2001)) / 1000.0 - 1.0) * noise;
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    const double nx = -(b.y - a.y) / len, ny = (b.x - a.x) / len;
    pts.push_back({{}, {a.x + t * (b.x - a.x) + e * nx, a.y + t * (b.y - a.y) + e * ny}, 3.0F, ScanDirection::kVertical});
  }
}

void add_outliers(std::vector<CandidatePoint>& pts, int n, SplitMix64& rng) {
  for (int i = 0; i < n; ++i) {
    const double x = 0.5 + static_cast<double>(rng.below(4000)) / 1000.0;
    const double y = -2.0 + static_cast<double>(rng.below(4000)) / 1000.0;
    pts.push_back({{}, {x, y}, 3.0F, ScanDirection::kVertical});
  }
}

void add_circle(std::vector<CandidatePoint>& pts, hal::RobotPoint c, double r, int n, double from = 0.0,
                double to = 2.0 * std::numbers::pi) {
  for (int i = 0; i < n; ++i) {
    const double a = from + (to - from) * (i + 0.5) / n;
    pts.push_back({{}, {c.x + r * std::cos(a), c.y + r * std::sin(a)}, 3.0F, ScanDirection::kVertical});
  }
}

// Distance of point p from the infinite line through a, b.
double off_line(hal::RobotPoint p, hal::RobotPoint a, hal::RobotPoint b) {
  const double len = std::hypot(b.x - a.x, b.y - a.y);
  return std::abs((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)) / len;
}

bool matches(const FieldLine& f, hal::RobotPoint a, hal::RobotPoint b, double tol) {
  return off_line(f.ground_start, a, b) < tol && off_line(f.ground_end, a, b) < tol;
}

LineSet run(const std::vector<CandidatePoint>& pts, RansacParams params, std::uint64_t frame = 1) {
  RansacLineFinder finder(params, 4096);
  LineSet out;
  finder.find(pts, frame, kK, kPose, {}, out);
  return out;
}

TEST(Ransac, RecoversTwoLinesAmongOutliers) {
  SplitMix64 rng(7);
  std::vector<CandidatePoint> pts;
  const hal::RobotPoint a0{2.0, -2.0}, a1{2.0, 2.0}, b0{0.8, 1.0}, b1{4.0, 1.0};
  add_line(pts, a0, a1, 400, rng);
  add_line(pts, b0, b1, 300, rng);
  add_outliers(pts, 100, rng);
  const LineSet out = run(pts, {});
  EXPECT_EQ(out.stats.points_used, 80);  // the first round's trials: every 10th of 800
  ASSERT_GE(out.count, 2U);
  int found_a = 0, found_b = 0;
  for (std::size_t i = 0; i < out.count; ++i) {
    const FieldLine& f = out.lines[i];
    if (matches(f, a0, a1, 0.05)) {
      ++found_a;
      EXPECT_NEAR(f.length_m, 4.0, 0.3);
    } else if (matches(f, b0, b1, 0.05)) {
      ++found_b;
      EXPECT_NEAR(f.length_m, 3.2, 0.3);
    } else {
      EXPECT_LT(f.inliers, 8) << "spurious line with many inliers";
    }
    EXPECT_NEAR(f.length_m, std::hypot(f.ground_end.x - f.ground_start.x, f.ground_end.y - f.ground_start.y), 1e-9);
  }
  EXPECT_EQ(found_a, 1);
  EXPECT_EQ(found_b, 1);
  EXPECT_FALSE(out.circle.seen);
}

TEST(Ransac, DeterministicPerSeedAndFrame) {
  SplitMix64 rng(11);
  std::vector<CandidatePoint> pts;
  add_line(pts, {1.0, -1.5}, {3.0, 1.5}, 300, rng);
  add_line(pts, {1.0, 1.0}, {4.0, 0.5}, 300, rng);
  add_outliers(pts, 200, rng);
  const LineSet a = run(pts, {}, 5);
  const LineSet b = run(pts, {}, 5);
  ASSERT_EQ(a.count, b.count);
  for (std::size_t i = 0; i < a.count; ++i) {
    EXPECT_EQ(a.lines[i].ground_start.x, b.lines[i].ground_start.x);
    EXPECT_EQ(a.lines[i].ground_end.y, b.lines[i].ground_end.y);
    EXPECT_EQ(a.lines[i].inliers, b.lines[i].inliers);
  }
  EXPECT_EQ(a.stats.trials_run, b.stats.trials_run);
  // The generator stream differs per frame and per seed.
  EXPECT_NE(SplitMix64::for_frame(1, 5).next(), SplitMix64::for_frame(1, 6).next());
  EXPECT_NE(SplitMix64::for_frame(1, 5).next(), SplitMix64::for_frame(2, 5).next());
}

TEST(Ransac, RespectsMaxTrialsAndSkip) {
  SplitMix64 rng(3);
  std::vector<CandidatePoint> pts;
  add_line(pts, {2.0, -2.0}, {2.0, 2.0}, 800, rng, 0.0);
  RansacParams p;
  p.max_lines = 1;
  LineSet out = run(pts, p);
  EXPECT_EQ(out.stats.points_in, 800);
  EXPECT_EQ(out.stats.points_used, 80);  // RANSAC_SKIP: indices 0, 10, ..., 790
  EXPECT_EQ(out.stats.trials_run, 30);   // MAX_TRIALS for the one line
  ASSERT_EQ(out.count, 1U);
  EXPECT_EQ(out.lines[0].inliers, 800) << "the chosen line is measured on every candidate";
  p.max_trials = 7;
  p.skip = 3;
  p.max_lines = 8;
  out = run(pts, p);
  EXPECT_EQ(out.stats.points_used, 267);  // every 3rd of 800
  // One round finds the line and takes every point; the pool is then empty, so no more rounds.
  EXPECT_EQ(out.stats.trials_run, 7);
  EXPECT_EQ(out.stats.lines_extracted, 1);
}

TEST(Ransac, TheSampleIsNeverThinnerThanMinSamplePoints) {
  // 95 points with skip 10 would leave 10 for the trials; the sample keeps 40 at least, so the
  // step becomes 95 / 40 = 2 and 48 points are tried.
  SplitMix64 rng(3);
  std::vector<CandidatePoint> pts;
  add_line(pts, {2.0, -0.5}, {2.0, 0.5}, 95, rng, 0.0);
  RansacParams p;
  p.max_lines = 1;
  const LineSet out = run(pts, p);
  EXPECT_EQ(out.stats.points_used, 48);
  ASSERT_EQ(out.count, 1U);
  EXPECT_EQ(out.lines[0].inliers, 95);
}

TEST(Ransac, SparseSupportForItsImageLengthIsNoLine) {
  // 12 points spread along 4 m of ground: far too few for the hundreds of pixels the segment
  // spans, as clutter lined up by chance would be; 400 points on the same segment are a line.
  SplitMix64 rng(9);
  std::vector<CandidatePoint> sparse;
  add_line(sparse, {1.0, -2.0}, {1.0, 2.0}, 12, rng, 0.0);
  RansacParams p;
  p.min_inliers = 5;
  const LineSet a = run(sparse, p);
  EXPECT_EQ(a.count, 0U);
  EXPECT_GE(a.stats.sparse_rejected, 1);
  std::vector<CandidatePoint> dense;
  add_line(dense, {1.0, -2.0}, {1.0, 2.0}, 400, rng, 0.0);
  EXPECT_EQ(run(dense, p).count, 1U);
}

TEST(Ransac, GapSplitsALine) {
  SplitMix64 rng(5);
  std::vector<CandidatePoint> pts;
  add_line(pts, {2.0, -2.0}, {2.0, -0.5}, 150, rng, 0.0);
  add_line(pts, {2.0, 0.5}, {2.0, 2.0}, 150, rng, 0.0);  // a 1 m gap (a robot standing on it)
  const LineSet out = run(pts, {});
  ASSERT_EQ(out.count, 2U);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_NEAR(out.lines[i].ground_start.x, 2.0, 0.01);
    EXPECT_NEAR(out.lines[i].length_m, 1.4, 0.1);
  }
  EXPECT_EQ(out.stats.lines_extracted, 1);  // one RANSAC line, two pieces
}

TEST(Ransac, CollinearPiecesFoundSeparatelyAreMerged) {
  SplitMix64 rng(9);
  std::vector<CandidatePoint> pts;
  add_line(pts, {1.0, 0.0}, {2.0, 0.0}, 200, rng, 0.0);
  add_line(pts, {2.3, 0.08}, {3.3, 0.08}, 200, rng, 0.0);  // 8 cm off, 30 cm gap
  RansacParams p;
  p.skip = 1;
  p.inlier_base_m = 0.01;  // tight enough that one hypothesis cannot take both
  p.inlier_per_m = 0.0;
  const LineSet out = run(pts, p);
  ASSERT_EQ(out.count, 1U);
  EXPECT_EQ(out.stats.merges, 1);
  EXPECT_NEAR(out.lines[0].length_m, 2.3, 0.05);
  EXPECT_EQ(out.lines[0].inliers, 400);
}

TEST(Ransac, CentreCircleIsNoStraightLine) {
  std::vector<CandidatePoint> pts;
  add_circle(pts, {2.5, 0.2}, 0.75, 600);
  RansacParams p;
  const LineSet out = run(pts, p);
  EXPECT_EQ(out.count, 0U) << out.lines[0].length_m;
  ASSERT_TRUE(out.circle.seen);
  EXPECT_NEAR(out.circle.radius_m, 0.75, 0.03);
  EXPECT_NEAR(out.circle.centre.x, 2.5, 0.03);
  EXPECT_NEAR(out.circle.centre.y, 0.2, 0.03);
  EXPECT_GE(out.stats.arcs_rejected, 1);
}

TEST(Ransac, CentreCircleWithTheHalfwayLine) {
  SplitMix64 rng(13);
  std::vector<CandidatePoint> pts;
  add_circle(pts, {2.5, 0.0}, 0.75, 500);
  add_line(pts, {2.5, -2.5}, {2.5, 2.5}, 500, rng);
  add_outliers(pts, 50, rng);
  const LineSet out = run(pts, {});
  ASSERT_TRUE(out.circle.seen);
  EXPECT_NEAR(out.circle.radius_m, 0.75, 0.05);
  int halfway = 0;
  for (std::size_t i = 0; i < out.count; ++i) {
    const FieldLine& f = out.lines[i];
    if (matches(f, {2.5, -2.5}, {2.5, 2.5}, 0.05)) {
      ++halfway;
    } else {
      ADD_FAILURE() << "spurious line (" << f.ground_start.x << "," << f.ground_start.y << ")-(" << f.ground_end.x
                    << "," << f.ground_end.y << ") inliers " << f.inliers;
    }
  }
  EXPECT_EQ(halfway, 1);
}

TEST(Ransac, ImageEndpointsAreTheProjectedGroundEndpoints) {
  // Hand-computed: camera at the pivot 0.5 m up, level; ground (2, y) is at v = cy + fy/4,
  // u = cx − fx·y/2.
  const auto pose = hal::CameraPose::from_head({0.5, 0.0, 0.0}, {0.0, 0.0});
  SplitMix64 rng(1);
  std::vector<CandidatePoint> pts;
  add_line(pts, {2.0, -0.5}, {2.0, 0.5}, 200, rng, 0.0);
  RansacLineFinder finder({}, 4096);
  LineSet out;
  finder.find(pts, 0, kK, pose, {}, out);
  ASSERT_EQ(out.count, 1U);
  const FieldLine& f = out.lines[0];
  EXPECT_NEAR(f.image_start.v, kK.cy + kK.fy * 0.25, 1e-6);
  EXPECT_NEAR(f.image_end.v, kK.cy + kK.fy * 0.25, 1e-6);
  EXPECT_NEAR(f.image_start.u, kK.cx - kK.fx * f.ground_start.y / 2.0, 1e-6);
  EXPECT_NEAR(f.image_end.u, kK.cx - kK.fx * f.ground_end.y / 2.0, 1e-6);
  EXPECT_NEAR(std::abs(f.ground_end.y - f.ground_start.y), 1.0, 0.02) << "the whole segment, from every candidate";
}

}  // namespace
}  // namespace ringlet::vision
