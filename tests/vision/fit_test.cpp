// The least-squares fits on their own: the total-least-squares line (principal axis of the
// scatter matrix) and Kåsa's circle, on exact and noisy points, their direction convention and
// the degenerate inputs they refuse.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "ringlet/vision/fit.hpp"

namespace ringlet::vision {
namespace {

/// All of `points`, through the identity index.
struct AllPoints {
  std::vector<hal::RobotPoint> points;
  std::vector<int> index;
  explicit AllPoints(std::vector<hal::RobotPoint> p) : points(std::move(p)) {
    for (std::size_t i = 0; i < points.size(); ++i) index.push_back(static_cast<int>(i));
  }
  [[nodiscard]] IndexedPoints view() const { return {points, index}; }
};

// n points from a along (dx, dy), offset ±noise across the line in the pattern + − − +: for n a
// multiple of 4 the offsets neither shift nor tilt the best line.
std::vector<hal::RobotPoint> along(hal::RobotPoint a, double dx, double dy, int n, double step, double noise) {
  std::vector<hal::RobotPoint> out;
  for (int i = 0; i < n; ++i) {
    const double t = i * step;
    const double e = ((i + 1) / 2 % 2 == 0 ? 1.0 : -1.0) * noise;
    out.push_back({a.x + t * dx - e * dy, a.y + t * dy + e * dx});
  }
  return out;
}

TEST(FitLine, RecoversADiagonalLineThroughNoise) {
  const double c = std::cos(0.6), s = std::sin(0.6);
  const AllPoints pts(along({1.0, -0.5}, c, s, 40, 0.05, 0.01));
  const auto line = fit_line_tls(pts.view());
  ASSERT_TRUE(line);
  EXPECT_NEAR(line->dx, c, 1e-12);
  EXPECT_NEAR(line->dy, s, 1e-12);
  EXPECT_NEAR(std::hypot(line->dx, line->dy), 1.0, 1e-15);
  // The balanced offsets put the best line on the generating one.
  EXPECT_NEAR(line->signed_distance({1.0, -0.5}), 0.0, 1e-12);
  EXPECT_NEAR(line_rms(*line, pts.view()), 0.01, 1e-12);
}

TEST(FitLine, DirectionDoesNotDependOnThePointOrder) {
  // The principal axis has no sign of its own; the fit points it towards +x (+y when vertical),
  // so a segment's ends come out in the same order whichever way its points were collected.
  auto forward = along({0.0, 0.0}, std::cos(2.5), std::sin(2.5), 12, 0.1, 0.0);
  auto backward = forward;
  std::reverse(backward.begin(), backward.end());
  const auto a = fit_line_tls(AllPoints(forward).view());
  const auto b = fit_line_tls(AllPoints(backward).view());
  ASSERT_TRUE(a && b);
  EXPECT_GT(a->dx, 0.0);
  EXPECT_NEAR(a->dx, -std::cos(2.5), 1e-12);
  EXPECT_NEAR(a->dy, -std::sin(2.5), 1e-12);
  EXPECT_NEAR(a->dx, b->dx, 1e-15);
  EXPECT_NEAR(a->dy, b->dy, 1e-15);

  const auto vertical = fit_line_tls(AllPoints(along({2.0, 1.0}, 0.0, -1.0, 8, 0.2, 0.0)).view());
  ASSERT_TRUE(vertical);
  EXPECT_NEAR(vertical->dx, 0.0, 1e-15);
  EXPECT_NEAR(vertical->dy, 1.0, 1e-15);
}

TEST(FitLine, RefusesTooFewOrCoincidentPoints) {
  EXPECT_FALSE(fit_line_tls(AllPoints({{1.0, 2.0}}).view()));
  EXPECT_FALSE(fit_line_tls(AllPoints({{1.0, 2.0}, {1.0, 2.0}, {1.0, 2.0}}).view()));
  EXPECT_TRUE(fit_line_tls(AllPoints({{1.0, 2.0}, {1.5, 2.0}}).view()));
}

TEST(FitLine, ReadsOnlyTheIndexedSubset) {
  // Two far outliers in the point array that the index leaves out.
  const std::vector<hal::RobotPoint> points{{0.0, 0.0}, {5.0, 9.0}, {1.0, 1.0}, {-4.0, 7.0}, {2.0, 2.0}};
  const std::vector<int> index{0, 2, 4};
  const auto line = fit_line_tls({points, index});
  ASSERT_TRUE(line);
  EXPECT_NEAR(line->dx, std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(line->dy, std::sqrt(0.5), 1e-12);
}

std::vector<hal::RobotPoint> arc(hal::RobotPoint c, double r, double from, double to, int n) {
  std::vector<hal::RobotPoint> out;
  for (int i = 0; i < n; ++i) {
    const double a = from + (to - from) * i / (n - 1);
    out.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
  }
  return out;
}

TEST(FitCircle, RecoversAFullCircleAndAShortArc) {
  const auto full = fit_circle(AllPoints(arc({3.0, -1.0}, 0.75, 0.0, 2.0 * std::numbers::pi, 24)).view());
  ASSERT_TRUE(full);
  EXPECT_NEAR(full->centre.x, 3.0, 1e-12);
  EXPECT_NEAR(full->centre.y, -1.0, 1e-12);
  EXPECT_NEAR(full->radius, 0.75, 1e-12);
  // A 30° arc far from the origin: the normal equations are poorly conditioned here, the points
  // lie exactly on the circle, and the solve must still find it.
  const AllPoints short_arc(arc({4.0, 3.0}, 0.75, 1.0, 1.0 + std::numbers::pi / 6.0, 12));
  const auto part = fit_circle(short_arc.view());
  ASSERT_TRUE(part);
  EXPECT_NEAR(part->centre.x, 4.0, 1e-9);
  EXPECT_NEAR(part->centre.y, 3.0, 1e-9);
  EXPECT_NEAR(part->radius, 0.75, 1e-9);
  EXPECT_LT(circle_rms(*part, short_arc.view()), 1e-9);
}

TEST(FitCircle, RefusesCollinearAndTooFewPoints) {
  EXPECT_FALSE(fit_circle(AllPoints(along({0.0, 0.0}, 0.6, 0.8, 10, 0.1, 0.0)).view()));
  EXPECT_FALSE(fit_circle(AllPoints({{0.0, 0.0}, {1.0, 0.0}}).view()));
  EXPECT_FALSE(fit_circle(AllPoints({{0.5, 0.5}, {0.5, 0.5}, {0.5, 0.5}, {0.5, 0.5}}).view()));
}

TEST(FitCircleGeometric, HeldRadiusFindsTheCentreOfAShortNoisyArc) {
  // 40° of the circle, every point 1 cm off in the pattern + − − +; started 30 cm off.
  auto pts = arc({2.0, 1.0}, 0.75, -0.3, -0.3 + 40.0 * std::numbers::pi / 180.0, 24);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double e = ((i + 1) / 2 % 2 == 0 ? 0.01 : -0.01);
    const double a = std::atan2(pts[i].y - 1.0, pts[i].x - 2.0);
    pts[i].x += e * std::cos(a);
    pts[i].y += e * std::sin(a);
  }
  const AllPoints all(pts);
  const auto held = fit_circle_geometric(all.view(), {{2.2, 1.2}, 0.75}, true);
  ASSERT_TRUE(held);
  EXPECT_NEAR(held->radius, 0.75, 0.0);
  EXPECT_LT(std::hypot(held->centre.x - 2.0, held->centre.y - 1.0), 0.02);
  const auto free = fit_circle_geometric(AllPoints(arc({2.0, 1.0}, 0.8, 0.0, 6.0, 30)).view(), {{2.1, 1.1}, 0.75}, false);
  ASSERT_TRUE(free);
  EXPECT_NEAR(free->radius, 0.8, 1e-9);
  EXPECT_NEAR(free->centre.x, 2.0, 1e-9);
  EXPECT_NEAR(free->centre.y, 1.0, 1e-9);
  EXPECT_FALSE(fit_circle_geometric(AllPoints({{1.0, 1.0}}).view(), {{0.0, 0.0}, 0.75}, true));
}

TEST(FitBend, AnArcBendsTowardsItsCentreAndALineDoesNot) {
  // An arc of radius 0.75 seen from its chord: |c| = 1 / (2 · 0.75), on the centre's side.
  const AllPoints a(arc({0.0, 0.0}, 0.75, 1.2, 1.2 + std::numbers::pi / 3.0, 30));
  const auto chord = fit_line_tls(a.view());
  ASSERT_TRUE(chord);
  const auto bend = fit_bend(*chord, a.view());
  ASSERT_TRUE(bend);
  EXPECT_NEAR(std::abs(bend->c), 1.0 / 1.5, 0.06);  // a parabola, not quite a circle
  EXPECT_EQ(bend->c > 0.0, chord->signed_distance({0.0, 0.0}) > 0.0);
  EXPECT_GT(bend->z(), 10.0);
  // A straight line with noise (the + − − + pattern): no bend to speak of.
  const AllPoints l(along({1.0, 0.0}, 0.8, 0.6, 40, 0.02, 0.01));
  const auto line = fit_line_tls(l.view());
  ASSERT_TRUE(line);
  const auto flat = fit_bend(*line, l.view());
  ASSERT_TRUE(flat);
  EXPECT_LT(flat->z(), 2.0);
  EXPECT_FALSE(fit_bend(*line, AllPoints({{0.0, 0.0}, {1.0, 0.0}, {2.0, 0.0}}).view()));
}

}  // namespace
}  // namespace ringlet::vision
