// The particle filter on synthetic views of the SPL field (scenario.hpp): tracking from a known
// start, odometry alone, an unknown start, a kidnapping, and the mirror-symmetric field's
// ambiguity. Each scenario is a few hundred milliseconds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <numbers>

#include "scenario.hpp"

namespace ringlet::localization {
namespace {

constexpr hal::Pose2 kStart{-3.0, -2.2, std::numbers::pi / 2};  // the mission's start, facing +x

FilterParams params() {
  FilterParams p;
  p.particles = 200;
  return p;
}

TEST(LocalizationFilter, TracksFromAKnownStart) {
  const FieldModel field;
  ParticleFilter filter(field, params());
  filter.reset_to(kStart, 0.1, 0.05);
  test::Scenario s(filter, kStart);
  double sum = 0.0, worst = 0.0, worst_heading = 0.0;
  int n = 0, reliable = 0;
  s.run(30.0, [&](const test::StepRecord& r) {
    sum += r.error();
    worst = std::max(worst, r.error());
    worst_heading = std::max(worst_heading, std::fabs(hal::wrap_angle(r.estimate.pose.theta - r.truth.theta)));
    reliable += r.estimate.reliable() ? 1 : 0;
    ++n;
  });
  EXPECT_LT(sum / n, 0.12);
  EXPECT_LT(worst, 0.4);
  EXPECT_LT(worst_heading, 0.25);
  EXPECT_GT(reliable, n * 95 / 100);
  EXPECT_EQ(filter.relocalizations(), 0U) << "tracking is never a relocalization";
}

TEST(LocalizationFilter, OdometryAloneDriftsAndSaysSo) {
  const FieldModel field;
  ParticleFilter filter(field, params());
  filter.reset_to(kStart, 0.05, 0.02);
  test::Scenario s(filter, kStart);
  s.observe = false;
  std::vector<test::StepRecord> r;
  s.run(40.0, [&](const test::StepRecord& x) { r.push_back(x); });
  const auto& early = r[60];   // 2 s
  const auto& late = r.back(); // 40 s, 24 m driven with 3 % scale and 0.02 1/m curvature bias
  EXPECT_GT(late.error(), 0.5) << "the biased odometry must drift";
  EXPECT_GT(late.estimate.sigma_xy(), 2.0 * early.estimate.sigma_xy()) << "and the covariance must grow";
  EXPECT_LT(late.estimate.confidence, 0.5 * early.estimate.confidence);
  EXPECT_LT(late.error(), 3.0 * late.estimate.sigma_xy()) << "the truth stays inside 3 sigma";
  RecordProperty("drift_m", std::to_string(late.error()));
  RecordProperty("sigma_m", std::to_string(late.estimate.sigma_xy()));
  std::printf("odometry alone, 40 s: error %.2f m, sigma %.2f m (2 s: %.3f m), confidence %.2f -> %.2f\n", late.error(),
              late.estimate.sigma_xy(), early.estimate.sigma_xy(), early.estimate.confidence, late.estimate.confidence);
}

TEST(LocalizationFilter, RecoversFromAnUnknownStartInItsOwnHalf) {
  const FieldModel field;
  ParticleFilter filter(field, params());
  filter.reset_uniform(-1.0);  // the own half (x < 0): the prior every kick-off gives
  test::Scenario s(filter, kStart);
  double recovered_at = -1.0;
  bool silently_wrong = false;
  s.run(20.0, [&](const test::StepRecord& r) {
    silently_wrong = silently_wrong || (r.t > 1.0 && r.silently_wrong());
    if (recovered_at < 0.0 && r.estimate.reliable() && r.error() < 0.3) recovered_at = r.t;
  });
  ASSERT_GE(recovered_at, 0.0);
  EXPECT_LT(recovered_at, 8.0);
  EXPECT_FALSE(silently_wrong);
  EXPECT_EQ(filter.relocalizations(), 0U) << "a first fix is no relocalization";
  RecordProperty("recovery_s", std::to_string(recovered_at));
  std::printf("unknown start (own half): recovered after %.2f s\n", recovered_at);
}

TEST(LocalizationFilter, TheMirrorIsReportedNeverSilentlyChosen) {
  const FieldModel field;
  ParticleFilter filter(field, params());
  filter.reset_uniform();  // no prior at all: the field cannot tell the halves apart
  test::Scenario s(filter, kStart);
  bool silently_wrong = false, ever_reliable = false, found = false;
  s.run(20.0, [&](const test::StepRecord& r) {
    silently_wrong = silently_wrong || r.silently_wrong();
    ever_reliable = ever_reliable || r.estimate.reliable();
    found = found || (!r.estimate.lost && std::min(r.error(), r.mirror_error()) < 0.3);
  });
  EXPECT_TRUE(found) << "the pose is found up to the mirror";
  EXPECT_FALSE(ever_reliable) << "but never claimed without a prior";
  EXPECT_FALSE(silently_wrong);
  EXPECT_TRUE(filter.estimate().ambiguous);
  // The prior resolves it: the robot knows it is in the west half (x < 0 at this moment?).
  filter.resolve_mirror(s.truth().x >= 0.0 ? 1.0 : -1.0);
  EXPECT_TRUE(filter.estimate().reliable());
  EXPECT_LT(std::hypot(filter.estimate().pose.x - s.truth().x, filter.estimate().pose.y - s.truth().y), 0.3);
}

TEST(LocalizationFilter, AKidnappingIsNoticedAndRecovered) {
  const FieldModel field;
  ParticleFilter filter(field, params());
  filter.reset_to(kStart, 0.1, 0.05);
  filter.set_side_prior(1.0);  // the referee puts it back in the east half
  test::Scenario s(filter, kStart);
  s.run(10.0);
  ASSERT_TRUE(filter.estimate().reliable());
  const double kidnap_t = 10.0;
  s.teleport({2.0, 1.0, -std::numbers::pi / 2});
  double lost_at = -1.0, recovered_at = -1.0;
  bool silently_wrong_after_grace = false;
  s.run(20.0, [&](const test::StepRecord& r) {
    if (lost_at < 0.0 && r.estimate.lost) lost_at = r.t;
    if (lost_at >= 0.0 && recovered_at < 0.0 && r.estimate.reliable() && r.error() < 0.3) recovered_at = r.t;
    if (r.t > kidnap_t + 1.0) silently_wrong_after_grace = silently_wrong_after_grace || r.silently_wrong();
  });
  ASSERT_GE(lost_at, 0.0) << "the kidnap must be noticed";
  EXPECT_LT(lost_at - kidnap_t, 1.0);
  EXPECT_GE(filter.relocalizations(), 1U);
  ASSERT_GE(recovered_at, 0.0);
  EXPECT_LT(recovered_at - kidnap_t, 8.0);
  EXPECT_FALSE(silently_wrong_after_grace);
  RecordProperty("lost_after_s", std::to_string(lost_at - kidnap_t));
  RecordProperty("recovered_after_s", std::to_string(recovered_at - kidnap_t));
  std::printf("kidnap: lost after %.2f s, recovered after %.2f s\n", lost_at - kidnap_t, recovered_at - kidnap_t);
}

TEST(LocalizationFilter, SameSeedSameBits) {
  const FieldModel field;
  ParticleFilter a(field, params()), b(field, params());
  a.reset_uniform();
  b.reset_uniform();
  test::Scenario sa(a, kStart), sb(b, kStart);
  sa.run(3.0);
  sb.run(3.0);
  ASSERT_EQ(a.particles().size(), b.particles().size());
  for (std::size_t i = 0; i < a.particles().size(); ++i) {
    ASSERT_EQ(a.particles()[i].x, b.particles()[i].x);
    ASSERT_EQ(a.particles()[i].theta, b.particles()[i].theta);
  }
}

}  // namespace
}  // namespace ringlet::localization
