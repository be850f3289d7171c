// Each observation model on hand-computed cases: a line point, the direction classes, the circle,
// the outlier floor, and the point-symmetry of the field.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ringlet/localization/observation_model.hpp"
#include "ringlet/localization/pose_candidates.hpp"

namespace ringlet::localization {
namespace {

constexpr double kHalfPi = std::numbers::pi / 2;

Observations one_line(double x0, double y0, double x1, double y1) {
  Observations o;
  o.add_line({x0, y0, x1, y1});
  return o;
}

TEST(LocalizationObservation, ASegmentOnTheCentreLineFitsPerfectly) {
  const FieldModel field;
  const ObservationModel model(field, {});
  PreparedObservations p;
  // Facing +x from (-2, 0): 2 m ahead, across the view, lies the centre line x = 0.
  p.prepare(one_line(2.0, -0.25, 2.0, 0.25), model.params());
  ASSERT_EQ(p.point_count(), 3U);  // 0.5 m: its ends and its middle
  const Fit fit = model.evaluate(p, hal::Pose2{-2.0, 0.0, kHalfPi});
  EXPECT_NEAR(fit.likelihood, 1.0, 1e-12);
  EXPECT_NEAR(fit.quality, 1.0, 1e-12);
  EXPECT_EQ(fit.terms, 1U);  // one segment, one term
}

TEST(LocalizationObservation, ATenCentimetreErrorScoresTheCauchyTerm) {
  const FieldModel field;
  const ObservationModel model(field, {});
  PreparedObservations p;
  p.prepare(one_line(2.0, -0.25, 2.0, 0.25), model.params());
  // 0.1 m short of the line: every point is 0.1 m off. σ = 0.12 + 0.06 r.
  const Fit fit = model.evaluate(p, hal::Pose2{-2.1, 0.0, kHalfPi});
  const double s_end = 0.12 + 0.06 * std::sqrt(4.0 + 0.0625);  // r = 2.0156 m at the ends
  const double s_mid = 0.12 + 0.06 * 2.0;                      // 0.24 m
  const double t_end = 1.0 / (1.0 + 0.01 / (s_end * s_end));   // 0.8531
  const double t_mid = 1.0 / (1.0 + 0.01 / (s_mid * s_mid));   // 0.8521
  EXPECT_NEAR(t_mid, 0.852071, 1e-6);
  EXPECT_NEAR(fit.likelihood, (2 * t_end + t_mid) / 3, 1e-9);  // the segment: its points' mean
  EXPECT_NEAR(fit.quality, (2 * t_end + t_mid) / 3, 1e-9);
}

TEST(LocalizationObservation, ASegmentIsComparedWithLinesOfItsDirectionOnly) {
  const FieldModel field;
  const ObservationModel model(field, {});
  // At (0.5, 2.0): the centre line (along y) is 0.5 m away, the nearest line along x (the north
  // touch line at y = 3; the penalty area side at y = 2 starts at x = 2.85) 1 m.
  EXPECT_DOUBLE_EQ(model.line_error2(0.5, 2.0, 1.0), 1.0);                        // along x
  EXPECT_DOUBLE_EQ(model.line_error2(0.5, 2.0, 0.0), 0.25);                       // along y
  EXPECT_DOUBLE_EQ(model.line_error2(0.5, 2.0, std::cos(std::numbers::pi / 4)), 0.25);  // diagonal: both
}

TEST(LocalizationObservation, TheCircleCentreAgainstTheCentreSpot) {
  const FieldModel field;
  const ObservationModel model(field, {});
  Observations o;
  o.circle_seen = true;
  o.circle_x = 1.0;  // 1 m ahead
  PreparedObservations p;
  p.prepare(o, model.params());
  EXPECT_NEAR(model.evaluate(p, hal::Pose2{-1.0, 0.0, kHalfPi}).likelihood, 1.0, 1e-12);
  // 0.3 m to the side: e² = 0.09, σ = 0.25, term 1 / (1 + 1.44) = 0.409836; it counts twice.
  const Fit fit = model.evaluate(p, hal::Pose2{-1.0, 0.3, kHalfPi});
  EXPECT_NEAR(fit.quality, 0.409836, 1e-6);
  EXPECT_NEAR(fit.likelihood, (1.0 / 2.44) * (1.0 / 2.44), 1e-12);
  EXPECT_EQ(fit.terms, 2U);
}

TEST(LocalizationObservation, AFalseSegmentCostsABoundedFactor) {
  const FieldModel field;
  const ObservationModel model(field, {});
  EXPECT_DOUBLE_EQ(model.term(0.0, 1.0), 1.0);
  EXPECT_DOUBLE_EQ(model.term(0.04, 1.0 / 0.04), 0.5);  // an error of σ: a half
  // The centre line seen 2 m ahead, and a false diagonal from world (-1.7, 0.7) to (-1.1, 1.3):
  // at least 1.1 m from every line (the centre line, the penalty area front at x = -2.85, the
  // penalty area side at y = 2 that ends at x = -2.85), so every point's term is under 0.05.
  Observations o = one_line(2.0, -0.25, 2.0, 0.25);
  o.add_line({0.3, 0.7, 0.9, 1.3});
  PreparedObservations p;
  p.prepare(o, model.params());
  ASSERT_EQ(p.segment_count(), 2U);
  const Fit fit = model.evaluate(p, hal::Pose2{-2.0, 0.0, kHalfPi});
  EXPECT_DOUBLE_EQ(fit.likelihood, 0.1);  // 1 for the centre line × the floor for the false one
  EXPECT_DOUBLE_EQ(fit.quality, 0.55);
}

TEST(LocalizationObservation, ShortAndFarSegmentsAreLeftOut) {
  const FieldModel field;
  const ObservationModel model(field, {});
  Observations o;
  o.add_line({1.0, 0.0, 1.2, 0.0});   // 0.2 m: too short
  o.add_line({7.0, 0.0, 7.0, 1.0});   // beyond 6 m
  PreparedObservations p;
  p.prepare(o, model.params());
  EXPECT_TRUE(p.empty());
}

TEST(LocalizationObservation, ThePointMirrorExplainsTheSameLines) {
  const FieldModel field;
  const ObservationModel model(field, {});
  Observations o = one_line(1.0, -1.0, 1.5, 1.0);
  o.add_line({0.5, 0.8, 2.5, 0.9});
  o.circle_seen = true;
  o.circle_x = 2.0;
  o.circle_y = -0.4;
  PreparedObservations p;
  p.prepare(o, model.params());
  const hal::Pose2 pose{-1.3, 0.7, 1.2};
  const Fit a = model.evaluate(p, pose);
  const Fit b = model.evaluate(p, mirrored(pose));
  EXPECT_NEAR(a.likelihood, b.likelihood, 1e-12);
  EXPECT_NEAR(a.quality, b.quality, 1e-12);
}

}  // namespace
}  // namespace ringlet::localization
